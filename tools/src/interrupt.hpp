#pragma once
// Ctrl-C (SIGINT) and SIGTERM during `lacrima render`. The handler only sets atomic flags; the
// render loop reads them. The first signal asks to stop after the frame being rendered (it is
// still written, so no work is lost); the second abandons that frame at once (the renderer polls
// the flag between tiles, nothing is written); a third one kills the process the default way,
// for a render that does not react.
#include <atomic>

namespace lacrima::cli {

inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, what shells report for Ctrl-C

void installInterruptHandlers();
bool stopRequested();                        // at least one signal arrived
const std::atomic<bool>& abandonRequested();  // two or more: drop the current frame

}  // namespace lacrima::cli
