#include "memory_usage.hpp"

#include "lacrima/base/allocator_tuning.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

namespace lacrima::cli {

namespace {

// The value in kB of a "Name:   1234 kB" line of /proc/self/status, or -1 when absent.
double statusKiloBytes(const std::string& status, const std::string& name) {
  std::istringstream lines(status);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(name + ":", 0) == 0) return std::stod(line.substr(name.size() + 1));
  return -1;
}

constexpr double kBytesPerMiB = 1024.0 * 1024.0;

void addHeapUsage(MemoryUsage& usage) {
#if defined(__GLIBC__)
  const struct mallinfo2 info = mallinfo2();
  usage.heapInUseMiB = double(info.uordblks + info.hblkhd) / kBytesPerMiB;  // allocated chunks + mmapped blocks
  usage.heapHeldMiB = double(info.arena + info.hblkhd) / kBytesPerMiB;      // from the OS: arenas + mmapped blocks
#else
  (void)usage;
#endif
}

}  // namespace

MemoryUsage currentMemoryUsage() {
  std::ifstream file("/proc/self/status");
  const std::string status((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  MemoryUsage usage;
  const double peak = statusKiloBytes(status, "VmHWM"), resident = statusKiloBytes(status, "VmRSS");
  if (peak >= 0) {
    usage.peakMiB = peak / 1024.0;
    usage.residentMiB = std::max(resident, 0.0) / 1024.0;
    addHeapUsage(usage);
    return usage;
  }
  rusage self{};
  getrusage(RUSAGE_SELF, &self);
  usage.peakMiB = double(self.ru_maxrss) / 1024.0;  // kB on Linux
  addHeapUsage(usage);
  return usage;
}

void releaseFreeHeapMemory() {
  returnFreedMemoryPromptly();
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

std::string formatMemoryUsage(const MemoryUsage& usage) {
  std::string text = fmt::format("peak RSS {:.1f} MiB, RSS {:.1f} MiB", usage.peakMiB, usage.residentMiB);
  if (usage.heapInUseMiB >= 0)
    text += fmt::format(", heap {:.1f} MiB in use of {:.1f} MiB", usage.heapInUseMiB, usage.heapHeldMiB);
  return text;
}

}  // namespace lacrima::cli
