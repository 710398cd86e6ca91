// ShotReader (shot_reader.hpp): the section "environment" (docs/shot-format.md), its map loaded.
#include <fmt/format.h>

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
    env.file = resolve(*file);
    if (checkExists(o.at("file"), *file, env.file)) {
      try {
        env.map = std::make_shared<const EnvironmentMap>(
            EnvironmentMap::load(env.file, env.intensity, degreesToRadians(env.rotationDegrees)));
        if (const size_t clamped = env.map->clampedTexelCount())
          shot_.warnings.push_back(c_.warning(
              o.at("file"), Anchor::Value,
              fmt::format("{}: {} texel{} NaN, infinite or negative, set to 0", env.file.string(), clamped,
                          clamped == 1 ? " was" : "s were")));
      } catch (const std::exception& e) {
        o.error("file", fmt::format("cannot load the environment map: {}", e.what()));
      }
    }
  }
  shot_.environment = std::move(env);
}

}  // namespace lacrima::shotfile
