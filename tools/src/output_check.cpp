#include "output_check.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "lacrima/base/error.hpp"

namespace lacrima::cli {

namespace fs = std::filesystem;

uint64_t estimatedFrameBytes(const RenderSettings& s, bool preview) {
  const uint64_t pixels = uint64_t(s.filmWidth()) * uint64_t(s.filmHeight());
  const uint64_t channels = 11 + (s.adaptive.enabled ? 1 : 0) + (s.denoise ? 3 : 0);
  // Further float layers: each Cryptomatte's ranks (2 channels a rank), light groups (3 a group,
  // about four groups a shot), light paths (3 each).
  const uint64_t floatLayers = uint64_t(s.cryptomatte.objects + s.cryptomatte.materials) * 2 * uint64_t(s.cryptomatte.ranks) +
                               (s.lightGroups ? 12 : 0) + 3 * uint64_t(std::popcount(s.lightPaths.bits));
  const uint64_t exr = (pixels * channels * (s.floatOutput ? 4 : 2) + pixels * floatLayers * 4) / 2;
  return exr + (preview ? pixels * 3 / 2 : 0);
}

namespace {

std::string formatBytes(uint64_t bytes) {
  if (bytes >= (uint64_t(1) << 30)) return fmt::format("{:.1f} GB", double(bytes) / double(uint64_t(1) << 30));
  if (bytes >= (uint64_t(1) << 20)) return fmt::format("{:.1f} MB", double(bytes) / double(uint64_t(1) << 20));
  return fmt::format("{:.0f} KB", double(bytes) / 1024.0);
}

// Creates and removes a file in `directory`: the only test that a render's writes will work
// (permissions, read-only mounts, ACLs, root squash on a network file system all show here).
void requireWritable(const fs::path& directory) {
  const fs::path probe = directory / fmt::format(".lacrima-write-test-{}", long(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
  if (fd < 0)
    throw InputError(fmt::format("output directory '{}' is not writable: {}", directory.string(), std::strerror(errno)));
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

std::string spaceProblem(const fs::path& directory, uint64_t available, uint64_t frameBytes) {
  if (available >= frameBytes) return "";
  return fmt::format("output directory '{}' has {} free, a frame needs about {}", directory.string(),
                     formatBytes(available), formatBytes(frameBytes));
}

void checkOutputDirectories(const std::vector<fs::path>& directories, uint64_t frameBytes, size_t frameCount) {
  for (const fs::path& directory : directories) {
    std::error_code ec;
    fs::create_directories(directory, ec);
    if (ec)
      throw InputError(fmt::format("output directory '{}' cannot be created: {}", directory.string(), ec.message()));
    requireWritable(directory);
    const fs::space_info space = fs::space(directory, ec);
    if (ec) continue;  // no answer (some network file systems): the writes will tell
    const std::string problem = spaceProblem(directory, space.available, frameBytes);
    if (!problem.empty()) throw InputError(problem);
    if (space.available < frameBytes * frameCount)
      std::fprintf(stderr, "lacrima: warning: output directory '%s' has %s free, %zu frames need about %s\n",
                   directory.c_str(), formatBytes(space.available).c_str(), frameCount,
                   formatBytes(frameBytes * frameCount).c_str());
  }
}

}  // namespace lacrima::cli
