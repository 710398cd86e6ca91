// Tables and JSON for `lacrima diff`; see diff_report.hpp.
#include "diff/diff_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "lacrima/base/error.hpp"

namespace lacrima::diff {

namespace {

std::string joinedChannels(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

std::string psnrText(double psnr) { return std::isinf(psnr) ? "inf" : fmt::format("{:.2f}", psnr); }

std::string flipLine(const FlipResult& f) {
  const std::string mode = f.highDynamicRange ? fmt::format("HDR-FLIP, exposures {:.4f} to {:.4f} ({} stops)",
                                                            f.startExposure, f.stopExposure, f.exposures)
                                              : std::string("LDR-FLIP");
  return fmt::format("  FLIP      mean {:.6f}, max {:.6f} at ({}, {})   [{}, {:.2f} pixels per degree]\n", f.mean, f.max,
                     f.maxX, f.maxY, mode, f.ppd);
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json groupJson(const GroupMetrics& g) {
  return {{"name", g.name},           {"channels", g.channels},       {"meanError", g.meanError},
          {"rmsError", number(g.rmsError)}, {"maxError", number(g.maxError)}, {"maxPixel", {g.maxX, g.maxY}},
          {"maxChannel", g.maxChannel}, {"psnr", number(g.psnr)},     {"failPixels", g.failPixels},
          {"failPercent", g.failPercent}, {"warnPixels", g.warnPixels}, {"warnPercent", g.warnPercent},
          {"verdict", verdictName(g.verdict)}, {"reasons", g.reasons}};
}

nlohmann::json pairJson(const PairOutcome& o) {
  nlohmann::json j = {{"label", o.pair.label},
                      {"a", o.pair.a ? nlohmann::json(*o.pair.a) : nlohmann::json(nullptr)},
                      {"b", o.pair.b ? nlohmann::json(*o.pair.b) : nlohmann::json(nullptr)},
                      {"status", o.status()},
                      {"verdict", verdictName(o.verdict)}};
  if (!o.error.empty()) j["error"] = o.error;
  if (!o.comparison) return j;
  const Comparison& c = *o.comparison;
  j["width"] = c.width;
  j["height"] = c.height;
  j["groups"] = nlohmann::json::array();
  for (const GroupMetrics& g : c.groups) j["groups"].push_back(groupJson(g));
  if (c.flip) {
    const FlipResult& f = *c.flip;
    j["flip"] = {{"mean", f.mean}, {"max", f.max}, {"maxPixel", {f.maxX, f.maxY}}, {"hdr", f.highDynamicRange},
                 {"ppd", f.ppd}};
    if (f.highDynamicRange) {
      j["flip"]["startExposure"] = f.startExposure;
      j["flip"]["stopExposure"] = f.stopExposure;
      j["flip"]["exposures"] = f.exposures;
    }
  }
  return j;
}

}  // namespace

std::string PairOutcome::status() const {
  if (!error.empty()) return "error";
  if (!pair.a) return "missing in A";
  if (!pair.b) return "missing in B";
  return verdict == Verdict::Pass ? "pass" : verdict == Verdict::Warn ? "warn" : "fail";
}

PairOutcome comparePair(const ImagePair& pair, const CompareOptions& options, const ComparedHook& onCompared) {
  PairOutcome outcome;
  outcome.pair = pair;
  if (!pair.a || !pair.b) {
    outcome.verdict = Verdict::Fail;
    return outcome;
  }
  try {
    const Image a = readImage(*pair.a), b = readImage(*pair.b);
    outcome.comparison = compareImages(a, b, options);
    outcome.verdict = outcome.comparison->verdict;
    if (onCompared) onCompared(a, b, *outcome.comparison);
  } catch (const InputError& e) {
    outcome.error = e.what();
    outcome.verdict = Verdict::Fail;
  }
  return outcome;
}

Verdict overallVerdict(const std::vector<PairOutcome>& outcomes) {
  Verdict v = Verdict::Pass;
  for (const PairOutcome& o : outcomes) v = worst(v, o.verdict);
  return v;
}

bool anyError(const std::vector<PairOutcome>& outcomes) {
  for (const PairOutcome& o : outcomes)
    if (!o.error.empty()) return true;
  return false;
}

std::string formatComparison(const Comparison& c) {
  std::string out = fmt::format("{} vs {}: {} x {}\n", c.pathA, c.pathB, c.width, c.height);
  out += fmt::format("  {:<9} {:<26} {:>11} {:>11} {:>11}  {:<18} {:>8} {:>18} {:>18}\n", "group", "channels",
                     "mean err", "RMS", "max err", "at (x, y) channel", "PSNR dB", "> fail", "> warn");
  for (const GroupMetrics& g : c.groups) {
    const std::string where = g.maxError > 0 ? fmt::format("({}, {}) {}", g.maxX, g.maxY, g.maxChannel) : "-";
    out += fmt::format("  {:<9} {:<26} {:>11.4g} {:>11.4g} {:>11.4g}  {:<18} {:>8} {:>18} {:>18}\n", g.name,
                       joinedChannels(g.channels), g.meanError, g.rmsError, g.maxError, where, psnrText(g.psnr),
                       fmt::format("{} ({:.3g}%)", g.failPixels, g.failPercent),
                       fmt::format("{} ({:.3g}%)", g.warnPixels, g.warnPercent));
  }
  if (c.flip) out += flipLine(*c.flip);
  for (const GroupMetrics& g : c.groups)
    for (const std::string& r : g.reasons) out += fmt::format("  {}: {}\n", verdictName(g.verdict), r);
  return out;
}

std::string formatReport(const std::vector<PairOutcome>& outcomes, const Thresholds& t) {
  std::string out;
  std::vector<std::string> missingA, missingB, failed, warned, errors;
  for (const PairOutcome& o : outcomes) {
    if (o.comparison) out += formatComparison(*o.comparison) + fmt::format("  {}\n", verdictName(o.verdict));
    if (!o.error.empty()) {
      out += fmt::format("{}: ERROR: {}\n", o.pair.label, o.error);
      errors.push_back(o.pair.label);
    } else if (!o.pair.a) {
      out += fmt::format("{}: FAIL: missing in A ({} has it)\n", o.pair.label, *o.pair.b);
      missingA.push_back(o.pair.label);
    } else if (!o.pair.b) {
      out += fmt::format("{}: FAIL: missing in B ({} has it)\n", o.pair.label, *o.pair.a);
      missingB.push_back(o.pair.label);
    } else if (o.verdict == Verdict::Fail) {
      failed.push_back(o.pair.label);
    } else if (o.verdict == Verdict::Warn) {
      warned.push_back(o.pair.label);
    }
  }
  auto list = [](const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
  };
  out += fmt::format("thresholds: fail {} (allowed {}%), warn {} (allowed {}%){}\n", t.fail, t.failPercent, t.warn,
                     t.warnPercent, t.maxMeanError ? fmt::format(", mean error <= {}", *t.maxMeanError) : "");
  if (outcomes.size() > 1) {
    out += fmt::format("{} pairs: {} failed, {} warned, {} missing in A, {} missing in B, {} errors\n", outcomes.size(),
                       failed.size(), warned.size(), missingA.size(), missingB.size(), errors.size());
    if (!failed.empty()) out += "  failed: " + list(failed) + "\n";
    if (!warned.empty()) out += "  warned: " + list(warned) + "\n";
    if (!missingA.empty()) out += "  missing in A: " + list(missingA) + "\n";
    if (!missingB.empty()) out += "  missing in B: " + list(missingB) + "\n";
    if (!errors.empty()) out += "  errors: " + list(errors) + "\n";
  }
  out += fmt::format("{}\n", anyError(outcomes) ? "ERROR" : verdictName(overallVerdict(outcomes)));
  return out;
}

std::string formatJson(const std::vector<PairOutcome>& outcomes, const Thresholds& t) {
  nlohmann::json j;
  const Verdict v = overallVerdict(outcomes);
  j["verdict"] = anyError(outcomes) ? "ERROR" : verdictName(v);
  j["exitStatus"] = int(v);
  j["thresholds"] = {{"fail", t.fail}, {"failPercent", t.failPercent}, {"warn", t.warn}, {"warnPercent", t.warnPercent}};
  if (t.maxMeanError) j["thresholds"]["maxMeanError"] = *t.maxMeanError;
  j["pairs"] = nlohmann::json::array();
  for (const PairOutcome& o : outcomes) j["pairs"].push_back(pairJson(o));
  return j.dump(2) + "\n";
}

}  // namespace lacrima::diff
