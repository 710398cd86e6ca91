// thresholds.json of `lacrima test-suite`; see suite_thresholds.hpp.
#include "diff/suite_thresholds.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "lacrima/base/error.hpp"

namespace lacrima::diff {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& file, const std::string& where, const std::string& problem) {
  throw InputError(fmt::format("{}: {}: {}", file, where, problem));
}

double nonNegative(const json& value, const std::string& file, const std::string& where) {
  if (!value.is_number() || value.get<double>() < 0.0)
    fail(file, where, fmt::format("expected a number >= 0, found {}", value.dump()));
  return value.get<double>();
}

// Applies the keys of `entry` over `base`.
ShotThresholds readEntry(const json& entry, ShotThresholds base, const std::string& file, const std::string& where) {
  if (!entry.is_object()) fail(file, where, fmt::format("expected an object, found {}", entry.dump()));
  Thresholds& t = base.thresholds;
  const bool warnGiven = entry.contains("warn"), warnPercentGiven = entry.contains("warnpercent");
  for (const auto& [key, value] : entry.items()) {
    const std::string at = where + "/" + key;
    if (key == "fail") t.fail = nonNegative(value, file, at);
    else if (key == "failpercent") t.failPercent = nonNegative(value, file, at);
    else if (key == "warn") t.warn = nonNegative(value, file, at);
    else if (key == "warnpercent") t.warnPercent = nonNegative(value, file, at);
    else if (key == "maxmean") t.maxMeanError = nonNegative(value, file, at);
    else if (key == "aovs") {
      if (!value.is_array() || value.empty()) fail(file, at, "expected a non-empty list of channel group names");
      base.aovs.clear();
      for (const json& name : value) {
        if (!name.is_string()) fail(file, at, fmt::format("expected a channel group name, found {}", name.dump()));
        base.aovs.push_back(name.get<std::string>());
      }
    } else {
      fail(file, at, "unknown key (expected fail, failpercent, warn, warnpercent, maxmean or aovs)");
    }
  }
  if (!warnGiven) t.warn = t.fail / 10.0;
  if (!warnPercentGiven) t.warnPercent = t.failPercent;
  return base;
}

}  // namespace

const ShotThresholds& SuiteThresholds::forShot(const std::string& name) const {
  const auto it = shots.find(name);
  return it == shots.end() ? defaults : it->second;
}

ShotThresholds defaultSuiteThresholds() {
  ShotThresholds s;
  s.thresholds = Thresholds{0.05, 0.5, 0.005, 0.5, 0.002};
  s.aovs = {"beauty"};
  return s;
}

SuiteThresholds loadSuiteThresholds(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open", path));
  json root;
  try {
    root = json::parse(in, nullptr, true, /*ignore_comments=*/true);
  } catch (const json::parse_error& e) {
    throw InputError(fmt::format("{}: invalid JSON: {}", path, e.what()));
  }
  if (!root.is_object()) fail(path, "/", "expected an object with \"default\" and \"shots\"");
  SuiteThresholds suite;
  suite.defaults = defaultSuiteThresholds();
  for (const auto& [key, value] : root.items())
    if (key != "default" && key != "shots") fail(path, "/" + key, "unknown key (expected default or shots)");
  if (root.contains("default")) suite.defaults = readEntry(root["default"], suite.defaults, path, "/default");
  if (root.contains("shots")) {
    if (!root["shots"].is_object()) fail(path, "/shots", "expected an object of shot name -> thresholds");
    for (const auto& [name, entry] : root["shots"].items())
      suite.shots[name] = readEntry(entry, suite.defaults, path, "/shots/" + name);
  }
  return suite;
}

}  // namespace lacrima::diff
