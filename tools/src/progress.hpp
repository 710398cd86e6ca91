#pragma once
// Progress on stderr: one updating line per frame on a terminal, a line every 10% otherwise,
// and one summary line per frame.
#include <chrono>
#include <string>

#include "lacrima/renderer/render.hpp"

namespace lacrima::cli {

class ProgressReporter {
 public:
  ProgressReporter(int frame, int frameIndex, int frameCount, bool quiet);
  void update(const RenderProgress& progress);
  void finish();

 private:
  int frame_, frameIndex_, frameCount_;
  bool quiet_, terminal_;
  int lastDecile_ = -1;
  std::chrono::steady_clock::time_point lastPrint_;
};

std::string formatDuration(double seconds);
std::string formatRate(double perSecond);  // "12.3 M"

}  // namespace lacrima::cli
