#pragma once
// Equirectangular (latitude-longitude) environment map with importance sampling.
// Direction convention: world +Y is up; u = 0.5 looks along -Z... see environment.cpp header.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "lacrima/base/math.hpp"

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
  // radiance(direction) and pdf(direction) (bitwise), with one direction-to-cell lookup for both:
  // its two arc tangents are most of either's cost.
  EnvironmentSample lookup(const Vec3& direction) const;
  EnvironmentSample sample(const Vec2& u) const;

  int width() const { return width_; }
  int height() const { return height_; }
  // Texels whose value was non-finite or negative and was replaced by 0 (callers report it).
  std::size_t clampedTexelCount() const { return clampedTexels_; }

 private:
  // piecewise-constant 2D distribution (marginal over rows, conditional per row) over the cells
  // between texel centres, weighted by the bilinear radiance's mean luminance * solid angle; see
  // environment.cpp
  int width_ = 0, height_ = 0;
  std::vector<float> rgb_;
  float intensity_ = 1.0f;
  float rotation_ = 0.0f;
  std::vector<float> marginalCdf_;      // height + 2 (height + 1 cell rows)
  std::vector<float> conditionalCdf_;   // (height + 1) * (width + 1)
  std::vector<int> marginalGuide_;      // guide tables of the CDFs (distribution.hpp): height + 2
  std::vector<int> conditionalGuide_;   // (height + 1) * (width + 1)
  std::size_t clampedTexels_ = 0;

  // The cell between texel centres that holds (u, v) and the position in it: the bilinear
  // weights of its right (fx) and lower (fy) corners.
  struct Cell {
    int column = 0, row = 0;  // column in [0, width), row in [0, height]
    float fx = 0.0f, fy = 0.0f;
  };
  Cell cellAt(const Vec2& uv) const;
  Color radianceIn(const Cell& cell) const;
  float pdfIn(const Cell& cell, float sinTheta) const;
  static float sinPolarAngle(const Vec3& direction);
  Color texel(int i, int j) const;
  float texelLuminance(int i, int j) const;
  void buildDistribution();
  double cellRowTop(int r) const;
  double cellRowSolidAngleFactor(int r) const;

  Vec2 directionToUv(const Vec3& direction) const;
  Vec3 uvToDirection(const Vec2& uv) const;
};

}  // namespace lacrima
