#pragma once
// Procedural skin pores: a height field of small pits that tilts the shading normal so that
// specular highlights break up, as they do on real skin.
//
// Field: one pore per cell of a cubic lattice of spacing `scale` (metres), centred at a point
// jittered uniformly inside its cell by a hash of the cell (Worley 1996, "A Cellular Texture
// Basis Function", SIGGRAPH: one hashed feature point per cell, neighbours searched in the 27
// surrounding cells). Each pore is a smooth pit of radius kPoreRadius * scale:
//   h(p) = -depth * sum_k b(|p - c_k|^2 / R^2),  b(s) = (1 - s)^2 for s < 1, else 0,
// b is C1 at the rim (b = b' = 0 at s = 1), so h and its gradient are continuous in p. The field
// lives in 3D and the surface slices it, which gives pits of varying apparent size.
// Normal: bump mapping (Blinn 1978, "Simulation of Wrinkled Surfaces", SIGGRAPH): a height
// field h over the tangent plane of n has the normal normalize(n - grad_t h), grad_t the
// gradient's tangential part. The tangential slope is clamped to kMaxPoreSlope (tilt <= 45 deg),
// and a tilted normal that would come within kMinPoreCosToGeometric of the geometric surface is
// not used (the unperturbed one is returned), so perturbation never produces NaN or a normal
// below the geometric surface.
// The field is evaluated at the world-space shading position: on an animated face the pores
// slide over the skin when it deforms (a rest-pose position is not available at the hit).
#include "lacrima/base/math.hpp"

namespace lacrima {

inline constexpr float kPoreRadius = 0.3f;             // pore radius as a fraction of the lattice spacing
inline constexpr float kMaxPoreSlope = 1.0f;           // tan(45 deg)
inline constexpr float kMinPoreCosToGeometric = 0.05f;

struct PoreHeight {
  float height = 0.0f;           // metres, <= 0 (pits)
  Vec3 gradient = Vec3::Zero();  // d height / d position (dimensionless slope)
};

// The pore height field and its analytic gradient at world position p. scale > 0, depth >= 0.
PoreHeight poreHeight(const Vec3& p, float scale, float depth);

// Shading normal ns (unit, on the same side as the geometric normal ng) tilted by the pore field
// at p; ns itself when depth is 0 or the tilted normal is too close to the geometric horizon.
Vec3 perturbNormalByPores(const Vec3& p, const Vec3& ns, const Vec3& ng, float scale, float depth);

// Shading normal ns tilted by a height field's gradient (bump mapping as above: the tangential
// slope clamped to kMaxPoreSlope, ns kept where the result would come within
// kMinPoreCosToGeometric of the geometric horizon). Shared by every relief of the skin.
Vec3 tiltNormalBySlope(const Vec3& gradient, const Vec3& ns, const Vec3& ng);

}  // namespace lacrima
