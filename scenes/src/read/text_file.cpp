// Whole text files; see text_file.hpp.
#include "read/text_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "lacrima/scenes/shot.hpp"

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

ParsedJsonFile readJsonFile(const std::filesystem::path& path, const char* what) {
  std::string readError;
  auto text = readTextFile(path, what, readError);
  if (!text) throw ShotError({Diagnostic{path, "", 0, 0, readError}});
  JsonSource source(std::move(*text));
  auto json = source.parse();
  if (!json) {
    const TextPosition p = source.positionOf(source.syntaxErrorOffset());
    throw ShotError({Diagnostic{path, "", p.line, p.column,
                                "JSON syntax error: " + source.syntaxError() + "\n" + source.excerpt(p)}});
  }
  return {std::move(source), std::move(*json)};
}

}  // namespace lacrima::shotfile
