#include "atomic_write.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "lacrima/base/error.hpp"

namespace lacrima::cli {

namespace fs = std::filesystem;

namespace {

// Removes the temporary file unless it was renamed into place.
class TemporaryFile {
 public:
  explicit TemporaryFile(fs::path path) : path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    std::error_code ec;
    if (!kept_) fs::remove(path_, ec);
  }
  const fs::path& path() const { return path_; }
  void keep() { kept_ = true; }

 private:
  fs::path path_;
  bool kept_ = false;
};

}  // namespace

void writeFileAtomically(const fs::path& path, const char* what, const std::function<void(std::ostream&)>& write) {
  const auto fail = [&](const std::string& reason) {
    throw InputError(fmt::format("cannot write {} '{}': {}", what, path.string(), reason));
  };
  if (path.filename().empty()) fail("not a file name");
  if (const fs::path parent = path.parent_path(); !parent.empty()) {
    std::error_code ec;
    fs::create_directories(parent, ec);
    if (ec) fail(fmt::format("cannot create directory '{}': {}", parent.string(), ec.message()));
  }
  fs::path temporaryPath = path;
  temporaryPath += fmt::format(".tmp-{}", long(::getpid()));
  TemporaryFile temporary(temporaryPath);
  std::ofstream out(temporary.path(), std::ios::binary | std::ios::trunc);
  if (!out) fail(std::strerror(errno));
  write(out);
  out.close();
  if (!out) fail("write error (disk full?)");
  std::error_code ec;
  fs::rename(temporary.path(), path, ec);
  if (ec) fail(fmt::format("cannot rename the temporary file into place: {}", ec.message()));
  temporary.keep();
}

}  // namespace lacrima::cli
