// Files lacrima finds by default: the OCIO config and the default shot of the source tree it was
// built from (LACRIMA_SOURCE_DIR), overridable with $LACRIMA_OCIO_CONFIG.
#include <cstdlib>

#include "commands.hpp"

namespace lacrima::cli {

std::string defaultOcioConfig() {
  if (const char* fromEnvironment = std::getenv("LACRIMA_OCIO_CONFIG")) return fromEnvironment;
  return std::string(LACRIMA_SOURCE_DIR) + "/scenes/ocio/config.ocio";
}

std::string defaultShot() { return std::string(LACRIMA_SOURCE_DIR) + "/scenes/shots/tear_closeup.json"; }

}  // namespace lacrima::cli
