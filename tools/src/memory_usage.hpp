#pragma once
// The process's own memory use, for `lacrima render --report-memory`: a per-frame leak shows as a
// peak that keeps growing over a long sequence (tools/hardening.sh, docs/hardening.md); and the
// trim that keeps `lacrima render`'s memory flat from frame to frame.
#include <string>

namespace lacrima::cli {

struct MemoryUsage {
  double peakMiB = 0;      // VmHWM: the highest resident set size so far
  double residentMiB = 0;  // VmRSS: the resident set size now
  // malloc's own view (glibc's mallinfo2, all arenas; -1 elsewhere): the bytes the program holds,
  // and the bytes malloc holds for it, free chunks included. Held far above in use while the
  // program's own use stays flat is memory freed but not given back: fragmentation, not a leak.
  double heapInUseMiB = -1;
  double heapHeldMiB = -1;
};

// From /proc/self/status (Linux); the peak falls back to getrusage's ru_maxrss elsewhere, with
// residentMiB left at 0.
MemoryUsage currentMemoryUsage();

// Called after every frame of `render` and `export`: from then on the heap returns freed memory
// promptly (base/allocator_tuning.hpp: the first frame, with the shot's load and the
// simulation up to it, reused it), and the free pages inside the heap go back to the system
// (glibc's malloc_trim; nothing elsewhere), so what a frame freed does not add up over a sequence.
void releaseFreeHeapMemory();

// "peak RSS 123.4 MiB, RSS 120.1 MiB, heap 80.2 MiB in use of 95.0 MiB" (without the heap part
// where malloc cannot tell)
std::string formatMemoryUsage(const MemoryUsage& usage);

}  // namespace lacrima::cli
