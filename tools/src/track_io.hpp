#pragma once
// The files of `lacrima track`: a recorded performance (a manifest naming the depth camera, the
// per-frame depth EXRs and the landmarks CSV), and the tracks it writes (a weight track in the
// shot format's `performance` CSV, and the head pose per frame).
#include <filesystem>
#include <string>
#include <vector>

#include "lacrima/tracking/animation_prior.hpp"
#include "lacrima/tracking/depth_frame.hpp"

namespace lacrima::cli {

// performance.json: {"version": 1, "fps": 30, "frames": {"start": 1, "end": 40},
//   "camera": {"width", "height", "fx", "fy", "cx", "cy"}, "depth": "depth.####.exr",
//   "landmarks": "landmarks.csv"} (files relative to the manifest; landmarks optional).
struct PerformanceManifest {
  std::filesystem::path file;
  double fps = 30.0;
  int firstFrame = 1, lastFrame = 1;
  tracking::PinholeCamera camera;
  std::string depthPattern;          // resolved; '#'s are the frame number
  std::filesystem::path landmarks;   // resolved; empty: none
};

// Reads and checks a manifest (its landmarks: landmark_io.hpp); throws InputError naming the file and the key.
PerformanceManifest readPerformanceManifest(const std::filesystem::path& file);
void writePerformanceManifest(const PerformanceManifest& manifest);

// A depth EXR: one float channel (named Z, or the first), metres, 0 = no measurement, of the
// camera's size. Throws InputError naming the file.
tracking::DepthFrame readDepthExr(const std::filesystem::path& file, const tracking::PinholeCamera& camera);
void writeDepthExr(const std::filesystem::path& file, const tracking::DepthFrame& frame);

// The shot format's performance CSV: "frame,<target>,..." one row per frame.
void writeWeightsCsv(const std::filesystem::path& file, const std::vector<std::string>& names, int firstFrame,
                     const tracking::WeightSequence& weights);

// A face rig's head channels [head.rx, head.ry, head.rz, head.tx, head.ty, head.tz] (Euler
// degrees, x first; metres) and the motion they make, p -> R (p - pivot) + pivot + t.
const std::vector<std::string>& headChannelNames();
Eigen::VectorXd channelsOfHeadMotion(const Eigen::Isometry3d& motion, const Vec3d& pivot);
Eigen::Isometry3d headMotionOfChannels(const Eigen::VectorXd& channels, const Vec3d& pivot);

// The head's motion since the first frame as the head channels, after the head's pose at the
// first frame (`start`, a motion in the asset's own axes; identity: the track starts at rest):
// start M_i with M_i = P_0^-1 P_i (P: model to camera).
tracking::WeightSequence headChannels(const std::vector<Eigen::Isometry3d>& poses, const Vec3d& pivot,
                                      const Eigen::Isometry3d& start = Eigen::Isometry3d::Identity());

}  // namespace lacrima::cli
