#pragma once
// The results of `lacrima diff` and `lacrima test-suite`: per pair of images a comparison, a
// missing side or an error, printed as a table for people or as JSON for machines.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "diff/image_diff.hpp"
#include "diff/image_pairs.hpp"

namespace lacrima::diff {

struct PairOutcome {
  ImagePair pair;
  std::optional<Comparison> comparison;  // none: a side is missing or an image could not be used
  std::string error;                     // the message when an image could not be read or compared
  Verdict verdict = Verdict::Pass;

  // "pass", "warn", "fail", "missing in A", "missing in B" or "error".
  std::string status() const;
};

// Reads and compares one pair; a missing side is a failure, an unusable image an error (both FAIL).
// `onCompared` (optional) sees both images and the comparison, e.g. to write difference images;
// an InputError it throws becomes the pair's error.
using ComparedHook = std::function<void(const Image& a, const Image& b, const Comparison& comparison)>;
PairOutcome comparePair(const ImagePair& pair, const CompareOptions& options, const ComparedHook& onCompared = {});

Verdict overallVerdict(const std::vector<PairOutcome>& outcomes);
bool anyError(const std::vector<PairOutcome>& outcomes);

// The table of one comparison: a line per channel group and one for FLIP, then the reasons.
std::string formatComparison(const Comparison& c);
// Every pair (the full table of each compared one) and an overall line with the missing frames.
std::string formatReport(const std::vector<PairOutcome>& outcomes, const Thresholds& thresholds);
std::string formatJson(const std::vector<PairOutcome>& outcomes, const Thresholds& thresholds);

}  // namespace lacrima::diff
