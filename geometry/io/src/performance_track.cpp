// Reading, resampling and filtering performance-capture weight tracks.
#include "lacrima/io/performance_track.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"
#include "lacrima/base/name_suggestion.hpp"

namespace lacrima {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) {
    const size_t first = field.find_first_not_of(" \t\r"), last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? "" : field.substr(first, last - first + 1));
  }
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// Where in the file a problem is, for messages: "<file>:<line>:<column>".
std::string at(const std::filesystem::path& path, size_t line, size_t column) {
  return fmt::format("{}:{}:{}", path.string(), line, column);
}

float parseFinite(const std::string& text, const std::filesystem::path& path, size_t line, size_t column,
                  const std::string& columnName) {
  float value = 0.0f;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw InputError(fmt::format("{}: '{}' in column '{}' is not a finite number", at(path, line, column), text, columnName));
  return value;
}

struct Header {
  size_t timeColumn = 0;
  bool timeIsFrame = false;
  std::vector<size_t> channelColumns;  // field index of each channel
  std::vector<std::string> names;      // asset names of the channels
  size_t fieldCount = 0;
};

Header parseHeader(const std::string& line, const std::filesystem::path& path, const std::vector<std::string>& validNames,
                   const PerformanceCsvOptions& options) {
  const std::vector<std::string> fields = splitFields(line);
  Header header;
  header.fieldCount = fields.size();
  // The time column first: without it no row can be read, whatever the other columns are.
  const auto time = std::find_if(fields.begin(), fields.end(), [](const std::string& f) { return f == "time" || f == "frame"; });
  if (time == fields.end())
    throw InputError(fmt::format("{}: no 'time' (seconds) or 'frame' column in the header '{}'", at(path, 1, 1), line));
  header.timeColumn = size_t(time - fields.begin());
  header.timeIsFrame = *time == "frame";
  for (size_t c = 0; c < fields.size(); ++c) {
    if (c == header.timeColumn) continue;
    const auto mapped = options.nameMap.find(fields[c]);
    const std::string name = mapped == options.nameMap.end() ? fields[c] : mapped->second;
    if (std::find(validNames.begin(), validNames.end(), name) == validNames.end())
      throw InputError(fmt::format("{}: {}", at(path, 1, c + 1), unknownNameMessage("blendshape", name, validNames)));
    header.channelColumns.push_back(c);
    header.names.push_back(name);
  }
  return header;
}

}  // namespace

PerformanceTrack readPerformanceCsv(const std::filesystem::path& path, const std::vector<std::string>& validNames,
                                    const PerformanceCsvOptions& options) {
  if (!(options.sourceFps > 0.0f) || !std::isfinite(options.sourceFps))
    throw InputError(fmt::format("{}: source fps must be positive (got {})", path.string(), options.sourceFps));
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the performance track", path.string()));
  std::string line;
  if (!std::getline(in, line)) throw InputError(fmt::format("{}: the performance track is empty", path.string()));
  const Header header = parseHeader(line, path, validNames, options);
  PerformanceTrack track;
  track.names = header.names;
  for (size_t lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;  // blank lines, e.g. at the end
    const std::vector<std::string> fields = splitFields(line);
    if (fields.size() != header.fieldCount)
      throw InputError(fmt::format("{}: {} fields, the header has {}", at(path, lineNumber, 1), fields.size(), header.fieldCount));
    float time = parseFinite(fields[header.timeColumn], path, lineNumber, header.timeColumn + 1,
                             header.timeIsFrame ? "frame" : "time");
    if (header.timeIsFrame) time /= options.sourceFps;
    if (!track.times.empty() && !(time > track.times.back()))
      throw InputError(fmt::format("{}: time {} s is not after the previous row's {} s", at(path, lineNumber, header.timeColumn + 1),
                                   time, track.times.back()));
    std::vector<float>& frame = track.frames.emplace_back();
    for (size_t c = 0; c < header.channelColumns.size(); ++c) {
      const size_t column = header.channelColumns[c];
      frame.push_back(parseFinite(fields[column], path, lineNumber, column + 1, header.names[c]));
    }
    track.times.push_back(time);
  }
  return track;
}

