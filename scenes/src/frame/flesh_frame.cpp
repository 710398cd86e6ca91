#include "frame/flesh_frame.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "asset_pose.hpp"
#include "lacrima/flesh/flesh_state_cache.hpp"
#include "lacrima/flesh/flesh_volume_cache.hpp"
#include "lacrima/flesh/fnv1a.hpp"
#include "lacrima/rig/region_refinement.hpp"
#include "lacrima/base/user_cache.hpp"
#include "resolve/surface_anchor.hpp"

namespace lacrima::shotfile {

namespace {

namespace fs = std::filesystem;

// A skin vertex is carried by the flesh when it lies in a tetrahedron or this little outside one
// (in barycentric weight): the vertices of a skin refined after the volume was built lie on its
// boundary, a hair inside or outside it.
constexpr double kEmbeddingSlack = 0.02;

TriangleMesh posedSkin(const ShotAsset& asset, size_t primitive, double frame) {
  return posedPrimitive(asset, assetPoseAt(asset, frame), primitive);
}

std::vector<Vec3d> patchPositions(const flesh::SkinPatch& patch, const TriangleMesh& skin) {
  std::vector<Vec3d> out(patch.skinVertex.size());
  for (size_t v = 0; v < out.size(); ++v) out[v] = skin.positions.at(patch.skinVertex[v]).cast<double>();
  return out;
}

// The patch of the skin in the regions, its vertices welded by position first (glTF splits
// vertices along uv seams: unwelded, a seam would be a border inside the patch, with walls on both
// sides of it), triangles of no area left out.
std::shared_ptr<const flesh::SkinPatch> skinPatchOf(const TriangleMesh& skin, const std::vector<uint32_t>& weld,
                                                    const std::vector<ShotSkinRegion>& regions) {
  TriangleMesh withNormals = skin;
  if (withNormals.normals.size() != withNormals.positions.size()) computeSmoothNormals(withNormals, weld);
  std::vector<Vec3d> positions, normals;
  for (size_t v = 0; v < skin.positions.size(); ++v) {
    positions.push_back(skin.positions[v].cast<double>());
    normals.push_back(withNormals.normals[v].cast<double>());
  }
  std::vector<bool> selected = trianglesWithinRegions(skin, regions);
  std::vector<std::array<uint32_t, 3>> triangles;
  for (size_t t = 0; t < skin.triangleCount(); ++t) {
    const std::array<uint32_t, 3> corners{weld[skin.indices[3 * t]], weld[skin.indices[3 * t + 1]],
                                          weld[skin.indices[3 * t + 2]]};
    const Vec3d area = (positions[corners[1]] - positions[corners[0]]).cross(positions[corners[2]] - positions[corners[0]]);
    if (!(area.norm() > 0.0)) selected[t] = false;
    triangles.push_back(corners);
  }
  return std::make_shared<const flesh::SkinPatch>(flesh::extractSkinPatch(positions, normals, triangles, selected));
}

// What a flesh's states depend on besides the rig's motion: the volume, the material, the
// solver's settings and revision, the step grid.
uint64_t baseStateKey(const ShotFlesh& flesh, const flesh::SkinPatch& patch, double fps, double startFrame) {
  flesh::Fnv1a h(flesh::fleshVolumeKey(patch, flesh.volume));
  h.add(flesh::kFleshSolverRevision);
  h.add(flesh.material);
  h.add(flesh.youngsModulus);
  h.add(flesh.poissonRatio);
  const flesh::FleshDynamicsParams& d = flesh.dynamics;
  for (double value : {d.density, d.massDamping, d.stiffnessDamping, d.newtonTolerance, d.cgTolerance, d.positionTolerance})
    h.add(value);
  for (int value : {int(d.integrator), d.newtonIterations, d.cgIterations, flesh.substeps}) h.add(value);
  h.add(fps);
  h.add(startFrame);
  return h.value();
}

std::optional<FleshProblem> resolveOne(Shot& shot, ShotFlesh& flesh) {
  for (ShotSkinRegion& region : flesh.regions)
    region.centerPoint = resolveSurfaceAnchor(shot, flesh.asset, flesh.part, region.center);
  flesh.primitive = flesh.regions.front().centerPoint.primitive;
  for (size_t i = 1; i < flesh.regions.size(); ++i)
    if (flesh.regions[i].centerPoint.primitive != flesh.primitive)
      return FleshProblem{fmt::format("{}/regions/{}/center", flesh.pointer, i),
                          "the regions' centres lie on different primitives of the part; a flesh volume lies under one"};
  const ShotAsset& asset = shot.assets[flesh.asset];
  const TriangleMesh skin = posedSkin(asset, flesh.primitive, shot.frameStart);
  flesh.patch = skinPatchOf(skin, findCoincidentVertices(skin), flesh.regions);
  if (flesh.patch->triangles.empty())
    return FleshProblem{flesh.pointer + "/regions",
                        "no triangle of the skin lies wholly within the regions: give larger radii"};
  try {
    flesh.tetVolume = std::make_shared<const flesh::FleshVolume>(
        flesh::cachedFleshVolume(*flesh.patch, flesh.volume, fleshCacheDirectory()));
  } catch (const flesh::FleshVolumeError& e) {
    return FleshProblem{flesh.pointer, fmt::format("the flesh volume cannot be built: {}", e.what())};
  }
  flesh.unrefinedAsset = std::make_shared<const ShotAsset>(asset);
  return std::nullopt;
}

}  // namespace

fs::path fleshCacheDirectory() { return userCacheDirectory("flesh"); }

std::vector<FleshProblem> resolveFleshVolumes(Shot& shot) {
  std::vector<FleshProblem> problems;
  for (ShotFlesh& flesh : shot.flesh)
    if (std::optional<FleshProblem> problem = resolveOne(shot, flesh)) problems.push_back(*problem);
  return problems;
}

void embedFleshSkins(Shot& shot) {
  for (ShotFlesh& flesh : shot.flesh) {
    if (!flesh.tetVolume) continue;
    const TriangleMesh skin = posedSkin(shot.assets[flesh.asset], flesh.primitive, shot.frameStart);
    const flesh::TetMesh& mesh = flesh.tetVolume->mesh;
    Eigen::AlignedBox3d box;
    for (const Vec3d& p : mesh.nodes) box.extend(p);
    std::vector<Vec3d> points;
    std::vector<size_t> vertices;
    for (size_t v = 0; v < skin.positions.size(); ++v)
      if (box.contains(skin.positions[v].cast<double>())) {
        points.push_back(skin.positions[v].cast<double>());
        vertices.push_back(v);
      }
    flesh.skinEmbedding.assign(skin.positions.size(), flesh::TetEmbedding{});
    const std::vector<flesh::TetEmbedding> embedded = flesh::embedPoints(mesh, points, kEmbeddingSlack);
    for (size_t i = 0; i < vertices.size(); ++i) flesh.skinEmbedding[vertices[i]] = embedded[i];
  }
}

FleshRun::FleshRun(const Shot& shot, const ShotFlesh& flesh, StateFiling filing)
    : asset_(flesh.unrefinedAsset),
      primitive_(flesh.primitive),
      patch_(flesh.patch),
      volume_(flesh.tetVolume),
      initial_(volume_->mesh, flesh.material, flesh::LameParameters::fromYoung(flesh.youngsModulus, flesh.poissonRatio),
               flesh.dynamics, volume_->kinematic),
      fps_(shot.fps),
      substeps_(flesh.substeps),
      startFrame_(shot.frameStart + std::min(0.0, shot.shutter ? shot.shutter->first : 0.0)),
      simulation_(initial_) {
  // How deep each node lies, as a fraction of the flesh's depth: 0 on the skin, 1 on the inner surface.
  for (const flesh::NodeAnchor& anchor : volume_->anchors)
    depthFraction_.push_back(std::clamp(anchor.offset.norm() / flesh.volume.depth, 0.0, 1.0));
  if (const fs::path cache = fleshCacheDirectory(); !cache.empty() && filing == StateFiling::On) {
    stateDirectory_ = cache / "states";
    stateKeys_.push_back(baseStateKey(flesh, *patch_, fps_, startFrame_));
    keyedPoseThrough_ = int(std::floor(startFrame_)) - 1;
  }
  restart();
}

std::vector<Vec3d> FleshRun::targetAtFrame(int frame) {
  for (const auto& [posedFrame, target] : posedTargets_)
    if (posedFrame == frame) return target;
  // The skin as the rig poses it, and as its joints alone pose it (the skull's and jaw's motion,
  // no expression).
  AssetPose pose = assetPoseAt(*asset_, frame);
  const std::vector<Vec3d> skin = flesh::anchoredNodePositions(
      *volume_, *patch_, patchPositions(*patch_, posedPrimitive(*asset_, pose, primitive_)));
  std::fill(pose.face.blendshapeWeights.begin(), pose.face.blendshapeWeights.end(), 0.0f);
  const std::vector<Vec3d> skull = flesh::anchoredNodePositions(
      *volume_, *patch_, patchPositions(*patch_, posedPrimitive(*asset_, pose, primitive_)));
  std::vector<Vec3d> target(skin.size());
  for (size_t i = 0; i < target.size(); ++i) target[i] = (1.0 - depthFraction_[i]) * skin[i] + depthFraction_[i] * skull[i];
  posedTargets_[nextPosedSlot_] = {frame, target};
  nextPosedSlot_ = (nextPosedSlot_ + 1) % posedTargets_.size();
  return target;
}

std::vector<Vec3d> FleshRun::targetAt(double frame) {
  const int before = int(std::floor(frame));
  const double f = frame - before;
  std::vector<Vec3d> target = targetAtFrame(before);
  if (f == 0.0) return target;
  const std::vector<Vec3d> after = targetAtFrame(before + 1);
  for (size_t i = 0; i < target.size(); ++i) target[i] += f * (after[i] - target[i]);
  return target;
}

void FleshRun::restart() {
  simulation_ = initial_;
  step_ = 0;
  target_ = targetAt(startFrame_);
  // At rest on the rig's pose, moving with it.
  const std::vector<Vec3d> next = targetAt(frameAtStep(1));
  const double h = stepFrames() / fps_;
  std::vector<Vec3d> velocities(next.size());
  for (size_t i = 0; i < next.size(); ++i) velocities[i] = (next[i] - target_[i]) / h;
  simulation_.setState(target_, velocities);
  offsets_.assign(next.size(), Vec3d::Zero());
  previousOffsets_ = offsets_;
  previousKnown_ = true;
}

void FleshRun::advanceOneStep() {
  const double h = stepFrames() / fps_;
  std::vector<Vec3d> next = targetAt(frameAtStep(step_ + 1));
  std::vector<Vec3d> velocities(next.size());
  for (size_t i = 0; i < next.size(); ++i) velocities[i] = (next[i] - target_[i]) / h;
  const flesh::FleshStepReport report = simulation_.step(h, next, velocities);
  ++counts_.steps;
  counts_.newtonIterations += report.newtonIterations;
  counts_.conjugateGradientIterations += report.cgIterations;
  target_ = std::move(next);
  ++step_;
  previousOffsets_ = std::move(offsets_);
  previousKnown_ = true;
  offsets_.resize(target_.size());
  for (size_t v = 0; v < target_.size(); ++v) offsets_[v] = simulation_.positions()[v] - target_[v];
  if (step_ % substeps_ == 0) fileState();
}

uint64_t FleshRun::stateKey(long index) {
  // Whole frame j's state depends on the rig's poses of every whole frame up to the one at or
  // after the simulation's time there (the steps interpolate between whole frames' poses).
  while (long(stateKeys_.size()) <= index) {
    uint64_t key = stateKeys_.back();
    const int through = int(std::ceil(startFrame_ + double(stateKeys_.size())));
    for (; keyedPoseThrough_ < through; ++keyedPoseThrough_)
      key = flesh::chainFleshStateKey(key, targetAtFrame(keyedPoseThrough_ + 1));
    stateKeys_.push_back(key);
  }
  return stateKeys_[size_t(index)];
}

void FleshRun::fileState() {
  if (stateDirectory_.empty()) return;
  const long index = step_ / substeps_;
  try {
    std::error_code ec;
    std::filesystem::create_directories(stateDirectory_, ec);
    const flesh::FleshState state{simulation_.positions(), simulation_.velocities()};
    flesh::writeFleshState(flesh::fleshStateFile(stateDirectory_, index, stateKey(index)), state, stateKey(index));
  } catch (const std::exception&) {
    // Not filed (a full or read-only disk): a later frame rendered alone simulates more.
  }
}

bool FleshRun::loadState(long index) {
  const uint64_t key = stateKey(index);
  std::optional<flesh::FleshState> state =
      flesh::readFleshState(flesh::fleshStateFile(stateDirectory_, index, key), key, initial_.positions().size());
  if (!state) return false;
  simulation_ = initial_;
  simulation_.setState(std::move(state->positions), std::move(state->velocities));
  step_ = index * substeps_;
  target_ = targetAt(frameAtStep(step_));
  offsets_.resize(target_.size());
  for (size_t v = 0; v < target_.size(); ++v) offsets_[v] = simulation_.positions()[v] - target_[v];
  previousOffsets_ = offsets_;
  previousKnown_ = false;
  return true;
}

void FleshRun::resumeNear(double frame, bool behind) {
  if (!stateDirectory_.empty()) {
    const long latest = long(std::floor(frame - startFrame_ + 1e-9));
    const long kept = behind ? 0 : step_ / substeps_;
    for (long index = latest; index > kept; --index)
      if (loadState(index)) return;
  }
  if (behind) restart();
}

std::vector<Vec3d> FleshRun::nodeOffsetsAt(double frame) {
  const size_t nodes = volume_->mesh.nodes.size();
  if (frame <= startFrame_) return std::vector<Vec3d>(nodes, Vec3d::Zero());
  std::lock_guard<std::mutex> lock(mutex_);
  constexpr double kSlack = 1e-9;  // frames: a time on the step grid is on it
  const double keptFrom = previousKnown_ ? frameAtStep(step_ - 1) : frameAtStep(step_);
  const bool behind = frame < keptFrom - kSlack;
  if (behind || frame > frameAtStep(step_) + 1.0) resumeNear(frame, behind);
  while (frameAtStep(step_) < frame - kSlack) advanceOneStep();
  if (frame >= frameAtStep(step_) - kSlack) return offsets_;
  // Between two steps (a shutter time off the grid): the offsets interpolated linearly between
  // them (a shorter step from the earlier one would cost as much as a whole step).
  const double f = std::clamp((frame - frameAtStep(step_ - 1)) / stepFrames(), 0.0, 1.0);
  std::vector<Vec3d> offsets(nodes);
  for (size_t v = 0; v < nodes; ++v) offsets[v] = previousOffsets_[v] + f * (offsets_[v] - previousOffsets_[v]);
  return offsets;
}

bool fleshMoves(const ShotFlesh& flesh, const TriangleMesh& posed) {
  return flesh.tetVolume && posed.positions.size() == flesh.skinEmbedding.size();
}

void moveSkinWithFlesh(const ShotFlesh& flesh, const GltfPrimitive& primitiveSource, const std::vector<Vec3d>& offsets,
                       TriangleMesh& posed) {
  const flesh::TetMesh& mesh = flesh.tetVolume->mesh;
  bool any = false;
  for (size_t v = 0; v < posed.positions.size(); ++v) {
    const flesh::TetEmbedding& e = flesh.skinEmbedding[v];
    if (e.tet < 0) continue;
    const Vec3d offset = flesh::embeddedPosition(mesh, offsets, e);
    if (offset == Vec3d::Zero()) continue;
    posed.positions[v] += offset.cast<float>();
    any = true;
  }
  // The normals as the rig makes them for this primitive (a linear refinement is shaded as the
  // unrefined mesh: normals from the split triangles would show its facets, and would turn the
  // directions the details then displace the skin along).
  if (any) computePrimitiveNormals(posed, primitiveSource);
}

}  // namespace lacrima::shotfile
