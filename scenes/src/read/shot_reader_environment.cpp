// ShotReader (shot_reader.hpp): the section "environment" (docs/shot-format.md); the map
// is loaded with the other files (load/shot_files.cpp).
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

void ShotReader::readEnvironment(const Json& v) {
  ObjectReader o(c_, v, "/environment", {"file", "intensity", "rotation"});
  if (!o.ok()) return;
  ShotEnvironment env;
  const auto file = o.string("file", true);
  if (auto x = o.number("intensity", Range::atLeast(0))) env.intensity = float(*x);
  if (auto x = o.number("rotation", Range::any())) env.rotationDegrees = float(*x);
  if (file) {
    uses_.environmentMap = fileUse(o.at("file"), *file);
    env.file = uses_.environmentMap->resolved;
  }
  shot_.environment = std::move(env);
}

}  // namespace lacrima::shotfile
