// `lacrima track`: the realtime tracker of Weise, Bouaziz, Li & Pauly 2011
// (geometry/tracking, docs/tracking.md) on a recorded performance (depth EXRs + landmarks), writing
// the weight track `lacrima render` plays (the shot's `performance`) and the head pose; or a
// synthetic performance of a face to validate it on (`--synthesize`).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "atomic_write.hpp"
#include "commands.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/rig/face_rig.hpp"
#include "lacrima/io/performance_track.hpp"
#include "lacrima/scenes/shot.hpp"
#include "lacrima/tracking/depth_sensor.hpp"
#include "lacrima/tracking/initial_pose.hpp"
#include "lacrima/tracking/performance_tracker.hpp"
#include "lacrima/tracking/synthetic_capture.hpp"
#include "landmark_io.hpp"
#include "synthetic_take.hpp"
#include "track_io.hpp"

namespace lacrima::cli {

namespace {

using namespace tracking;

std::filesystem::path assetPath(const TrackOptions& o) {
  return o.asset.empty() ? std::filesystem::path(LACRIMA_SOURCE_DIR) / "scenes/assets/ict-face/ict_face.glb"
                         : std::filesystem::path(o.asset);
}

// A shot that renders the face playing truth_performance.csv (weights and the head's channels,
// through the ICT rig) from (0, 0, distance) with the pinhole camera's vertical field of view, so
// that its Z AOV is the camera's depth map.
std::string captureShot(const TrackOptions& o, const PinholeCamera& camera, int firstFrame, int lastFrame, double fps,
                        double distance) {
  const double fov = 2.0 * std::atan(0.5 * camera.height / camera.fy) * 180.0 / std::numbers::pi;
  return fmt::format(R"({{
  // Written by `lacrima track --synthesize --render`: the face playing truth_performance.csv, seen by the
  // performance's depth camera (its Z AOV is the depth map; {}x{}, vertical field of view {:.4f} degrees).
  "version": 1,
  "frames": {{"start": {}, "end": {}, "fps": {}}},
  "output": "render.####.exr",
  "render": {{"width": {}, "height": {}, "spp": 4, "maxDepth": 2, "seed": {}}},
  "camera": {{"position": [0, 0, {}], "lookAt": [0, 0, 0], "fov": {:.6f}}},
  "materials": {{"skin": {{"type": "diffuse", "albedo": [0.6, 0.45, 0.4]}}}},
  "lights": [{{"type": "sphere", "center": [0.3, 0.4, 0.8], "radius": 0.05, "power": 40}}],
  "assets": [{{"name": "face", "file": "{}", "materials": {{"{}": "skin"}},
              // The real-time helper shells over the eyes are not surfaces a sensor sees.
              "hide": ["M_EyeBlend", "M_EyeOcclusion"],
              "rig": {{"preset": "ict"}},
              "performance": {{"file": "truth_performance.csv", "fps": {}}}}}]
}}
)",
                     camera.width, camera.height, fov, firstFrame, lastFrame, fps, camera.width, camera.height, o.seed, distance, fov,
                     assetPath(o).string(), o.part, fps);
}

// The weights and the head's channels, one CSV a shot plays on an asset with a rig
// (`"rig": {"preset": "ict"}`).
void writePerformanceCsv(const std::filesystem::path& file, const BlendshapeModel& model, int firstFrame,
                         const WeightSequence& weights, const WeightSequence& head) {
  std::vector<std::string> names = model.targetNames;
  names.insert(names.end(), headChannelNames().begin(), headChannelNames().end());
  WeightSequence rows;
  for (size_t i = 0; i < weights.size(); ++i) {
    Eigen::VectorXd row(weights[i].size() + 6);
    row << weights[i], head[i];
    rows.push_back(row);
  }
  writeWeightsCsv(file, names, firstFrame, rows);
}

