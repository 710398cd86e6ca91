// Performance-capture weight tracks in JSON (the same data as the CSV form, as a tracker or a
// script writes it):
//   {"fps": 30, "weights": {"jawOpen": [0, 0.1, ...], "eyeBlink_L": [...]}}
// or with explicit sample times in seconds instead of "fps":
//   {"time": [0, 0.04, ...], "weights": {...}}
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "lacrima/base/error.hpp"
#include "lacrima/base/name_suggestion.hpp"
#include "lacrima/io/performance_track.hpp"

namespace lacrima {

namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& pointer, const std::string& message) {
  throw InputError(fmt::format("{}: {}: {}", path.string(), pointer, message));
}

float finiteNumber(const Json& v, const std::filesystem::path& path, const std::string& pointer) {
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    fail(path, pointer, fmt::format("expected a finite number, found {}", v.dump()));
  return v.get<float>();
}

Json parseFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the performance track", path.string()));
  try {
    return Json::parse(in);
  } catch (const Json::parse_error& e) {
    throw InputError(fmt::format("{}: JSON syntax error at byte {}: {}", path.string(), e.byte, e.what()));
  } catch (const Json::out_of_range& e) {  // "1e999": found by tools/hardening.sh (was an internal error)
    throw InputError(fmt::format("{}: JSON number out of range: {}", path.string(), e.what()));
  }
}

// Sample times in seconds: "time" (strictly increasing) or i / fps for `count` samples.
std::vector<float> sampleTimes(const Json& root, size_t count, const std::filesystem::path& path,
                               const PerformanceCsvOptions& options) {
  std::vector<float> times;
  if (root.contains("time")) {
    const Json& time = root["time"];
    if (!time.is_array()) fail(path, "/time", "expected an array of seconds, found " + time.dump());
    for (size_t i = 0; i < time.size(); ++i) {
      const float t = finiteNumber(time[i], path, fmt::format("/time/{}", i));
      if (!times.empty() && !(t > times.back()))
        fail(path, fmt::format("/time/{}", i), fmt::format("time {} s is not after the previous {} s", t, times.back()));
      times.push_back(t);
    }
    if (times.size() != count)
      fail(path, "/time", fmt::format("{} times for {} samples per blendshape", times.size(), count));
    return times;
  }
  float fps = options.sourceFps;
  if (root.contains("fps")) {
    fps = finiteNumber(root["fps"], path, "/fps");
    if (!(fps > 0.0f)) fail(path, "/fps", fmt::format("expected a number > 0, found {}", fps));
  }
  for (size_t i = 0; i < count; ++i) times.push_back(float(double(i) / fps));
  return times;
}

}  // namespace

PerformanceTrack readPerformanceJson(const std::filesystem::path& path, const std::vector<std::string>& validNames,
                                     const PerformanceCsvOptions& options) {
  const Json root = parseFile(path);
  if (!root.is_object()) fail(path, "/", "expected an object with 'weights' and 'fps' or 'time'");
  for (const auto& item : root.items())
    if (item.key() != "fps" && item.key() != "time" && item.key() != "weights")
      fail(path, "/" + item.key(), unknownNameMessage("key", item.key(), {"fps", "time", "weights"}));
  if (!root.contains("weights") || !root["weights"].is_object() || root["weights"].empty())
    fail(path, "/weights", "expected an object mapping blendshape names to arrays of weights");

  PerformanceTrack track;
  std::vector<std::vector<float>> channels;
  for (const auto& item : root["weights"].items()) {
    const std::string pointer = "/weights/" + item.key();
    const auto mapped = options.nameMap.find(item.key());
    const std::string name = mapped == options.nameMap.end() ? item.key() : mapped->second;
    if (std::find(validNames.begin(), validNames.end(), name) == validNames.end())
      fail(path, pointer, unknownNameMessage("blendshape", name, validNames));
    if (!item.value().is_array() || item.value().empty())
      fail(path, pointer, "expected a non-empty array of weights, found " + item.value().dump());
    std::vector<float>& samples = channels.emplace_back();
    for (size_t i = 0; i < item.value().size(); ++i)
      samples.push_back(finiteNumber(item.value()[i], path, fmt::format("{}/{}", pointer, i)));
    if (samples.size() != channels.front().size())
      fail(path, pointer, fmt::format("{} samples, but '{}' has {}", samples.size(), track.names.front(),
                                      channels.front().size()));
    track.names.push_back(name);
  }
  track.times = sampleTimes(root, channels.front().size(), path, options);
  for (size_t i = 0; i < track.times.size(); ++i) {
    std::vector<float>& frame = track.frames.emplace_back();
    for (const std::vector<float>& channel : channels) frame.push_back(channel[i]);
  }
  return track;
}

PerformanceTrack readPerformanceTrack(const std::filesystem::path& path, const std::vector<std::string>& validNames,
                                      const PerformanceCsvOptions& options) {
  return path.extension() == ".json" ? readPerformanceJson(path, validNames, options)
                                     : readPerformanceCsv(path, validNames, options);
}

}  // namespace lacrima
