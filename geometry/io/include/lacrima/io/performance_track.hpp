#pragma once
// Performance-capture blendshape weight tracks (Weise et al. 2011: a tracker's output is a sequence of
// blendshape weights over time), read from CSV and resampled to the render frame rate.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lacrima {

struct PerformanceTrack {
  std::vector<std::string> names;          // one asset blendshape name per channel
  std::vector<float> times;                // seconds, strictly increasing, one per frame
  std::vector<std::vector<float>> frames;  // frames[i][c]: weight of channel c at times[i]
};

struct PerformanceCsvOptions {
  float sourceFps = 30.0f;  // converts a `frame` column to seconds (frame / sourceFps)
  // Tracker name -> asset name (e.g. ARKit "jawOpen" -> the asset's spelling); names not in the
  // map are used as they are.
  std::map<std::string, std::string> nameMap;
};

// Reads a CSV whose header is a `time` (seconds) or `frame` column plus one column per
// blendshape. Every error is an InputError "<file>:<line>:<column>: ..." (1-based) for: no time or
// frame column, a field that is not a finite number, a blendshape name not in validNames (with
// the closest valid name), a time not after the previous row's, or a row with the wrong number
// of fields.
PerformanceTrack readPerformanceCsv(const std::filesystem::path& path, const std::vector<std::string>& validNames,
                                    const PerformanceCsvOptions& options = {});

// The same from JSON: {"fps": 30, "weights": {"jawOpen": [...], ...}} (sample i at i / fps;
// options.sourceFps when "fps" is absent) or {"time": [seconds...], "weights": {...}}. Errors are
// InputError "<file>: <JSON pointer>: ..." for syntax errors, unknown keys or blendshape names
// (with the closest valid one), non-finite numbers, times not increasing, and channels of
// different lengths.
PerformanceTrack readPerformanceJson(const std::filesystem::path& path, const std::vector<std::string>& validNames,
                                     const PerformanceCsvOptions& options = {});

// readPerformanceJson for a .json file, readPerformanceCsv otherwise.
PerformanceTrack readPerformanceTrack(const std::filesystem::path& path, const std::vector<std::string>& validNames,
                                      const PerformanceCsvOptions& options = {});

// The track at targetFps from its first time to its last, by linear interpolation between the
// samples around each output time. Throws InputError for a non-positive or non-finite fps.
PerformanceTrack resampleTrack(const PerformanceTrack& track, float targetFps);

struct AdaptiveFilterOptions {
  int window = 5;          // k, frames looked back (Weise et al. 2011 use k = 5)
  float sharpness = 20.0f;  // H: larger means less smoothing for a given amount of motion
};

// Weise et al. (2011)'s temporal filter, applied to the whole weight vector of each frame (it filters the
// rigid pose there; the same filter keeps weight jitter down without lagging fast expressions):
// a causal weighted average over the last k frames whose weights decay faster when the window
// moved more. Throws InputError for window < 0, non-finite or negative sharpness.
std::vector<std::vector<float>> adaptiveTemporalFilter(const std::vector<std::vector<float>>& frames,
                                                       const AdaptiveFilterOptions& options = {});

}  // namespace lacrima
