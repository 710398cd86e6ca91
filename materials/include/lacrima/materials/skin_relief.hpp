#pragma once
// The skin's fine relief at a point: pores (pores.hpp) and furrows (furrows.hpp) summed into one
// height field, whose gradient tilts the shading normal (bump mapping, Blinn 1978) and whose
// hollows darken the albedo.
//
// Why darken: a bump-mapped surface has no self-shadowing (Max 1988, "Horizon mapping: shadows for
// bump-mapped surfaces"), so pits and grooves that only tilt the normal read as glitter on a
// smooth plastic, not as hollows. A point at depth delta under the rim of its hollow sees the sky
// only through the hollow's opening; the cosine-weighted fraction it sees (the configuration
// factor to the opening, Howell, "A Catalog of Radiation Heat Transfer Configuration Factors") is
//   pore (a pit of radius R):          F = R^2 / (R^2 + delta^2)   (element to a parallel coaxial disk),
//   furrow (a groove of half-width w): F = w / sqrt(w^2 + delta^2) (element to a parallel strip, in 2D),
// with R = kPoreRadius * poreScale and w = kFurrowHalfWidth * furrowScale; where both hollows
// overlap the factors multiply. The albedo is scaled by 1 - cavity (1 - F), an obscurance (Zhukov,
// Iones & Kronin 1998, "An ambient light illumination model") taken into the albedo: light that
// bounces inside the hollow comes back out in part, so cavity = 1 overstates the darkening for a
// bright albedo; cavity < 1 is how a shot weighs that. The darkened albedo is also what the skin
// below scatters with (subsurface) and what the denoiser's albedo feature sees, so the relief
// survives denoising.
#include "lacrima/base/math.hpp"
#include "lacrima/materials/material.hpp"

namespace lacrima {

struct SkinRelief {
  Vec3 gradient = Vec3::Zero();  // of the summed height field (dimensionless slope)
  float visibility = 1.0f;       // F above: the cosine-weighted fraction of the sky seen from here
};

// The relief of pores (poreScale, poreDepth) and furrows (furrowScale, furrowDepth) at world
// position p; a smooth surface (zero gradient, visibility 1) where both depths are 0.
struct ReliefFields {
  float poreScale, poreDepth, furrowScale, furrowDepth;
};
SkinRelief skinReliefAt(const ReliefFields& fields, const Vec3& p);
inline SkinRelief skinReliefAt(const SkinParams& skin, const Vec3& p) {
  return skinReliefAt(ReliefFields{skin.poreScale, skin.poreDepth, skin.furrowScale, skin.furrowDepth}, p);
}

// 1 - cavity (1 - visibility): the factor on the albedo.
float cavityAlbedoFactor(const SkinParams& skin, const SkinRelief& relief);

}  // namespace lacrima
