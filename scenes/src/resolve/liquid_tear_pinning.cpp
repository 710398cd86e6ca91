// The skin's pinning of a liquid tear's contact line; see liquid_tear_pinning.hpp.
#include "resolve/liquid_tear_pinning.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "lacrima/base/gradient_noise.hpp"

namespace lacrima::shotfile {

std::vector<float> skinPinning(const TriangleMesh& skinAtFirstFrame, double maxFactor, double patchSize) {
  // A fixed seed: the pattern is a property of the skin, the same in every shot (and another than
  // the wet trail's edge, liquid_tear_film.hpp).
  constexpr uint64_t kSeed = 0x9e11a7ed;
  const float logFactor = float(std::log(maxFactor));
  std::vector<float> factors(skinAtFirstFrame.positions.size());
  for (size_t v = 0; v < factors.size(); ++v) {
    const Vec3 p = skinAtFirstFrame.positions[v] / float(patchSize);
    const float variation = std::clamp(kPinningContrast * fractalGradientNoise(p, kPinningOctaves, kSeed), -1.0f, 1.0f);
    factors[v] = std::exp(logFactor * variation);
  }
  return factors;
}

}  // namespace lacrima::shotfile
