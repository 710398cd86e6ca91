// The skin's relief; see skin_relief.hpp for the model and its sources.
#include "lacrima/materials/skin_relief.hpp"

#include <algorithm>
#include <cmath>

#include "lacrima/materials/furrows.hpp"
#include "lacrima/materials/pores.hpp"

namespace lacrima {

SkinRelief skinReliefAt(const ReliefFields& skin, const Vec3& p) {
  SkinRelief relief;
  if (skin.poreDepth > 0.0f && skin.poreScale > 0.0f) {
    const PoreHeight pore = poreHeight(p, skin.poreScale, skin.poreDepth);
    const float radius = kPoreRadius * skin.poreScale;
    relief.gradient += pore.gradient;
    relief.visibility *= radius * radius / (radius * radius + pore.height * pore.height);
  }
  if (skin.furrowDepth > 0.0f && skin.furrowScale > 0.0f) {
    const FurrowHeight furrow = furrowHeight(p, skin.furrowScale, skin.furrowDepth);
    const float halfWidth = kFurrowHalfWidth * skin.furrowScale;
    relief.gradient += furrow.gradient;
    relief.visibility *= halfWidth / std::sqrt(halfWidth * halfWidth + furrow.height * furrow.height);
  }
  return relief;
}

float cavityAlbedoFactor(const SkinParams& skin, const SkinRelief& relief) {
  return 1.0f - std::clamp(skin.cavity, 0.0f, 1.0f) * (1.0f - relief.visibility);
}

}  // namespace lacrima
