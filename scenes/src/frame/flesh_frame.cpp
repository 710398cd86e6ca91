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

std::vector<Vec3d> patchPositions(const flesh::SkinPatch& patch, const TriangleMesh& skin) {
  std::vector<Vec3d> out(patch.skinVertex.size());
  for (size_t v = 0; v < out.size(); ++v) out[v] = skin.positions.at(patch.skinVertex[v]).cast<double>();
  return out;
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

}  // namespace

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
