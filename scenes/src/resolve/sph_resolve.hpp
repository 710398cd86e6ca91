#pragma once
// A shot's SPH liquids (ShotSph, docs/shot-format.md "sph") resolved at load: their collider regions
// placed on the skin, their releases checked to hold particles and not too many. Simulated frame by
// frame by frame/sph_liquid.hpp.
#include <string>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

struct SphProblem {
  std::string pointer;
  std::string message;
};

// Resolves each liquid's collider regions; the problems found (a release too small to hold a
// particle, a collider with no surface to sample).
std::vector<SphProblem> resolveSphLiquids(Shot& shot);

struct SphParticles {
  std::vector<Vec3d> positions, velocities;
};

// The particles a release puts in the liquid: a lattice of spacing 2 r filling the drop's ball or
// the block's box, all at the release's velocity.
SphParticles releasedParticles(const ShotSphRelease& release, double particleRadius);

}  // namespace lacrima::shotfile
