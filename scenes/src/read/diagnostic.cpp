// Diagnostic formatting and ShotError.
#include <fmt/format.h>

#include "lacrima/scenes/shot.hpp"

namespace lacrima {

namespace {

std::string joinDiagnostics(const std::vector<Diagnostic>& diagnostics) {
  std::string out;
  for (size_t i = 0; i < diagnostics.size(); ++i) {
    if (i > 0) out += '\n';
    out += diagnostics[i].format();
  }
  return out;
}

}  // namespace

std::string Diagnostic::format() const {
  std::string out = file.string();
  if (line > 0) {
    out += fmt::format(":{}", line);
    if (column > 0) out += fmt::format(":{}", column);
  }
  out += ": ";
  if (!jsonPath.empty()) out += jsonPath + ": ";
  return out + message;
}

ShotError::ShotError(std::vector<Diagnostic> diagnostics)
    : InputError(joinDiagnostics(diagnostics)), diagnostics_(std::move(diagnostics)) {}

}  // namespace lacrima
