#include "memory_usage.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

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

}  // namespace

MemoryUsage currentMemoryUsage() {
  std::ifstream file("/proc/self/status");
  const std::string status((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  MemoryUsage usage;
  const double peak = statusKiloBytes(status, "VmHWM"), resident = statusKiloBytes(status, "VmRSS");
  if (peak >= 0) {
    usage.peakMiB = peak / 1024.0;
    usage.residentMiB = std::max(resident, 0.0) / 1024.0;
    return usage;
  }
  rusage self{};
  getrusage(RUSAGE_SELF, &self);
  usage.peakMiB = double(self.ru_maxrss) / 1024.0;  // kB on Linux
  return usage;
}

std::string formatMemoryUsage(const MemoryUsage& usage) {
  return fmt::format("peak RSS {:.1f} MiB, RSS {:.1f} MiB", usage.peakMiB, usage.residentMiB);
}

}  // namespace lacrima::cli
