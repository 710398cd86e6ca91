#pragma once
// Direct-light sampling for next-event estimation: area lights (rectangles, spheres) and the
// environment. A light is chosen uniformly; pdf() returns the same density a BSDF-sampled ray
// that reaches the light would have had, for multiple importance sampling.
#include <vector>

#include "lacrima/renderer/environment.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct LightSample {
  Vec3 direction;      // from the shading point towards the light, unit
  float distance = 0;  // to the light surface (infinity for the environment)
  Color radiance = Color::Zero();
  float pdf = 0.0f;    // solid angle, including the light selection probability
  Vec3 normal = Vec3::Zero();  // the light surface's unit normal at the sampled point (area lights)
  int lightIndex = -1;         // the area light sampled; -1 for the environment
};

class LightSampler {
 public:
  explicit LightSampler(const Frame& frame);

  bool empty() const { return lightCount_ == 0; }
  LightSample sample(const Vec3& point, float uSelect, const Vec2& u) const;

  // Density of sampling direction towards area light `index` hit at `lightPoint` (normal
  // `lightNormal`) from `point`.
  float pdfAreaLight(int index, const Vec3& point, const Vec3& lightPoint, const Vec3& lightNormal) const;
  // True when next-event estimation samples the background (an environment map, not a uniform colour).
  bool environmentIsSampled() const { return environment_ != nullptr; }

  // Radiance leaving area light `index` towards `towardsViewer`.
  Color emitted(int index, const Vec3& towardsViewer) const;
  // Background radiance for rays that escape.
  Color background(const Vec3& direction) const;
  // background(direction) and the density of sampling that direction, in one lookup of the map.
  struct Background {
    Color radiance;
    float pdf = 0.0f;
  };
  Background backgroundWithPdf(const Vec3& direction) const;

 private:
  LightSample sampleRectangle(const AreaLight& light, const Vec3& point, const Vec2& u) const;
  LightSample sampleSphere(const AreaLight& light, const Vec3& point, const Vec2& u) const;

  const std::vector<AreaLight>& lights_;
  const EnvironmentMap* environment_;
  Color uniformBackground_;
  int lightCount_ = 0;  // area lights + environment
  float selectPdf_ = 0.0f;
};

}  // namespace lacrima