int synthesize(const TrackOptions& o, const BlendshapeModel& model, const Vec3d& headPivot) {
  const std::filesystem::path dir = o.synthesize;
  const SyntheticTake take =
      o.fromShot.empty() ? keyedTake(model, o.frames, o.seed) : takeFromShot(o.fromShot, o.shotAsset, model, headPivot);
  const int frames = int(take.weights.size());
  PerformanceManifest m;
  m.file = dir / "performance.json";
  m.fps = take.fps;
  m.firstFrame = take.firstFrame;
  m.lastFrame = take.firstFrame + frames - 1;
  m.depthPattern = (dir / "depth.####.exr").string();
  m.landmarks = dir / "landmarks.csv";
  WeightSequence headTruth;
  std::vector<Eigen::Isometry3d> poses;
  for (const Eigen::Isometry3d& motion : take.headMotions) {
    headTruth.push_back(channelsOfHeadMotion(motion, headPivot));
    poses.push_back(cameraFacing() * motion);
  }
  writeWeightsCsv(dir / "truth_weights.csv", model.targetNames, m.firstFrame, take.weights);
  writePerformanceCsv(dir / "truth_performance.csv", model, m.firstFrame, take.weights, headTruth);
  if (o.render) {
    // The face rendered by the path tracer, every primitive of the asset in view; its Z AOV is read
    // back below as the sensor's depth.
    writeFileAtomically(dir / "capture.json", "the capture shot", [&](std::ostream& out) {
      out << captureShot(o, m.camera, m.firstFrame, m.lastFrame, m.fps, cameraFacing().translation().z());
    });
    RenderOptions render;
    render.shotPath = (dir / "capture.json").string();
    render.quiet = true;
    if (const int status = runRender(render); status != kExitOk) return status;
  }
  const LandmarkDetectorErrors detector{o.landmarkNoise, o.contourDrift, o.dropHiddenLandmarks};
  LandmarkTrack landmarks;
  for (int i = 0; i < frames; ++i) {
    const int frame = m.firstFrame + i;
    const Eigen::Isometry3d& pose = poses[size_t(i)];
    const uint64_t noiseSeed = hashCombine(o.seed, uint64_t(frame));
    DepthFrame depth(m.camera);
    if (o.render) {
      depth = readDepthExr(expandFramePattern((dir / "render.####.exr").string(), frame), m.camera);
      addSensorNoise(depth, o.noise, noiseSeed);
    } else {
      depth = captureDepth(model, take.weights[size_t(i)], pose, m.camera, o.noise, noiseSeed);
    }
    writeDepthExr(expandFramePattern(m.depthPattern, frame), depth);
    landmarks[frame] = detectLandmarks(model, take.weights[size_t(i)], pose, m.camera, detector, hashCombine(o.seed, 7),
                                       frame, double(i) / take.fps, &depth);
  }
  writeLandmarksCsv(m.landmarks, landmarks);
  writePerformanceManifest(m);
  std::printf("synthesized %d frames of %s (depth %s, noise x%g; landmarks +-%g px%s%s) in %s: performance.json, "
              "depth.####.exr, landmarks.csv, truth_weights.csv, truth_performance.csv\n",
              frames, take.description.c_str(), o.render ? "rendered by lacrima (Z AOV)" : "rasterised", o.noise,
              o.landmarkNoise, o.contourDrift > 0 ? fmt::format(", jaw line drifting {} px", o.contourDrift).c_str() : "",
              o.dropHiddenLandmarks ? ", hidden ones dropped" : "", dir.string().c_str());
  return kExitOk;
}

// --head-start: the head's channels at the first frame (rx, ry, rz in degrees, then optionally
// tx, ty, tz in metres) as a motion about the pivot.
Eigen::Isometry3d headStart(const TrackOptions& o, const Vec3d& headPivot) {
  if (o.headStart.empty()) return Eigen::Isometry3d::Identity();
  if (o.headStart.size() != 3 && o.headStart.size() != 6)
    throw InputError(fmt::format("--head-start takes 3 values (rx ry rz, degrees) or 6 (and tx ty tz, metres), not {}",
                                 o.headStart.size()));
  Eigen::VectorXd channels = Eigen::VectorXd::Zero(6);
  for (size_t i = 0; i < o.headStart.size(); ++i) channels[long(i)] = o.headStart[i];
  return headMotionOfChannels(channels, headPivot);
}

