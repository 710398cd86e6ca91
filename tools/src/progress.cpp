#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace lacrima::cli {

std::string formatDuration(double seconds) {
  const long total = long(seconds + 0.5);
  if (total >= 3600) return fmt::format("{}:{:02}:{:02}", total / 3600, (total / 60) % 60, total % 60);
  return fmt::format("{}:{:02}", total / 60, total % 60);
}

std::string formatRate(double perSecond) {
  if (perSecond >= 1e6) return fmt::format("{:.2f} M", perSecond / 1e6);
  if (perSecond >= 1e3) return fmt::format("{:.1f} k", perSecond / 1e3);
  return fmt::format("{:.0f} ", perSecond);
}

double sequenceEta(const SequenceProgress& sequence, double frameElapsed, double frameFraction) {
  if (frameFraction <= 0) return 0.0;  // nothing to extrapolate from yet
  const double frameTotal = frameElapsed / frameFraction;
  const double perFrame = sequence.meanFrameSeconds > 0 ? sequence.meanFrameSeconds : frameTotal;
  return frameTotal - frameElapsed + perFrame * sequence.framesToRenderAfter;
}

ProgressReporter::ProgressReporter(int frame, int frameIndex, int frameCount, const SequenceProgress& sequence,
                                   bool quiet)
    : frame_(frame),
      frameIndex_(frameIndex),
      frameCount_(frameCount),
      sequence_(sequence),
      quiet_(quiet),
      terminal_(isatty(STDERR_FILENO)) {}

void ProgressReporter::update(const RenderProgress& p) {
  if (quiet_ || p.samplesTotal == 0) return;
  const double fraction = double(p.samplesDone) / double(p.samplesTotal);
  const int decile = int(fraction * 10.0);
  const auto now = std::chrono::steady_clock::now();
  if (terminal_) {
    if (p.samplesDone != p.samplesTotal && now - lastPrint_ < std::chrono::milliseconds(200)) return;
  } else if (decile == lastDecile_) {
    return;
  }
  lastDecile_ = decile;
  lastPrint_ = now;
  const double eta = fraction > 0 ? p.elapsedSeconds * (1.0 - fraction) / fraction : 0.0;
  const std::string line =
      fmt::format("frame {} [{}/{}] {:5.1f}%  {}rays/s  elapsed {}  ETA {}  | sequence {}/{} frames done, ETA {}",
                  frame_, frameIndex_ + 1, frameCount_, 100.0 * fraction,
                  formatRate(p.raysSoFar / std::max(p.elapsedSeconds, 1e-9)), formatDuration(p.elapsedSeconds),
                  formatDuration(eta), sequence_.framesDone, sequence_.framesTotal,
                  formatDuration(sequenceEta(sequence_, p.elapsedSeconds, fraction)));
  std::fprintf(stderr, terminal_ ? "\r%s\033[K" : "%s\n", line.c_str());
}

void ProgressReporter::finish() {
  if (!quiet_ && terminal_) std::fprintf(stderr, "\r\033[K");
}

}  // namespace lacrima::cli
