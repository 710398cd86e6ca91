// A shot's SPH liquids resolved; see sph_resolve.hpp.
#include "resolve/sph_resolve.hpp"

#include <fmt/format.h>

#include <optional>

#include "lacrima/sph/dfsph.hpp"
#include "resolve/surface_anchor.hpp"

namespace lacrima::shotfile {

namespace {

// A bound that turns a slip in a shot (a particle radius a thousand times too small) into a clear
// error instead of hours of simulation: the regression drop (4,200 particles) simulates at ~50 s per
// simulated second on 2 cores, so 4 million particles are ~13 hours per second and ~2 GiB of solver
// state.
constexpr double kMaxFluidParticles = 4e6;

// The lattice points a release's bounding box holds (what releasedParticles walks; a drop keeps
// about half of them).
double latticePointsOfRelease(const ShotSphRelease& release, double particleRadius) {
  if (release.kind == ShotSphRelease::Kind::Block)
    return sph::latticeBlockCount(release.min, release.max, 2.0 * particleRadius);
  const Vec3d extent = Vec3d::Constant(release.radius);
  return sph::latticeBlockCount(release.center - extent, release.center + extent, 2.0 * particleRadius);
}

std::string releasePointer(const ShotSph& liquid, size_t release) {
  return fmt::format("{}/{}/{}", liquid.pointer,
                     liquid.releases[release].kind == ShotSphRelease::Kind::Drop ? "drops" : "blocks", release);
}

// A liquid that would release more particles than kMaxFluidParticles, as a problem.
std::optional<SphProblem> tooManyParticles(const ShotSph& liquid) {
  double total = 0.0;
  for (size_t i = 0; i < liquid.releases.size(); ++i) {
    const double points = latticePointsOfRelease(liquid.releases[i], liquid.fluid.particleRadius);
    total += points;
    if (total > kMaxFluidParticles)
      return SphProblem{releasePointer(liquid, i),
                        fmt::format("the liquid's releases up to this one fill {:.3g} particles at particleRadius {} m, "
                                    "more than the {:.0f} million allowed: make particleRadius larger or the "
                                    "releases smaller",
                                    total, liquid.fluid.particleRadius, kMaxFluidParticles / 1e6)};
  }
  return std::nullopt;
}

}  // namespace

SphParticles releasedParticles(const ShotSphRelease& release, double particleRadius) {
  const double spacing = 2.0 * particleRadius;
  SphParticles out;
  if (release.kind == ShotSphRelease::Kind::Block) {
    out.positions = sph::latticeBlock(release.min, release.max, spacing);
  } else {
    const Vec3d extent = Vec3d::Constant(release.radius);
    for (const Vec3d& p : sph::latticeBlock(release.center - extent, release.center + extent, spacing))
      if ((p - release.center).norm() <= release.radius) out.positions.push_back(p);
  }
  out.velocities.assign(out.positions.size(), release.velocity);
  return out;
}

std::vector<SphProblem> resolveSphLiquids(Shot& shot) {
  std::vector<SphProblem> problems;
  for (ShotSph& liquid : shot.sph) {
    if (const std::optional<SphProblem> tooMany = tooManyParticles(liquid)) {
      problems.push_back(*tooMany);
      continue;
    }
    for (ShotSph::Part& part : liquid.colliderParts)
      for (ShotSkinRegion& region : part.regions)
        region.centerPoint = resolveSurfaceAnchor(shot, part.asset, part.part, region.center);
    for (size_t i = 0; i < liquid.releases.size(); ++i)
      if (releasedParticles(liquid.releases[i], liquid.fluid.particleRadius).positions.empty())
        problems.push_back({releasePointer(liquid, i),
                            fmt::format("holds no particle: make it larger than the particle spacing ({} m = 2 x "
                                        "particleRadius)",
                                        2.0 * liquid.fluid.particleRadius)});
  }
  return problems;
}

}  // namespace lacrima::shotfile
