#pragma once
// The pass/warn/fail thresholds of a regression directory for `lacrima test-suite`, kept in
// <directory>/thresholds.json next to the shots:
//   {"default": {"fail": 0.05, "failpercent": 0.5, "maxmean": 0.002, "aovs": ["beauty"]},
//    "shots": {"water_sphere_furnace": {"fail": 0.01, "failpercent": 0.1, "maxmean": 1e-4}}}
// A shot's entry overrides the default's keys; warn defaults to fail / 10 and warnpercent to
// failpercent. Without the file every shot gets kDefaultSuiteThresholds.
#include <map>
#include <string>
#include <vector>

#include "diff/image_diff.hpp"

namespace lacrima::diff {

struct ShotThresholds {
  Thresholds thresholds;
  std::vector<std::string> aovs;  // channel groups compared
};

struct SuiteThresholds {
  ShotThresholds defaults;
  std::map<std::string, ShotThresholds> shots;

  const ShotThresholds& forShot(const std::string& name) const;
};

// fail 0.05, 0.5 % of the pixels, mean error 0.002, the beauty only (depth AOVs hold infinities
// on background pixels, and the beauty is what the references exist for).
ShotThresholds defaultSuiteThresholds();

// Reads `path`; throws InputError "<path>: <JSON path>: <problem>" for a bad file.
SuiteThresholds loadSuiteThresholds(const std::string& path);

}  // namespace lacrima::diff
