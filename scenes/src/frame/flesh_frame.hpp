#pragma once
// A shot's simulated flesh, frame by frame (ShotFlesh, docs/shot-format.md "flesh"): resolved at
// load (resolve/flesh_resolve.hpp), simulated from the shot's first frame with the rig's pose of the volume as the moving rest
// shape, and applied to the posed skin as the simulated nodes' offsets from the rig's.
#include <array>
#include <climits>
#include <mutex>
#include <vector>

#include "lacrima/flesh/flesh_simulation.hpp"
#include "lacrima/scenes/shot_model.hpp"
#include "resolve/flesh_resolve.hpp"

namespace lacrima::shotfile {

// One flesh's simulation, advanced on demand and kept at the step after the latest time asked for
// (a time between two steps is interpolated between them): a sequence rendered in order simulates
// each step once. Its state at each whole frame of the simulation is filed on disk
// (flesh_state_cache.hpp, under fleshCacheDirectory()/states): a time more than a frame ahead, or
// before the kept steps, continues from the latest filed state at or before it, else (behind)
// starts again from the shot's first frame. The same positions either way. Thread-safe.
// What a run has simulated so far (for lacrima bench --flesh).
struct FleshRunCounts {
  long steps = 0, newtonIterations = 0, conjugateGradientIterations = 0;
};

class FleshRun {
 public:
  enum class StateFiling { On, Off };  // Off: states are neither read nor filed (benchmarks)
  FleshRun(const Shot& shot, const ShotFlesh& flesh, StateFiling filing = StateFiling::On);

  FleshRunCounts counts() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return counts_;
  }

  // The simulated nodes' offsets from the rig's pose of them at a (fractional) frame (zero before
  // the simulation starts).
  std::vector<Vec3d> nodeOffsetsAt(double frame);

 private:
  // The rig's pose of the volume's nodes at a (fractional) frame: a node on the skin where the rig
  // puts the skin, a node on the inner surface where the rig's joints alone put it (the skull and
  // jaw carry the deep flesh; an expression moves the skin, and the flesh between follows by
  // depth), blended linearly in between. Posed at the whole frames around it and interpolated
  // linearly (posing the face is most of a step's cost; the rig's keys are smooth over a frame).
  std::vector<Vec3d> targetAt(double frame);
  std::vector<Vec3d> targetAtFrame(int frame);
  double stepFrames() const { return 1.0 / substeps_; }
  double frameAtStep(long step) const { return startFrame_ + double(step) * stepFrames(); }
  void restart();
  void advanceOneStep();
  // Moves to the latest filed state at or before `frame` and after the kept step (any filed state
  // when `behind`); restarts when behind and none is filed.
  void resumeNear(double frame, bool behind);
  bool loadState(long frameIndex);
  void fileState();
  // The chain key of the state at whole frame `index` of the simulation (flesh_state_cache.hpp).
  uint64_t stateKey(long index);

  std::shared_ptr<const ShotAsset> asset_;  // the asset as loaded, unrefined (ShotFlesh::unrefinedAsset)
  size_t primitive_;
  std::shared_ptr<const flesh::SkinPatch> patch_;
  std::shared_ptr<const flesh::FleshVolume> volume_;
  flesh::FleshSimulation initial_;
  double fps_;
  int substeps_;
  double startFrame_;
  std::vector<double> depthFraction_;  // per node: 0 on the skin, 1 on the inner surface

  mutable std::mutex mutex_;
  FleshRunCounts counts_;
  flesh::FleshSimulation simulation_;
  long step_ = 0;                  // simulation_ is at frameAtStep(step_)
  std::vector<Vec3d> target_;      // the rig's pose there
  std::vector<Vec3d> offsets_;     // the simulated nodes' offsets from it
  std::vector<Vec3d> previousOffsets_;  // and at the step before (zero at the start)
  bool previousKnown_ = true;      // false right after a filed state is loaded
  std::filesystem::path stateDirectory_;  // empty: states are not filed
  std::vector<uint64_t> stateKeys_;       // per whole frame of the simulation, as far as computed
  int keyedPoseThrough_ = 0;              // the last whole frame whose pose is in stateKeys_.back()
  std::array<std::pair<int, std::vector<Vec3d>>, 2> posedTargets_{{{INT_MIN, {}}, {INT_MIN, {}}}};
  size_t nextPosedSlot_ = 0;
};

// Whether the flesh moves its posed primitive: the flesh is resolved and embedded in this mesh.
bool fleshMoves(const ShotFlesh& flesh, const TriangleMesh& posed);

// Moves the posed primitive's embedded skin vertices by the flesh's node offsets (its run's
// nodeOffsetsAt one time), interpolated in their tetrahedra, and renews its normals as the rig
// makes them (primitiveSource: the asset's glTF primitive it was posed from). A still face keeps
// the rig's normals bitwise. Only for a primitive the flesh moves (fleshMoves).
void moveSkinWithFlesh(const ShotFlesh& flesh, const GltfPrimitive& primitiveSource, const std::vector<Vec3d>& offsets,
                       TriangleMesh& posed);

}  // namespace lacrima::shotfile
