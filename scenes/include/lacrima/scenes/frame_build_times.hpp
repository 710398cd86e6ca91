#pragma once
// Where FrameBuilder::build's time goes, stage by stage, for `lacrima bench`'s per-frame report.
// Separate from frame_builder.hpp so that the files including it do not recompile when a stage is
// added.
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima {

// Wall seconds (std::chrono::steady_clock) of each stage of one FrameBuilder::build call. The
// subdivision of the skin under details and along liquid trails happens once per shot, in
// loadShot, so the per-frame stages below pose, displace and simulate on the already refined
// meshes.
struct FrameBuildTimes {
  double rigSeconds = 0.0;     // assets posed: blendshapes, skinning, normals (shutter open and close)
  double fleshSeconds = 0.0;   // simulated flesh: the simulation up to the frame, the skin moved with it
  double detailSeconds = 0.0;  // details displacing the posed skin, normals renewed around them
  // Liquid tears' simulation up to the frame's shutter open and close. It runs beside rig, flesh and
  // details (it needs no posed asset), so its time overlaps theirs.
  double liquidSimulationSeconds = 0.0;
  // Liquid tears on the posed skin: the wet trail's film, the meniscus swelling, beads and drops;
  // SPH liquids.
  double liquidSeconds = 0.0;
  double eyeSeconds = 0.0;     // eyes (cornea, sclera, iris, pupil) and lashes
  // The posed meshes copied into the Frame (with their defect check), shapes, kinematic tears,
  // lights, camera.
  double otherSeconds = 0.0;
  double totalSeconds = 0.0;   // the whole call
};

}  // namespace lacrima
