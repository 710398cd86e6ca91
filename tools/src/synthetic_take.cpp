// Synthetic takes; see synthetic_take.hpp.
#include "synthetic_take.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/base/hash.hpp"
#include "lacrima/scenes/shot.hpp"
#include "track_io.hpp"

namespace lacrima::cli {

using namespace tracking;

namespace {

// The keyed take's head: turning up to 8 degrees left and right every 3 s, nodding 3 degrees every
// 4 s, swaying 1 cm.
Eigen::Isometry3d syntheticHeadMotion(double seconds) {
  const double degree = std::numbers::pi / 180.0, tau = 2.0 * std::numbers::pi;
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = (Eigen::AngleAxisd(8.0 * degree * std::sin(tau * seconds / 3.0), Vec3d::UnitY()) *
                     Eigen::AngleAxisd(3.0 * degree * std::sin(tau * seconds / 4.0), Vec3d::UnitX()))
                        .toRotationMatrix();
  motion.translation() = Vec3d(0.01 * std::sin(tau * seconds / 5.0), 0.0, 0.0);
  return motion;
}

// A pose's weights (indexed like the asset's targetNames) as the model's, by name.
Eigen::VectorXd modelWeights(const BlendshapeModel& model, const std::vector<std::string>& assetNames,
                             const std::vector<float>& assetWeights) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(model.targetCount());
  for (size_t t = 0; t < model.targetNames.size(); ++t) {
    const size_t at = size_t(std::find(assetNames.begin(), assetNames.end(), model.targetNames[t]) - assetNames.begin());
    if (at < assetWeights.size()) w[long(t)] = assetWeights[at];
  }
  return w;
}

bool turnsJawOrEyes(const FacePose& pose) {
  return !pose.jaw.isIdentity() ||
         std::any_of(pose.eyeEulerDegrees.begin(), pose.eyeEulerDegrees.end(), [](const Vec3& e) { return !e.isZero(0.0f); });
}

}  // namespace

Eigen::Isometry3d cameraFacing() {
  Eigen::Isometry3d facing = Eigen::Isometry3d::Identity();
  facing.linear() = Vec3d(1, -1, -1).asDiagonal();
  facing.translation() = Vec3d(0, 0, 0.7);
  return facing;
}

SyntheticTake keyedTake(const BlendshapeModel& model, int frames, uint64_t seed) {
  SyntheticTake take;
  take.weights = keyedPerformance(archetypalExpressions(model.targetNames), frames, seed);
  addSpontaneousBlinks(take.weights, blinkExpression(model.targetNames), take.fps, hashCombine(seed, 0xb1));
  for (int i = 0; i < frames; ++i) take.headMotions.push_back(syntheticHeadMotion(double(i) / take.fps));
  take.description = "a keyed performance (archetypal expressions, spontaneous blinks)";
  return take;
}

SyntheticTake takeFromShot(const std::string& shotPath, const std::string& assetName, const BlendshapeModel& model,
                           const Vec3d& headPivot) {
  const Shot shot = loadShot(shotPath);
  const auto asset = std::find_if(shot.assets.begin(), shot.assets.end(),
                                  [&](const ShotAsset& a) { return a.name == assetName; });
  if (asset == shot.assets.end())
    throw InputError(fmt::format("{}: no asset named '{}' (--shot-asset)", shotPath, assetName));
  SyntheticTake take;
  take.fps = shot.fps;
  take.firstFrame = shot.frameStart;
  bool unseenJoints = false;
  for (int frame = shot.frameStart; frame <= shot.frameEnd; ++frame) {
    const FacePose pose = assetFacePoseAt(shot, size_t(asset - shot.assets.begin()), frame);
    take.weights.push_back(modelWeights(model, asset->gltf->targetNames, pose.blendshapeWeights));
    Eigen::VectorXd head(6);
    head << pose.head.eulerDegrees.cast<double>(), pose.head.translation.cast<double>();
    take.headMotions.push_back(headMotionOfChannels(head, headPivot));
    unseenJoints = unseenJoints || turnsJawOrEyes(pose);
  }
  if (unseenJoints)
    std::fprintf(stderr, "lacrima track: %s turns the jaw or eye joints of '%s': the synthetic capture keeps only its "
                 "blendshapes and head\n", shotPath.c_str(), assetName.c_str());
  take.description = fmt::format("{}'s '{}' (frames {}-{} at {} fps)", std::filesystem::path(shotPath).filename().string(),
                                 assetName, shot.frameStart, shot.frameEnd, shot.fps);
  return take;
}

TrackAccuracy trackAccuracy(const BlendshapeModel& model, const WeightSequence& truth, const WeightSequence& tracked) {
  TrackAccuracy accuracy;
  const size_t n = std::min(truth.size(), tracked.size());
  if (n == 0) return accuracy;
  double squares = 0.0;
  for (size_t i = 0; i < n; ++i) {
    squares += (tracked[i] - truth[i]).squaredNorm() / double(model.targetCount());
    const std::vector<Vec3d> a = model.positions(tracked[i]), b = model.positions(truth[i]);
    double s = 0.0;
    for (size_t v = 0; v < a.size(); ++v) s += (a[v] - b[v]).squaredNorm();
    accuracy.vertexMm += 1e3 * std::sqrt(s / double(a.size())) / double(n);
  }
  accuracy.weightRmse = std::sqrt(squares / double(n));
  return accuracy;
}

}  // namespace lacrima::cli