PerformanceTrack resampleTrack(const PerformanceTrack& track, float targetFps) {
  if (!(targetFps > 0.0f) || !std::isfinite(targetFps))
    throw InputError(fmt::format("target fps must be positive (got {})", targetFps));
  PerformanceTrack out;
  out.names = track.names;
  if (track.times.empty()) return out;
  const double start = track.times.front(), duration = double(track.times.back()) - start;
  // Found by tools/hardening.sh: a time of 1e7 (or a tiny source fps) asked for hundreds of
  // millions of frames and ended in std::bad_alloc. 1e6 frames is over 11 hours at 24 fps.
  constexpr double kMaxFrames = 1e6;
  const double lastFrame = std::floor(duration * targetFps + 1e-6);
  if (!(lastFrame < kMaxFrames))
    throw InputError(fmt::format("the track spans {:g} s, {:g} frames at {:g} fps: more than {:g} (are the times "
                                 "in seconds and the fps right?)",
                                 duration, lastFrame + 1, targetFps, kMaxFrames));
  const size_t count = size_t(lastFrame) + 1;
  size_t segment = 0;
  for (size_t i = 0; i < count; ++i) {
    const float t = float(start + double(i) / targetFps);
    while (segment + 2 < track.times.size() && track.times[segment + 1] <= t) ++segment;
    out.times.push_back(t);
    if (track.times.size() == 1) {
      out.frames.push_back(track.frames[0]);
      continue;
    }
    // Linear interpolation between the two samples around t (clamped at the last sample).
    const float t0 = track.times[segment], t1 = track.times[segment + 1];
    const float s = std::clamp((t - t0) / (t1 - t0), 0.0f, 1.0f);
    std::vector<float>& frame = out.frames.emplace_back(track.names.size());
    for (size_t c = 0; c < frame.size(); ++c)
      frame[c] = (1.0f - s) * track.frames[segment][c] + s * track.frames[segment + 1][c];
  }
  return out;
}

std::vector<std::vector<float>> adaptiveTemporalFilter(const std::vector<std::vector<float>>& frames,
                                                       const AdaptiveFilterOptions& options) {
  if (options.window < 0 || !std::isfinite(options.sharpness) || options.sharpness < 0.0f)
    throw InputError(fmt::format("adaptive filter: window {} and sharpness {} must be non-negative", options.window,
                                 options.sharpness));
  const auto distance = [](const std::vector<float>& a, const std::vector<float>& b) {
    double d2 = 0.0;
    for (size_t c = 0; c < a.size(); ++c) d2 += double(a[c] - b[c]) * double(a[c] - b[c]);
    return float(std::sqrt(d2));
  };
  std::vector<std::vector<float>> out(frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    const size_t k = std::min(size_t(options.window), i);  // the first frames have a shorter past
    // Weise et al. 2011, Sec. 3: t*_i = sum_j w_j t_{i-j} / sum_j w_j over j = 0..k, with
    // w_j = exp(-j H max_{l in 1..k} |t_i - t_{i-l}|): fast motion makes the weights fall off
    // quickly (little lag), a still face averages the whole window (little jitter).
    float motion = 0.0f;
    for (size_t l = 1; l <= k; ++l) motion = std::max(motion, distance(frames[i], frames[i - l]));
    std::vector<float> sum(frames[i].size(), 0.0f);
    float weightSum = 0.0f;
    for (size_t j = 0; j <= k; ++j) {
      const float w = std::exp(-float(j) * options.sharpness * motion);
      for (size_t c = 0; c < sum.size(); ++c) sum[c] += w * frames[i - j][c];
      weightSum += w;
    }
    for (float& v : sum) v /= weightSum;
    out[i] = std::move(sum);
  }
  return out;
}

}  // namespace lacrima
