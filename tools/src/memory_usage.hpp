#pragma once
// The process's own memory use, for `lacrima render --report-memory`: a per-frame leak shows as a
// peak that keeps growing over a long sequence (tools/hardening.sh, docs/hardening.md).
#include <string>

namespace lacrima::cli {

struct MemoryUsage {
  double peakMiB = 0;      // VmHWM: the highest resident set size so far
  double residentMiB = 0;  // VmRSS: the resident set size now
};

// From /proc/self/status (Linux); the peak falls back to getrusage's ru_maxrss elsewhere, with
// residentMiB left at 0.
MemoryUsage currentMemoryUsage();

// "peak RSS 123.4 MiB, RSS 120.1 MiB"
std::string formatMemoryUsage(const MemoryUsage& usage);

}  // namespace lacrima::cli
