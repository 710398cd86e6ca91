#pragma once
// The random walk below a subsurface skin (lacrima/materials/subsurface.hpp for the model).
#include <cstdint>
#include <optional>

#include "embree_scene.hpp"
#include "lacrima/geometry/sampler.hpp"
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
// meets from inside, whatever that surface is (an eyeball inside the head ends it too). Nothing
// when it ends on a light, escapes an open mesh, or reaches kMaxSubsurfaceSteps. `rays` counts
// the ray queries.
std::optional<SubsurfaceExit> walkBelowSurface(const EmbreeScene& scene, const SubsurfaceMedium& medium,
                                               const Vec3& entry, const Vec3& outwardNormal, float time,
                                               PixelSampler& sampler, uint64_t& rays);

}  // namespace lacrima
