// Every fuzz target runs its inputs on one thread. libFuzzer runs one input at a time and counts
// its coverage in counters shared by all threads, which two threads writing at once contend for:
// the regression shot face_rivulet (a liquid tear's course welling from 3 s before the frame) took
// 13.9 s under the instrumented build with TBB's two threads and 7.5 s on one core (2026-12-06),
// so with two threads it passed the 10 s hang limit of tools/hardening.sh's fuzz stage.
#include <tbb/global_control.h>

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  static const tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
  return 0;
}
