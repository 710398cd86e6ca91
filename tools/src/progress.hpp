#pragma once
// Progress on stderr: one updating line per frame on a terminal, a line every 10% otherwise,
// and one summary line per frame. Each progress line also tells where the whole sequence is.
#include <chrono>
#include <string>

#include "lacrima/renderer/render.hpp"

namespace lacrima::cli {

// The sequence around the frame being rendered, for the overall part of the progress line.
struct SequenceProgress {
  int framesDone = 0;           // rendered, skipped (--resume) or failed so far
  int framesTotal = 0;          // every frame of this run, skipped ones included
  int framesToRenderAfter = 0;  // frames still to render after this one
  double meanFrameSeconds = 0;  // over the frames rendered so far in this run; 0: none yet
};

class ProgressReporter {
 public:
  ProgressReporter(int frame, int frameIndex, int frameCount, const SequenceProgress& sequence, bool quiet);
  void update(const RenderProgress& progress);
  void finish();

 private:
  int frame_, frameIndex_, frameCount_;
  SequenceProgress sequence_;
  bool quiet_, terminal_;
  int lastDecile_ = -1;
  std::chrono::steady_clock::time_point lastPrint_;
};

std::string formatDuration(double seconds);
std::string formatRate(double perSecond);  // "12.3 M"

// Seconds until the sequence is done: the rest of this frame, then the frames after it at the
// mean frame time so far (or at this frame's projected time while no frame has finished).
double sequenceEta(const SequenceProgress& sequence, double frameElapsed, double frameFraction);

}  // namespace lacrima::cli
