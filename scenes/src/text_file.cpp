// Whole text files; see text_file.hpp.
#include "text_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace lacrima::shotfile {

std::optional<std::string> readTextFile(const std::filesystem::path& path, const char* what, std::string& error) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    error = fmt::format("cannot read {}: it is a directory", what);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = fmt::format("cannot read {}: {}", what, std::strerror(errno));
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    error = fmt::format("cannot read {}: read error", what);
    return std::nullopt;
  }
  return text.str();
}

}  // namespace lacrima::shotfile