int track(const TrackOptions& o, const BlendshapeModel& model, const Vec3d& headPivot) {
  const PerformanceManifest m = readPerformanceManifest(o.performance);
  const LandmarkTrack landmarks = m.landmarks.empty() ? LandmarkTrack{} : readLandmarks(m.landmarks);
  const std::optional<AnimationPrior> prior = o.noPrior ? std::nullopt : std::optional(archetypalPrior(model.targetNames));
  TrackerParams params;
  params.filterPose = !o.noFilter;
  params.upperFaceAbove = noseTipHeight(model);
  params.fit.sigmaLandmark = o.landmarkSigma;
  std::optional<PerformanceTracker> tracker;
  WeightSequence weights;
  std::vector<Eigen::Isometry3d> poses;
  double trackingSeconds = 0.0;
  for (int frame = m.firstFrame; frame <= m.lastFrame; ++frame) {
    const DepthFrame depth = readDepthExr(expandFramePattern(m.depthPattern, frame), m.camera);
    const auto seen = landmarks.find(frame);
    const std::vector<Eigen::Vector2d> points = seen == landmarks.end() ? std::vector<Eigen::Vector2d>{} : seen->second;
    const auto start = std::chrono::steady_clock::now();
    if (!tracker) {
      const auto first = poseFromLandmarks(model, depth, points);
      if (!first)
        throw InputError(fmt::format("{}: frame {} has fewer than six inner landmarks with depth: cannot find the head",
                                     m.file.string(), frame));
      tracker.emplace(model, prior ? &*prior : nullptr, params, *first);
    }
    const TrackedFrame t = tracker->track(depth, points);
    trackingSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    weights.push_back(t.weights);
    poses.push_back(t.pose);
    if ((frame - m.firstFrame) % 10 == 9 || frame == m.lastFrame)
      std::fprintf(stderr, "track: frame %d of %d-%d (%.1f frames a second)\n", frame, m.firstFrame, m.lastFrame,
                   double(weights.size()) / trackingSeconds);
  }
  const std::filesystem::path out = o.out;
  writeWeightsCsv(out / "weights.csv", model.targetNames, m.firstFrame, weights);
  writePerformanceCsv(out / "performance.csv", model, m.firstFrame, weights, headChannels(poses, headPivot, headStart(o, headPivot)));
  std::printf("tracked %zu frames at %.1f frames a second (tracking alone, 1 thread) -> %s, %s (with head.*)\n", weights.size(),
              double(weights.size()) / trackingSeconds, (out / "weights.csv").string().c_str(),
              (out / "performance.csv").string().c_str());
  // Beside a synthetic performance: how close the track is.
  const std::filesystem::path truthFile = m.file.parent_path() / "truth_weights.csv";
  if (std::filesystem::exists(truthFile)) {
    // The truth is the shot format's weight track: read as a shot reads it (geometry's reader).
    const PerformanceTrack track = readPerformanceCsv(truthFile, model.targetNames);
    WeightSequence truth;
    for (const std::vector<float>& row : track.frames) {
      Eigen::VectorXd w = Eigen::VectorXd::Zero(model.targetCount());
      for (size_t c = 0; c < track.names.size(); ++c)
        w[std::find(model.targetNames.begin(), model.targetNames.end(), track.names[c]) - model.targetNames.begin()] = row[c];
      truth.push_back(w);
    }
    const TrackAccuracy accuracy = trackAccuracy(model, truth, weights);
    std::printf("against truth_weights.csv: weight RMSE %.4f, mean vertex error %.3f mm\n", accuracy.weightRmse,
                accuracy.vertexMm);
  }
  return kExitOk;
}

}  // namespace

int runTrack(const TrackOptions& o) {
  try {
    if (o.performance.empty() == o.synthesize.empty())
      throw InputError("give a performance.json to track, or --synthesize FOLDER (not both)");
    const GltfAsset asset = loadGltfAsset(assetPath(o));
    const BlendshapeModel model = blendshapeModelOf(asset, o.part);
    // The head turns about the rig's pivot: the ICT face's preset (the base of the face), else the
    // asset's origin.
    Vec3d headPivot = Vec3d::Zero();
    try {
      headPivot = ictFaceRigConfig(asset).headPivot.cast<double>();
    } catch (const std::exception&) {
      std::fprintf(stderr, "lacrima track: %s is not the ICT face: the head channels turn about the asset's origin\n",
                   assetPath(o).string().c_str());
    }
    return o.synthesize.empty() ? track(o, model, headPivot) : synthesize(o, model, headPivot);
  } catch (const InputError& e) {
    std::fprintf(stderr, "lacrima track: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
