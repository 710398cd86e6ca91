// `lacrima test-suite DIR`: render every regression shot of DIR and compare it with its reference.
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "diff/diff_report.hpp"
#include "diff/suite_thresholds.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima::cli {

namespace {

namespace fs = std::filesystem;
using namespace lacrima::diff;

constexpr const char* kThresholdsFile = "thresholds.json";

// The shots of the directory (every *.json but thresholds.json), by name, sorted.
std::vector<std::string> shotNames(const fs::path& directory, const std::vector<std::string>& only) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) throw InputError(fmt::format("{}: no such directory", directory.string()));
  std::vector<std::string> names;
  for (const fs::directory_entry& e : fs::directory_iterator(directory))
    if (e.is_regular_file() && e.path().extension() == ".json" && e.path().filename() != kThresholdsFile)
      names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  if (only.empty()) {
    if (names.empty()) throw InputError(fmt::format("{}: no shot files (*.json)", directory.string()));
    return names;
  }
  for (const std::string& wanted : only)
    if (std::find(names.begin(), names.end(), wanted) == names.end())
      throw InputError(fmt::format("--shot {}: no shot {}.json in {}", wanted, wanted, directory.string()));
  return only;
}

SuiteThresholds thresholdsOf(const fs::path& directory) {
  const fs::path file = directory / kThresholdsFile;
  std::error_code ec;
  if (!fs::exists(file, ec)) return SuiteThresholds{defaultSuiteThresholds(), {}};
  SuiteThresholds suite = loadSuiteThresholds(file.string());
  std::vector<std::string> all = shotNames(directory, {});
  for (const auto& [name, entry] : suite.shots)
    if (std::find(all.begin(), all.end(), name) == all.end())
      throw InputError(fmt::format("{}: /shots/{}: no shot {}.json in {}", file.string(), name, name,
                                   directory.string()));
  return suite;
}

int renderShot(const fs::path& shot, const fs::path& exr, bool preview) {
  RenderOptions r;
  r.shotPath = shot.string();
  r.outputPattern = exr.string();
  r.quiet = true;
  r.preview = preview;
  return runRender(r);
}

// One line for a passing shot; the full table, the reasons and the saved images otherwise.
void report(const std::string& name, const PairOutcome& outcome, double failThreshold, const fs::path& out) {
  if (!outcome.comparison) {
    std::printf("%s: FAIL: %s\n", name.c_str(), outcome.error.c_str());
    return;
  }
  const Comparison& c = *outcome.comparison;
  const GroupMetrics& first = c.groups.front();
  const std::string flip = c.flip ? fmt::format("; FLIP mean {:.4f}", c.flip->mean) : "";
  std::printf("%s: %s  %s: mean error %.3g, max %.3g, %zu pixels over %g%s\n", name.c_str(),
              verdictName(outcome.verdict), first.name.c_str(), first.meanError, first.maxError, first.failPixels,
              failThreshold, flip.c_str());
  if (outcome.verdict == Verdict::Pass) return;
  std::fputs(formatComparison(c).c_str(), stdout);
  std::printf("  render, difference and FLIP images in %s\n", out.string().c_str());
}

}  // namespace

int runTestSuite(const TestSuiteOptions& o) {
  try {
    const auto start = std::chrono::steady_clock::now();
    const fs::path directory(o.directory);
    const std::vector<std::string> names = shotNames(directory, o.shots);
    const SuiteThresholds suite = thresholdsOf(directory);
    const fs::path references = o.references.empty() ? directory / ".." / "references" : fs::path(o.references);
    const fs::path out = o.out.empty() ? fs::temp_directory_path() / fmt::format("lacrima-test-suite-{}", getpid())
                                       : fs::path(o.out);
    fs::create_directories(o.update ? references : out);

    Verdict overall = Verdict::Pass;
    int counts[3] = {0, 0, 0};
    for (const std::string& name : names) {
      const fs::path shot = directory / (name + ".json");
      const fs::path reference = references / (name + ".exr");
      const fs::path rendered = o.update ? reference : out / (name + ".exr");
      const int status = renderShot(shot, rendered, o.update);
      if (status != kExitOk) {
        std::printf("%s: FAIL: the render failed (exit status %d)\n", name.c_str(), status);
        overall = Verdict::Fail;
        ++counts[2];
        continue;
      }
      if (o.update) {
        std::printf("%s: reference written: %s\n", name.c_str(), reference.string().c_str());
        continue;
      }
      const ShotThresholds& t = suite.forShot(name);
      CompareOptions options;
      options.thresholds = t.thresholds;
      options.groups = t.aovs;
      PairOutcome outcome;
      std::error_code ec;
      if (!fs::exists(reference, ec)) {
        outcome.error = fmt::format("no reference {}; create it with `lacrima test-suite {} --update`",
                                    reference.string(), o.directory);
        outcome.verdict = Verdict::Fail;
      } else {
        outcome = comparePair(ImagePair{name, reference.string(), rendered.string()}, options,
                              [&](const Image& a, const Image& b, const Comparison& c) {
                                if (c.verdict == Verdict::Pass) return;
                                writeDifferenceImage((out / (name + ".diff.exr")).string(), a, b, c);
                                if (c.flip) writeFlipImage((out / (name + ".flip.png")).string(), *c.flip, c.width, c.height);
                              });
      }
      report(name, outcome, t.thresholds.fail, out);
      std::fflush(stdout);  // in order with the renderer's lines on stderr
      overall = worst(overall, outcome.verdict);
      ++counts[int(outcome.verdict)];
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (o.update)
      std::printf("test-suite: %zu references rendered into %s in %.1f s\n", names.size(), references.string().c_str(),
                  seconds);
    else
      std::printf("test-suite: %zu shots: %d passed, %d warned, %d failed in %.1f s: %s\n", names.size(), counts[0],
                  counts[1], counts[2], seconds, verdictName(overall));
    return int(overall);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
