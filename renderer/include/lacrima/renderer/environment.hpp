#pragma once
// Equirectangular (latitude-longitude) environment map with importance sampling.
// Direction convention: world +Y is up; u = 0.5 looks along -Z... see environment.cpp header.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "lacrima/geometry/math.hpp"

namespace lacrima {

struct EnvironmentSample {
  Vec3 direction;  // world space, unit, pointing away from the scene towards the map
  Color radiance;
  float pdf = 0.0f;  // solid-angle density
};

class EnvironmentMap {
 public:
  // pixels: width*height RGB triples, row 0 at the top (north pole, +Y).
  EnvironmentMap(int width, int height, std::vector<float> rgb, float intensity, float rotationRadians);

  // Loads an EXR/HDR through OpenImageIO. Throws InputError naming the file.
  static EnvironmentMap load(const std::filesystem::path& path, float intensity, float rotationRadians);

  Color radiance(const Vec3& direction) const;
  float pdf(const Vec3& direction) const;  // solid-angle density of sample()
  EnvironmentSample sample(const Vec2& u) const;

  int width() const { return width_; }
  int height() const { return height_; }
  // Texels whose value was non-finite or negative and was replaced by 0 (callers report it).
  std::size_t clampedTexelCount() const { return clampedTexels_; }

 private:
  // piecewise-constant 2D distribution (marginal over rows, conditional per row),
  // weighted by luminance * sin(theta); see environment.cpp
  int width_ = 0, height_ = 0;
  std::vector<float> rgb_;
  float intensity_ = 1.0f;
  float rotation_ = 0.0f;
  std::vector<float> marginalCdf_;      // height + 1
  std::vector<float> conditionalCdf_;   // height * (width + 1)
  std::vector<float> rowIntegral_;      // height
  float totalIntegral_ = 0.0f;
  std::size_t clampedTexels_ = 0;

  int texelIndex(const Vec2& uv) const;

  Vec2 directionToUv(const Vec3& direction) const;
  Vec3 uvToDirection(const Vec2& uv) const;
};

}  // namespace lacrima
