// `lacrima diff A B`: compare two images, two directories or two frame sequences.
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "diff/diff_report.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima::cli {

namespace {

namespace fs = std::filesystem;
using namespace lacrima::diff;

// Two files: the output path as given. Directories or patterns: the directory given, one file
// per pair named after A's image (or B's when A's is missing): DIR/shot.0012.diff.exr.
std::string outputFor(const std::string& option, const ImagePair& pair, bool several, const char* suffix) {
  if (!several) return option;
  const fs::path source(pair.a ? *pair.a : *pair.b);
  return (fs::path(option) / (source.stem().string() + suffix)).string();
}

CompareOptions compareOptions(const DiffOptions& o) {
  CompareOptions c;
  c.thresholds = Thresholds{o.fail, o.failPercent, o.warn, o.warnPercent, o.maxMeanError};
  c.groups = o.aovs;
  c.flip = !o.noFlip || !o.flipOut.empty();
  c.ppd = o.ppd;
  return c;
}

}  // namespace

int runDiff(const DiffOptions& o) {
  try {
    const std::vector<ImagePair> pairs = pairImages(o.a, o.b);
    const CompareOptions options = compareOptions(o);
    std::error_code ec;
    const bool several = isFramePattern(o.a) || fs::is_directory(o.a, ec);
    std::vector<PairOutcome> outcomes;
    for (const ImagePair& pair : pairs) {
      outcomes.push_back(comparePair(pair, options, [&](const Image& a, const Image& b, const Comparison& c) {
        if (!o.out.empty()) writeDifferenceImage(outputFor(o.out, pair, several, ".diff.exr"), a, b, c);
        if (!o.flipOut.empty() && c.flip)
          writeFlipImage(outputFor(o.flipOut, pair, several, ".flip.png"), *c.flip, c.width, c.height);
      }));
      // An image that cannot be used ends a comparison of two files with just its message.
      if (!several && !outcomes.back().error.empty()) throw InputError(outcomes.back().error);
    }
    const Thresholds& t = options.thresholds;
    std::fputs((o.json ? formatJson(outcomes, t) : formatReport(outcomes, t)).c_str(), stdout);
    for (const PairOutcome& outcome : outcomes)
      if (!outcome.error.empty()) std::fprintf(stderr, "%s\n", outcome.error.c_str());
    return int(overallVerdict(outcomes));
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
