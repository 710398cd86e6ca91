#pragma once
// Comparison of two images channel by channel: per channel group (the beauty and each AOV)
// mean absolute error, RMS, the largest difference with its pixel and channel, PSNR, and the
// pixels over idiff-style fail/warn thresholds; plus the FLIP perceptual error of the beauty.
// Used by `lacrima diff` and `lacrima test-suite`; docs/diff.md explains every number.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::diff {

// An image as read from disk: all channels as float, interleaved, row-major, top row first.
struct Image {
  std::string path;
  int width = 0, height = 0;
  std::vector<std::string> channels;
  std::vector<float> values;
  bool highDynamicRange = false;  // float/half data (EXR): HDR-FLIP; 8/16-bit integer (PNG): LDR-FLIP
  std::string colorSpace;         // lacrima:colorSpace of a lacrima EXR ("ACEScg"), else empty

  float at(int x, int y, int channel) const {
    return values[(size_t(y) * size_t(width) + size_t(x)) * channels.size() + size_t(channel)];
  }
  int channelIndex(const std::string& name) const;  // -1 when absent
};

// Reads every channel of the first subimage. Throws InputError "<path>: no such file" or
// "<path>: cannot read image: <reason>".
Image readImage(const std::string& path);

// Channels that belong together: "beauty" (R, G, B, A), each dotted prefix ("N" for N.X N.Y N.Z,
// "albedo" for albedo.R ...), and every other undotted channel on its own ("Z").
struct ChannelGroup {
  std::string name;
  std::vector<std::string> channels;
};
std::vector<ChannelGroup> channelGroups(const std::vector<std::string>& channelNames);

// idiff semantics: a pixel fails when any channel differs by more than `fail`, warns when by
// more than `warn`; the image fails when more than `failPercent` % of its pixels fail (or its
// mean error exceeds `maxMeanError`), warns when more than `warnPercent` % warn.
struct Thresholds {
  double fail = 1e-6, failPercent = 0.0;
  double warn = 1e-6, warnPercent = 0.0;
  std::optional<double> maxMeanError;
};

enum class Verdict { Pass = 0, Warn = 1, Fail = 2 };  // also the exit status
const char* verdictName(Verdict v);                    // "PASS", "WARN", "FAIL"
Verdict worst(Verdict a, Verdict b);

struct GroupMetrics {
  std::string name;
  std::vector<std::string> channels;
  double meanError = 0, rmsError = 0, maxError = 0;
  int maxX = 0, maxY = 0;
  std::string maxChannel;
  // 10 log10(peak^2 / MSE) with peak 1.0 (display white in linear HDR, 255 in 8-bit PNGs read as
  // 0..1); +infinity for identical channels.
  double psnr = std::numeric_limits<double>::infinity();
  size_t failPixels = 0, warnPixels = 0;
  double failPercent = 0, warnPercent = 0;
  Verdict verdict = Verdict::Pass;
  std::vector<std::string> reasons;  // why it is not a pass, one sentence each
};

struct FlipResult {
  bool highDynamicRange = false;
  double ppd = 0;
  double startExposure = 0, stopExposure = 0;  // HDR only
  int exposures = 0;
  double mean = 0, max = 0;
  int maxX = 0, maxY = 0;
  std::vector<double> errorMap;  // per pixel, [0, 1]
};

struct CompareOptions {
  Thresholds thresholds;
  std::vector<std::string> groups;  // the channel groups to compare; empty: all
  bool flip = true;                 // FLIP of the beauty's R, G, B (when both have them)
  double ppd = 0;                   // 0: the FLIP default (67.02)
};

struct Comparison {
  std::string pathA, pathB;
  int width = 0, height = 0;
  std::vector<GroupMetrics> groups;
  std::optional<FlipResult> flip;
  Verdict verdict = Verdict::Pass;
};

// Compares A (the reference, for FLIP) with B. Throws InputError naming the offending file for
// different sizes, a channel of one image missing in the other, or an unknown group name.
Comparison compareImages(const Image& a, const Image& b, const CompareOptions& options);

// |A - B| of the compared channels, channel names kept, as a float EXR (written atomically).
void writeDifferenceImage(const std::string& path, const Image& a, const Image& b, const Comparison& comparison);
// The FLIP error map through the magma colour map, as an 8-bit sRGB PNG (written atomically).
void writeFlipImage(const std::string& path, const FlipResult& flip, int width, int height);

}  // namespace lacrima::diff
