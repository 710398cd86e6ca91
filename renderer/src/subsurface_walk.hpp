#pragma once
// The random walk below a subsurface skin (lacrima/materials/subsurface.hpp for the model).
#include <cstdint>
#include <optional>
#include <vector>

#include "embree_scene.hpp"
#include "lacrima/renderer/sampler.hpp"
#include "lacrima/materials/subsurface.hpp"

namespace lacrima {

// A walk ends after this many scattering events; the path is then dropped (absorbed). The bias:
// energy of walks longer than this is lost (tests/renderer/subsurface_test.cpp bounds it for a
// single-scattering albedo of 0.99; at 1 the furnace test uses a sphere small enough that no
// walk gets near the cap).
inline constexpr int kMaxSubsurfaceSteps = 256;

// Where a walk left the medium: the surface point, its geometric and shading normals pointing
// out of the medium (the side the path continues on), and the walk's weight per channel.
struct SubsurfaceExit {
  Vec3 position;
  Vec3 geometricNormal;
  Vec3 shadingNormal;
  Color weight;
};

// Walks from `entry` (a surface point whose geometric normal `outwardNormal` points away from the
// medium) into the medium: a cosine-distributed entry direction, exponential free flights with
// one-sample MIS over the channels, isotropic scattering. The walk ends at the first surface it
// meets from inside (an eyeball inside the head ends it too), except surfaces of dielectrics
// (dielectricIndex[materialId] > 0: their refractive index; 0 for opaque materials), which it
// crosses as if absent, since a drop sitting on the skin reaches into it. When the skin at the
// entry or the exit lies under a dielectric (a drop), the weight carries (n_entry / n_exit)^2,
// the radiance scaling between the two media; the skin's own Fresnel stays that against air.
// Nothing when it ends on a light, escapes an open mesh, or reaches kMaxSubsurfaceSteps. `rays`
// counts the ray queries.
std::optional<SubsurfaceExit> walkBelowSurface(const EmbreeScene& scene, const SubsurfaceMedium& medium,
                                               const std::vector<float>& dielectricIndex, const Vec3& entry,
                                               const Vec3& outwardNormal, float time,
                                               PixelSampler& sampler, uint64_t& rays);

// The channel whose cumulative probability passes u (probabilities sum to 1; zero ones are never
// picked); rounding falls back to the last possible one.
int pickChannel(const Color& probabilities, float u);

// The refractive index of what lies outside the skin at a surface point: the first surface along
// the outward normal decides; a dielectric's surface seen from inside means the point is under it
// (a drop on the skin), anything else means air (1). One ray query against the dielectrics alone,
// a second (occlusion up to the dielectric) only under one; counted in `rays`.
float indexOutsideSkin(const EmbreeScene& scene, const std::vector<float>& dielectricIndex, const Vec3& position,
                       const Vec3& outwardNormal, float time, uint64_t& rays);

}  // namespace lacrima
