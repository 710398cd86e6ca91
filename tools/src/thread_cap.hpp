#pragma once
// --threads caps all of a command's work: the shot's loading and each frame's geometry stage run
// on TBB's threads too, not only the path tracing (whose arena the renderer makes itself). On a farm
// node shared by several tasks, each with its CPUs, the whole command must stay within them.
#include <tbb/task_arena.h>

#include <utility>

namespace lacrima::cli {

// Runs `work` in a TBB arena of `threads` worker slots (0: all cores) and returns what it returns.
// The same results for any count: every parallel stage of lacrima computes each value in a fixed
// order.
template <typename Work>
decltype(auto) withThreadCap(int threads, Work&& work) {
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  return arena.execute(std::forward<Work>(work));
}

}  // namespace lacrima::cli
