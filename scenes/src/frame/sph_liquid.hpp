#pragma once
// A shot's SPH liquids (ShotSph, docs/shot-format.md "sph"), frame by frame: the colliders sampled
// into boundary particles at the liquid's start frame, the fluid released as drops and blocks at
// their frames and simulated from that start (so any frame renders alone), surfaced at
// shutter open and added to the frame as closed meshes of the liquid's material, each vertex moved
// at shutter close by the velocity of the particles around it (motion blur).
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "lacrima/renderer/frame.hpp"
#include "lacrima/scenes/shot_model.hpp"
#include "lacrima/sph/dfsph.hpp"
#include "resolve/sph_resolve.hpp"  // SphParticles, releasedParticles

namespace lacrima::shotfile {

// Where SPH checkpoints are filed: $XDG_CACHE_HOME/lacrima/sph/states, else
// ~/.cache/lacrima/sph/states; empty (not filed) when neither is set.
std::filesystem::path sphStateDirectory();

// One liquid's simulation, advanced on demand. It keeps the particles at the latest whole frame
// reached (a checkpoint) and steps from checkpoint to checkpoint, each step run by a solver seeded
// with the checkpoint's particles alone (DfsphSolver::setState, no warm start carried over), and a
// release due at a frame added at its checkpoint. A time between checkpoints is reached by a solver
// seeded at the checkpoint before it, which the run does not keep. So the particles at any time are
// a function of that time alone, whatever was asked before: a frame built alone, in a sequence or
// after a later frame (which starts again from the liquid's start) gets the same particles, bit for
// bit. Colliders that move (a keyed shape, an animated asset part) move their boundary particles
// (the same sites on their triangles) from their pose at one whole frame to the next in a straight
// line within the frame. Each checkpoint is filed on disk (sphStateDirectory()) under a key of everything the
// simulation depends on (fluid, colliders, releases, frame rate) and its frame, so a frame built
// alone (a farm task) continues from the latest filed checkpoint before it. Thread-safe.
class SphRun {
 public:
  SphRun(const Shot& shot, const ShotSph& liquid);

  // The particles at a (fractional) frame; none before the first release.
  SphParticles particlesAt(double frame);

 private:
  // The particles of the releases at whole frame `index` (frames since the start).
  void addReleasesAt(long index, SphParticles& particles) const;
  // The checkpoint after `particles` at whole frame `index`: stepped one frame, then released.
  SphParticles nextCheckpoint(const SphParticles& particles, long index) const;
  // `particles` at whole frame `index` stepped on to `seconds` (within the frame after it).
  SphParticles steppedTo(const SphParticles& particles, long index, double seconds) const;

  // Samples the colliders into boundary particles at the start frame, once, on the first frame
  // asked for (not at load: `lacrima check` and a shot's loading stay cheap; a 10 cm table at
  // 0.2 mm spacing is a quarter of a million particles).
  void prepareBoundary();
  // A collider as the run keeps it: a copy of its shape or asset, and its boundary particles' sites.
  struct Collider {
    std::optional<ShotShape> shape;
    std::optional<ShotAsset> asset;  // its meshes and rig shared with the shot's
    std::optional<ShotAsset> attachedAsset;  // a shape's: the asset its `attach` follows
    std::vector<size_t> primitives;   // of the asset, in its part
    std::vector<ShotSkinRegion> regions;  // the stretch of the part sampled; none: all of it
    std::vector<std::vector<sph::SurfaceSite>> sites;  // per mesh (one for a shape)
    bool moves = false;
    std::string pointer;  // "/sph/0/colliders/1", for errors
  };
  // Puts boundary sites on the collider (its regions only, when it has some) at the start frame;
  // their positions. Throws InputError when it would take too many or its regions hold nothing.
  std::vector<Vec3d> sampleCollider(Collider& collider) const;
  // The collider's meshes at a (whole) frame.
  std::vector<TriangleMesh> colliderMeshes(const Collider& collider, double frame) const;
  // Every boundary particle's position at whole frame `index` (frames since the start).
  const std::vector<Vec3d>& boundaryAt(long index) const;
  // The filed checkpoint at whole frame `index`, when one is filed under its key.
  std::optional<SphParticles> readCheckpoint(long index) const;
  void fileCheckpoint() const;
  uint64_t checkpointKey(long index) const;
  size_t particleCountAt(long index) const;

  sph::FluidParams params_;
  std::vector<Collider> colliders_;
  bool collidersMove_ = false;
  bool prepared_ = false;            // prepareBoundary has run
  sph::BoundaryParticles boundary_;  // at the start
  std::vector<std::pair<long, SphParticles>> releases_;  // (whole frame since the start, particles)
  double startFrame_, fps_;
  std::filesystem::path shotPath_;  // for errors
  uint64_t key_;                          // of everything the simulation depends on
  std::filesystem::path stateDirectory_;  // empty: checkpoints are not filed

  std::mutex mutex_;
  mutable std::map<long, std::vector<Vec3d>> posedBoundaries_;  // boundaryAt's last few frames
  mutable std::vector<uint64_t> keys_;  // checkpointKey's chain, per whole frame (moving colliders)
  long checkpointIndex_ = -1;  // none yet
  SphParticles checkpoint_;
};

// The liquids' surfaces at shutter open (and their motion to shutter close) added to `frame`;
// `runs`: one per liquid of the shot, in order.
void addSphLiquids(const Shot& shot, const std::vector<std::unique_ptr<SphRun>>& runs, double openFrame,
                   double closeFrame, Frame& frame);

}  // namespace lacrima::shotfile
