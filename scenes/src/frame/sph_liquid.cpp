#include "frame/sph_liquid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "asset_pose.hpp"
#include "shot_geometry.hpp"
#include "resolve/surface_anchor.hpp"
#include "resolve/surface_attachment.hpp"
#include "lacrima/flesh/flesh_state_cache.hpp"
#include "lacrima/flesh/fnv1a.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/base/user_cache.hpp"
#include "lacrima/sph/neighbour_grid.hpp"
#include "lacrima/sph/sph_kernel.hpp"
#include "lacrima/sph/sph_surface.hpp"

namespace lacrima::shotfile {

namespace {

// The kernel's support in particle radii (as the solver's: 2 particle spacings).
constexpr double kSupportPerRadius = 4.0;

// A bound that turns a slip in a shot (a table of metres sampled at a tenth of a millimetre) into a
// clear error instead of an exhausted memory: 8 million boundary sites are ~0.5 GiB before neighbour
// lists (the fluid's own bound is kMaxFluidParticles, resolve/sph_resolve.cpp).
constexpr double kMaxBoundarySites = 8e6;

// The seconds since the simulation's start of a (fractional) frame.
double secondsAt(double frame, double startFrame, double fps) { return (frame - startFrame) / fps; }

// A shape's surface at a frame: at its keyed centre, moved with the skin when it is attached
// (`attachedAsset`, the asset of its `attach`), as the frame builder places it.
TriangleMesh shapeSurface(const ShotShape& shape, const std::optional<ShotAsset>& attachedAsset, double frame) {
  Vec3 center = shape.centerCurve ? shape.centerCurve->evaluate(float(frame)) : shape.center;
  if (shape.attachment && attachedAsset) {
    const ShotShape::Attachment& attachment = *shape.attachment;
    // attachedPoint reads only the attachment's primitive: pose that one alone.
    std::vector<TriangleMesh> posed(attachment.primitive + 1);
    posed[attachment.primitive] = posedPrimitive(*attachedAsset, assetPoseAt(*attachedAsset, frame), attachment.primitive);
    center += shotfile::attachedPoint(posed, attachment) - attachment.reference;
  }
  return shapeTriangles(shape, center);
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
  hash.add(uint64_t(0x5048'0002));  // the checkpoint format: bump when the solver's results change
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

SphRun::SphRun(const Shot& shot, const ShotSph& liquid)
    : params_(liquid.fluid), startFrame_(liquid.startFrame), fps_(shot.fps), shotPath_(shot.path) {
  for (size_t c = 0; c < liquid.colliderShapes.size(); ++c) {
    const size_t index = liquid.colliderShapes[c];
    Collider collider;
    collider.pointer = liquid.colliderShapePointers[c];
    collider.shape = shot.shapes[index];
    if (collider.shape->attachment) collider.attachedAsset = shot.assets[collider.shape->attachment->asset];
    collider.moves = bool(collider.shape->centerCurve) || (collider.attachedAsset && collider.attachedAsset->animated());
    colliders_.push_back(std::move(collider));
  }
  for (size_t c = 0; c < liquid.colliderParts.size(); ++c) {
    const ShotSph::Part& part = liquid.colliderParts[c];
    Collider collider;
    collider.pointer = part.pointer;
    collider.asset = shot.assets[part.asset];
    for (size_t p = 0; p < collider.asset->gltf->primitives.size(); ++p)
      if (collider.asset->gltf->primitives[p].part == part.part) collider.primitives.push_back(p);
    collider.regions = part.regions;
    collider.moves = collider.asset->animated();
    colliders_.push_back(std::move(collider));
  }
  for (const Collider& collider : colliders_) collidersMove_ = collidersMove_ || collider.moves;
  for (const ShotSphRelease& release : liquid.releases)
    releases_.emplace_back(long(release.frame - liquid.startFrame), releasedParticles(release, params_.particleRadius));
  stateDirectory_ = sphStateDirectory();
}

void SphRun::prepareBoundary() {
  if (prepared_) return;
  std::vector<Vec3d> samples;
  for (Collider& collider : colliders_) {
    const std::vector<Vec3d> positions = sampleCollider(collider);
    samples.insert(samples.end(), positions.begin(), positions.end());
  }
  boundary_ = sph::boundaryFromSamples(std::move(samples), params_.particleRadius);
  key_ = simulationKey(params_, boundary_, releases_, fps_);
  prepared_ = true;
}

std::vector<Vec3d> SphRun::sampleCollider(Collider& collider) const {
  const double spacing = 2.0 * params_.particleRadius;
  const std::vector<TriangleMesh> meshes = colliderMeshes(collider, startFrame_);
  std::vector<std::vector<bool>> selected(meshes.size());  // empty: every triangle
  double candidates = 0.0;
  bool anySelected = false;
  for (size_t m = 0; m < meshes.size(); ++m) {
    if (!collider.regions.empty()) selected[m] = trianglesWithinRegions(meshes[m], collider.regions);
    anySelected = anySelected || std::find(selected[m].begin(), selected[m].end(), true) != selected[m].end();
    candidates += sph::meshSurfaceSiteCandidates(meshes[m], spacing, selected[m]);
  }
  if (!collider.regions.empty() && !anySelected)
    throw InputError(fmt::format("{}: {}/regions: no triangle of the part lies wholly within the regions: give "
                                 "larger radii",
                                 shotPath_.string(), collider.pointer));
  if (candidates > kMaxBoundarySites)
    throw InputError(fmt::format(
        "{}: {}: sampling this collider at the particle spacing ({} m) would take {:.3g} boundary particles, more "
        "than the {:.0f} million allowed: make particleRadius larger or the collider smaller{}",
        shotPath_.string(), collider.pointer, spacing, candidates, kMaxBoundarySites / 1e6,
        collider.asset ? " (e.g. with 'regions')" : ""));
  std::vector<Vec3d> samples;
  for (size_t m = 0; m < meshes.size(); ++m) {
    collider.sites.push_back(sph::meshSurfaceSites(meshes[m], spacing, selected[m]));
    const std::vector<Vec3d> positions = sph::sitePositions(meshes[m], collider.sites.back());
    samples.insert(samples.end(), positions.begin(), positions.end());
  }
  return samples;
}

std::vector<TriangleMesh> SphRun::colliderMeshes(const Collider& collider, double frame) const {
  if (collider.shape) return {shapeSurface(*collider.shape, collider.attachedAsset, frame)};
  std::vector<TriangleMesh> meshes;
  const AssetPose pose = assetPoseAt(*collider.asset, frame);
  for (size_t p : collider.primitives) meshes.push_back(posedPrimitive(*collider.asset, pose, p));
  return meshes;
}

const std::vector<Vec3d>& SphRun::boundaryAt(long index) const {
  if (const auto it = posedBoundaries_.find(index); it != posedBoundaries_.end()) return it->second;
  std::vector<Vec3d> positions;
  for (const Collider& collider : colliders_) {
    const std::vector<TriangleMesh> meshes = colliderMeshes(collider, startFrame_ + double(index));
    for (size_t m = 0; m < meshes.size(); ++m) {
      const std::vector<Vec3d> p = sph::sitePositions(meshes[m], collider.sites[m]);
      positions.insert(positions.end(), p.begin(), p.end());
    }
  }
  if (posedBoundaries_.size() >= 4) posedBoundaries_.erase(posedBoundaries_.begin());  // a sequence asks in order
  return posedBoundaries_.emplace(index, std::move(positions)).first->second;
}

// Still colliders: the simulation's key and the frame. Moving ones: a chain, each frame's key the
// one before combined with the colliders' pose there (flesh_state_cache.hpp's scheme), so a change
// of the animation up to a frame files that frame under another key.
uint64_t SphRun::checkpointKey(long index) const {
  if (!collidersMove_) {
    flesh::Fnv1a hash(key_);
    hash.add(index);
    return hash.value();
  }
  while (long(keys_.size()) <= index) {
    flesh::Fnv1a hash(keys_.empty() ? key_ : keys_.back());
    hash.add(long(keys_.size()));
    hashVector(hash, boundaryAt(long(keys_.size())));
    keys_.push_back(hash.value());
  }
  return keys_[size_t(index)];
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
  if (collidersMove_) {  // in a straight line from this frame's pose to the next one's
    const std::vector<Vec3d> from = boundaryAt(index);  // copies: boundaryAt may drop old frames
    const std::vector<Vec3d> to = boundaryAt(index + 1);
    std::vector<Vec3d> velocities(from.size());
    for (size_t b = 0; b < from.size(); ++b) velocities[b] = (to[b] - from[b]) * fps_;
    solver.moveBoundary(from, std::move(velocities));
  }
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
  prepareBoundary();
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

void addSphLiquids(const Shot& shot, const std::vector<std::unique_ptr<SphRun>>& runs, double openFrame,
                   double closeFrame, Frame& frame) {
  for (size_t l = 0; l < shot.sph.size(); ++l) {
    const ShotSph& liquid = shot.sph[l];
    const SphParticles particles = runs.at(l)->particlesAt(openFrame);
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
