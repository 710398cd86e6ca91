#pragma once
// The performances `lacrima track --synthesize` captures and `lacrima bench --tracking` tracks:
// per frame a face's blendshape weights and its head's motion, keyed from archetypal expressions
// or taken from a shot's animation of an asset.
#include <string>
#include <vector>

#include "lacrima/tracking/animation_prior.hpp"
#include "lacrima/tracking/blendshape_fit.hpp"

namespace lacrima::cli {

// What a synthetic capture records: per frame the face's weights (the model's targets) and the
// head's motion in its own axes (the rig's head joint about its pivot).
struct SyntheticTake {
  double fps = 30.0;
  int firstFrame = 1;
  tracking::WeightSequence weights;
  std::vector<Eigen::Isometry3d> headMotions;
  std::string description;
};

// The face at rest in front of the synthetic camera: 0.7 m away, the face's axes (+z towards the
// viewer, +y up) turned to the camera's (x right, y down, z forward).
Eigen::Isometry3d cameraFacing();

// Keyed archetypal expressions from the neutral face with spontaneous blinks, at 30 fps, the head
// turning up to 8 degrees left and right every 3 s, nodding 3 degrees every 4 s, swaying 1 cm.
SyntheticTake keyedTake(const tracking::BlendshapeModel& model, int frames, uint64_t seed);

// A shot's animation of its asset `assetName`, frame by frame over the shot's frames at its fps:
// every weight source and the rig's head joint (about `headPivot`), as the shot poses it. Throws
// InputError when the shot has no such asset.
SyntheticTake takeFromShot(const std::string& shotPath, const std::string& assetName,
                           const tracking::BlendshapeModel& model, const Vec3d& headPivot);

// How close a tracked weight sequence is to the truth, over the frames both have: the weights' RMSE
// and the mean over frames of the model's RMS vertex distance (millimetres).
struct TrackAccuracy {
  double weightRmse = 0.0, vertexMm = 0.0;
};
TrackAccuracy trackAccuracy(const tracking::BlendshapeModel& model, const tracking::WeightSequence& truth,
                            const tracking::WeightSequence& tracked);

}  // namespace lacrima::cli
