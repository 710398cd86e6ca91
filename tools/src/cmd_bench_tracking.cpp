// `lacrima bench --tracking`: what the face tracker costs (a live take needs at least 20 frames
// a second on 2 cores, Weise et al.'s own rate: Weise, Bouaziz, Li & Pauly 2011, rigid stage under
// 5 ms, non-rigid 45 ms a frame on their machine). A synthetic take of the ICT face (keyed
// archetypal expressions with blinks, the head turning; rasterised depth with a Kinect's noise,
// landmarks jittered by up to 1 pixel) is tracked with lacrima's prior and with one trained at
// Weise et al.'s size; the report gives each prior's training seconds, each stage's median and slowest
// milliseconds a frame, the frames a second, and the track's error against the take's truth.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "commands.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/base/hash.hpp"
#include "lacrima/tracking/initial_pose.hpp"
#include "lacrima/tracking/performance_tracker.hpp"
#include "lacrima/tracking/synthetic_capture.hpp"
#include "synthetic_take.hpp"

namespace lacrima::cli {

namespace {

using namespace tracking;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// One frame as the sensor and the landmark detector give it.
struct CapturedFrame {
  DepthFrame depth;
  std::vector<Eigen::Vector2d> landmarks;
};

std::vector<CapturedFrame> captureTake(const BlendshapeModel& model, const SyntheticTake& take) {
  std::vector<CapturedFrame> frames;
  for (size_t i = 0; i < take.weights.size(); ++i) {
    const Eigen::Isometry3d pose = cameraFacing() * take.headMotions[i];
    frames.push_back({captureDepth(model, take.weights[i], pose, PinholeCamera{}, 1.0, hashCombine(1, i)),
                      projectLandmarks(model, take.weights[i], pose, PinholeCamera{}, 1.0, hashCombine(2, i))});
  }
  return frames;
}

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, size_t(p * double(values.size())))];
}

void trackAndReport(const char* name, const BlendshapeModel& model, const AnimationPrior* prior,
                    const std::vector<CapturedFrame>& frames, const SyntheticTake& take, bool filter) {
  TrackerParams params;
  params.upperFaceAbove = noseTipHeight(model);
  params.filterPose = filter;
  const auto start = poseFromLandmarks(model, frames.front().depth, frames.front().landmarks);
  if (!start) throw InputError("bench --tracking: the first frame's landmarks found no head");
  PerformanceTracker tracker(model, prior, params, *start);
  std::vector<double> rigidMs, fitMs, frameMs;
  WeightSequence weights;
  for (const CapturedFrame& frame : frames) {
    const auto begin = Clock::now();
    const TrackedFrame t = tracker.track(frame.depth, frame.landmarks);
    frameMs.push_back(1e3 * secondsSince(begin));
    rigidMs.push_back(1e3 * t.rigidSeconds);
    fitMs.push_back(1e3 * t.fitSeconds);
    weights.push_back(t.weights);
  }
  double total = 0.0;
  for (double ms : frameMs) total += ms;
  const TrackAccuracy accuracy = trackAccuracy(model, take.weights, weights);
  std::printf("%-30s rigid %5.2f ms (slowest %5.2f), non-rigid %5.2f ms (slowest %5.2f), %5.1f frames/s; "
              "weight RMSE %.3f, vertex error %.2f mm\n",
              name, percentile(rigidMs, 0.5), percentile(rigidMs, 1.0), percentile(fitMs, 0.5), percentile(fitMs, 1.0),
              1e3 * double(frames.size()) / total, accuracy.weightRmse, accuracy.vertexMm);
}

}  // namespace

int runBenchTracking(const BenchOptions& o) {
  try {
    const auto loadStart = Clock::now();
    const GltfAsset asset = loadGltfAsset(std::filesystem::path(LACRIMA_SOURCE_DIR) / "scenes/assets/ict-face/ict_face.glb");
    const BlendshapeModel model = blendshapeModelOf(asset, "M_Face");
    std::printf("lacrima bench --tracking: the ICT face's M_Face (%zu vertices, %d targets), loaded in %.2f s; "
                "one thread (the tracker is serial)\n",
                model.neutral.positions.size(), model.targetCount(), secondsSince(loadStart));
    const SyntheticTake take = keyedTake(model, o.trackFrames, 1);
    const std::vector<CapturedFrame> frames = captureTake(model, take);
    std::printf("take: %d frames at 30 fps, %s; depth 640x480 with a Kinect's noise, landmarks +-1 px\n", o.trackFrames,
                take.description.c_str());

    auto trainStart = Clock::now();
    const AnimationPrior lacrimaPrior = archetypalPrior(model.targetNames);
    std::printf("prior, lacrima's: %d analysers, %d EM start(s) of %d iterations, trained in %.2f s (latent dimension %d)\n",
                archetypalPriorParams().components, archetypalPriorParams().restarts,
                archetypalPriorParams().iterations, secondsSince(trainStart), lacrimaPrior.latentDimension());
    AnimationPriorParams seedSize = archetypalPriorParams();
    seedSize.components = 20;
    seedSize.restarts = 50;
    seedSize.iterations = 60;
    trainStart = Clock::now();
    const AnimationPrior seedPrior = archetypalPrior(model.targetNames, seedSize);
    std::printf("prior, Weise et al.'s size: 20 analysers, 50 EM starts of 60 iterations, trained in %.2f s\n",
                secondsSince(trainStart));

    trackAndReport("lacrima's prior and the filter", model, &lacrimaPrior, frames, take, true);
    trackAndReport("seed-size prior and the filter", model, &seedPrior, frames, take, true);
    trackAndReport("lacrima's prior, no filter", model, &lacrimaPrior, frames, take, false);
    trackAndReport("no prior, no filter", model, nullptr, frames, take, false);
    std::printf("Weise et al. 2011 (on their 2011 machine): rigid < 5 ms, non-rigid 45 ms, 20 frames/s, "
                "< 150 ms latency\n");
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "lacrima bench: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
