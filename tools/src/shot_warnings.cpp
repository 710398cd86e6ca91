// Shot warnings on stderr, for `lacrima render` and `lacrima check`.
#include <cstdio>

#include "commands.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::cli {

void printShotWarnings(const Shot& shot) {
  // The scenes library starts each message with "warning: ", so format() reads like a compiler
  // warning: "file:line:column: /json/pointer: warning: what". Added here if a message lacks it.
  for (Diagnostic warning : shot.warnings) {
    if (warning.message.rfind("warning: ", 0) != 0) warning.message = "warning: " + warning.message;
    std::fprintf(stderr, "%s\n", warning.format().c_str());
  }
}

}  // namespace lacrima::cli
