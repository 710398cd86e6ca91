#include "sph_liquid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "asset_pose.hpp"
#include "lacrima/flesh/flesh_state_cache.hpp"
#include "lacrima/flesh/fnv1a.hpp"
#include "lacrima/geometry/shapes.hpp"
#include "lacrima/geometry/user_cache.hpp"
#include "lacrima/sph/neighbour_grid.hpp"
#include "lacrima/sph/sph_kernel.hpp"
#include "lacrima/sph/sph_surface.hpp"

namespace lacrima::shotfile {

namespace {

// The kernel's support in particle radii (as the solver's: 2 particle spacings).
constexpr double kSupportPerRadius = 4.0;

// The seconds since the simulation's start of a (fractional) frame.
double secondsAt(double frame, double startFrame, double fps) { return (frame - startFrame) / fps; }

// A shape's surface at a frame (a sphere tessellated as an ellipsoid).
TriangleMesh shapeSurface(const ShotShape& shape, double frame) {
  const Vec3 center = shape.centerCurve ? shape.centerCurve->evaluate(float(frame)) : shape.center;
  switch (shape.type) {
    case ShotShape::Type::Sphere:
      return makeEllipsoid(center, Mat3(shape.radius * Mat3::Identity()));
    case ShotShape::Type::Ellipsoid:
      return makeEllipsoid(center, Mat3(shape.rotation * shape.radii.asDiagonal()));
    case ShotShape::Type::Rectangle:
      break;
  }
  return makeRectangle(center, shape.edgeU, shape.edgeV);
}

// The liquid's colliders at its start frame, as one layer of boundary samples each.
std::vector<Vec3d> colliderSamples(const Shot& shot, const ShotSph& liquid, double spacing) {
  std::vector<Vec3d> samples;
  const auto add = [&](const TriangleMesh& mesh) {
    const std::vector<Vec3d> s = sph::meshSurfaceSamples(mesh, spacing);
    samples.insert(samples.end(), s.begin(), s.end());
  };
  for (size_t index : liquid.colliderShapes) add(shapeSurface(shot.shapes[index], liquid.startFrame));
  for (const ShotSph::Part& part : liquid.colliderParts) {
    const ShotAsset& asset = shot.assets[part.asset];
    const AssetPose pose = assetPoseAt(asset, liquid.startFrame);
    for (size_t p = 0; p < asset.gltf->primitives.size(); ++p)
      if (asset.gltf->primitives[p].part == part.part) add(posedPrimitive(asset, pose, p));
  }
  return samples;
}

// Per vertex, the kernel-weighted mean velocity of the particles within the kernel's support
// (zero where none is: the surface lies up to a particle radius or so off the particles).
std::vector<Vec3d> vertexVelocities(const TriangleMesh& mesh, const SphParticles& particles, double particleRadius) {
  const sph::CubicSplineKernel kernel(kSupportPerRadius * particleRadius);
  sph::NeighbourGrid grid(kernel.supportRadius());
  grid.build(particles.positions);
  std::vector<Vec3d> velocities(mesh.positions.size(), Vec3d::Zero());
  std::vector<uint32_t> near;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3d x = mesh.positions[i].cast<double>();
    grid.pointsNear(x, near);
    double weightSum = 0.0;
    Vec3d sum = Vec3d::Zero();
    for (uint32_t j : near) {
      const double w = kernel.value(x - particles.positions[j]);
      weightSum += w;
      sum += w * particles.velocities[j];
    }
    if (weightSum > 0.0) velocities[i] = sum / weightSum;
  }
  return velocities;
}

template <typename T>
void hashVector(flesh::Fnv1a& hash, const std::vector<T>& values) {
  hash.add(uint64_t(values.size()));
  if (!values.empty()) hash.add(values.data(), values.size() * sizeof(T));
}

// The key of a simulation: its fluid parameters, boundary, releases and frame rate.
uint64_t simulationKey(const sph::FluidParams& p, const sph::BoundaryParticles& boundary,
                       const std::vector<std::pair<long, SphParticles>>& releases, double fps) {
  flesh::Fnv1a hash;
  hash.add(uint64_t(0x5048'0001));  // the checkpoint format: bump when the solver's results change
  for (double x : {p.particleRadius, p.restDensity, p.xsphViscosity, p.surfaceTension, p.adhesion, p.gravity.x(),
                   p.gravity.y(), p.gravity.z(), p.cflFactor, p.minTimeStep, p.maxTimeStep, p.maxDensityError,
                   p.maxDivergenceError, fps})
    hash.add(x);
  hash.add(p.minIterations);
  hash.add(p.maxIterations);
  hashVector(hash, boundary.positions);
  hashVector(hash, boundary.volumes);
  for (const auto& [frame, particles] : releases) {
    hash.add(frame);
    hashVector(hash, particles.positions);
    hashVector(hash, particles.velocities);
  }
  return hash.value();
}

}  // namespace

std::filesystem::path sphStateDirectory() {
  const std::filesystem::path cache = userCacheDirectory("sph");
  return cache.empty() ? cache : cache / "states";
}

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

SphRun::SphRun(const Shot& shot, const ShotSph& liquid)
    : params_(liquid.fluid),
      boundary_(sph::boundaryFromSamples(colliderSamples(shot, liquid, 2.0 * liquid.fluid.particleRadius),
                                         liquid.fluid.particleRadius)),
      startFrame_(liquid.startFrame),
      fps_(shot.fps) {
  for (const ShotSphRelease& release : liquid.releases)
    releases_.emplace_back(long(release.frame - liquid.startFrame), releasedParticles(release, params_.particleRadius));
  key_ = simulationKey(params_, boundary_, releases_, fps_);
  stateDirectory_ = sphStateDirectory();
}

uint64_t SphRun::checkpointKey(long index) const {
  flesh::Fnv1a hash(key_);
  hash.add(index);
  return hash.value();
}

size_t SphRun::particleCountAt(long index) const {
  size_t count = 0;
  for (const auto& [frame, particles] : releases_)
    if (frame <= index) count += particles.positions.size();
  return count;
}

// Checkpoints are filed in the flesh's state format (positions and velocities under a key).
std::optional<SphParticles> SphRun::readCheckpoint(long index) const {
  if (stateDirectory_.empty()) return std::nullopt;
  const uint64_t key = checkpointKey(index);
  std::optional<flesh::FleshState> state =
      flesh::readFleshState(flesh::fleshStateFile(stateDirectory_, index, key), key, particleCountAt(index));
  if (!state) return std::nullopt;
  return SphParticles{std::move(state->positions), std::move(state->velocities)};
}

void SphRun::fileCheckpoint() const {
  if (stateDirectory_.empty() || checkpoint_.positions.empty()) return;
  try {
    std::error_code ec;
    std::filesystem::create_directories(stateDirectory_, ec);
    const uint64_t key = checkpointKey(checkpointIndex_);
    flesh::writeFleshState(flesh::fleshStateFile(stateDirectory_, checkpointIndex_, key),
                           flesh::FleshState{checkpoint_.positions, checkpoint_.velocities}, key);
  } catch (const std::exception&) {
    // Not filed (a full or read-only disk): a later frame built alone simulates more.
  }
}

void SphRun::addReleasesAt(long index, SphParticles& particles) const {
  for (const auto& [frame, released] : releases_) {
    if (frame != index) continue;
    particles.positions.insert(particles.positions.end(), released.positions.begin(), released.positions.end());
    particles.velocities.insert(particles.velocities.end(), released.velocities.begin(), released.velocities.end());
  }
}

SphParticles SphRun::steppedTo(const SphParticles& particles, long index, double seconds) const {
  if (particles.positions.empty()) return particles;
  sph::DfsphSolver solver(params_, particles.positions, boundary_);
  solver.setState(particles.positions, particles.velocities, double(index) / fps_);
  solver.advanceTo(seconds);
  return {solver.positions(), solver.velocities()};
}

SphParticles SphRun::nextCheckpoint(const SphParticles& particles, long index) const {
  SphParticles next = steppedTo(particles, index, double(index + 1) / fps_);
  addReleasesAt(index + 1, next);
  return next;
}

SphParticles SphRun::particlesAt(double frame) {
  const double seconds = secondsAt(frame, startFrame_, fps_);
  if (seconds < 0.0) return {};
  // The whole frame at or before `seconds` (a time within a nanosecond of a frame counts as it).
  const long index = long(std::floor(seconds * fps_ + 1e-6));
  std::lock_guard<std::mutex> lock(mutex_);
  if (checkpointIndex_ > index || checkpointIndex_ < 0) {
    checkpointIndex_ = 0;
    checkpoint_ = {};
    addReleasesAt(0, checkpoint_);
  }
  for (long k = index; k > checkpointIndex_; --k)  // the latest filed checkpoint ahead, if any
    if (std::optional<SphParticles> filed = readCheckpoint(k)) {
      checkpoint_ = std::move(*filed);
      checkpointIndex_ = k;
      break;
    }
  while (checkpointIndex_ < index) {
    checkpoint_ = nextCheckpoint(checkpoint_, checkpointIndex_);
    ++checkpointIndex_;
    fileCheckpoint();
  }
  if (seconds <= double(index) / fps_) return checkpoint_;
  return steppedTo(checkpoint_, index, seconds);
}

std::vector<SphProblem> resolveSphLiquids(Shot& shot) {
  std::vector<SphProblem> problems;
  for (ShotSph& liquid : shot.sph) {
    for (size_t i = 0; i < liquid.releases.size(); ++i)
      if (releasedParticles(liquid.releases[i], liquid.fluid.particleRadius).positions.empty())
        problems.push_back({fmt::format("{}/{}/{}", liquid.pointer,
                                        liquid.releases[i].kind == ShotSphRelease::Kind::Drop ? "drops" : "blocks", i),
                            fmt::format("holds no particle: make it larger than the particle spacing ({} m = 2 x "
                                        "particleRadius)",
                                        2.0 * liquid.fluid.particleRadius)});
    if (problems.empty()) liquid.run = std::make_shared<SphRun>(shot, liquid);
  }
  return problems;
}

void addSphLiquids(const Shot& shot, double openFrame, double closeFrame, Frame& frame) {
  for (size_t l = 0; l < shot.sph.size(); ++l) {
    const ShotSph& liquid = shot.sph[l];
    if (!liquid.run) continue;
    const SphParticles particles = liquid.run->particlesAt(openFrame);
    if (particles.positions.empty()) continue;
    sph::SurfaceParams surfacing;
    surfacing.voxelsPerRadius = liquid.voxelsPerRadius;
    surfacing.smoothingIterations = liquid.smoothing;
    MeshInstance instance(sph::surfaceOfParticles(particles.positions, liquid.fluid.particleRadius, surfacing),
                          liquid.materialId);
    if (instance.mesh.positions.empty()) continue;
    instance.mesh.name = fmt::format("sph {}", l);
    const double shutterSeconds = (closeFrame - openFrame) / shot.fps;
    if (shutterSeconds > 0.0) {
      const std::vector<Vec3d> v = vertexVelocities(instance.mesh, particles, liquid.fluid.particleRadius);
      instance.positionsAtClose.resize(v.size());
      for (size_t i = 0; i < v.size(); ++i)
        instance.positionsAtClose[i] = instance.mesh.positions[i] + (shutterSeconds * v[i]).cast<float>();
      instance.normalsAtClose = instance.mesh.normals;
    }
    frame.meshes.push_back(std::move(instance));
  }
}

}  // namespace lacrima::shotfile
