#include "light_sampler.hpp"

#include <limits>

namespace lacrima {

namespace {

float rectangleArea(const AreaLight& light) { return light.edgeU.cross(light.edgeV).norm(); }
Vec3 rectangleNormal(const AreaLight& light) { return light.edgeU.cross(light.edgeV).normalized(); }

// Solid angle subtended by a sphere seen from outside: 2 pi (1 - cos theta_max).
// (pbrt-v4 Sphere::Sample(ctx), section 6.2.4). Returns 0 inside the sphere.
float sphereConeOneMinusCos(const Vec3& center, float radius, const Vec3& point) {
  const float distance2 = (center - point).squaredNorm();
  const float radius2 = radius * radius;
  if (distance2 <= radius2) return 0.0f;
  const float sin2 = radius2 / distance2;
  const float cosMax = safeSqrt(1.0f - sin2);
  return sin2 / (1.0f + cosMax);  // 1 - cos, without cancellation for small spheres
}

// Distance along `direction` from `origin` to the first intersection with a sphere, or -1.
float raySphereDistance(const Vec3& origin, const Vec3& direction, const Vec3& center, float radius) {
  const Vec3 oc = origin - center;
  const float b = oc.dot(direction);
  // Numerically stable discriminant (Haines et al., Ray Tracing Gems ch. 7).
  const Vec3 f = oc - b * direction;
  const float disc = radius * radius - f.squaredNorm();
  if (disc < 0.0f) return -1.0f;
  const float q = -b - std::copysign(std::sqrt(disc), b);
  const float c = oc.squaredNorm() - radius * radius;
  float t0 = c / q, t1 = q;
  if (t0 > t1) std::swap(t0, t1);
  return t0 > 0.0f ? t0 : t1;
}

}  // namespace

LightSampler::LightSampler(const Frame& frame)
    : lights_(frame.lights), environment_(frame.environment.get()), uniformBackground_(frame.uniformBackground) {
  lightCount_ = int(lights_.size()) + (environment_ ? 1 : 0);
  selectPdf_ = lightCount_ > 0 ? 1.0f / float(lightCount_) : 0.0f;
}

LightSample LightSampler::sample(const Vec3& point, float uSelect, const Vec2& u) const {
  if (lightCount_ == 0) return {};
  const int chosen = std::min(int(uSelect * float(lightCount_)), lightCount_ - 1);
  LightSample s;
  if (chosen < int(lights_.size())) {
    const AreaLight& light = lights_[chosen];
    s = light.shape == AreaLight::Shape::Rectangle ? sampleRectangle(light, point, u) : sampleSphere(light, point, u);
    s.lightIndex = chosen;
  } else {
    const EnvironmentSample e = environment_->sample(u);
    s.direction = e.direction;
    s.distance = std::numeric_limits<float>::infinity();
    s.radiance = e.radiance;
    s.pdf = e.pdf;
  }
  s.pdf *= selectPdf_;
  return s;
}

LightSample LightSampler::sampleRectangle(const AreaLight& light, const Vec3& point, const Vec2& u) const {
  // Uniform by area, converted to solid angle: pdf = d^2 / (|cos theta_light| A).
  const Vec3 onLight = light.center + (u.x() - 0.5f) * light.edgeU + (u.y() - 0.5f) * light.edgeV;
  Vec3 toLight = onLight - point;
  const float distance2 = toLight.squaredNorm();
  const float distance = std::sqrt(distance2);
  if (distance <= 0.0f) return {};
  toLight /= distance;
  const Vec3 normal = rectangleNormal(light);
  const float cosLight = -normal.dot(toLight);
  if (cosLight <= 0.0f && !light.twoSided) return {};
  const float absCos = std::abs(cosLight);
  if (absCos < 1e-7f) return {};
  LightSample s;
  s.direction = toLight;
  s.distance = distance;
  s.radiance = light.radiance;
  s.pdf = distance2 / (absCos * rectangleArea(light));
  s.normal = normal;
  return s;
}

LightSample LightSampler::sampleSphere(const AreaLight& light, const Vec3& point, const Vec2& u) const {
  // Uniform in the cone of directions that see the sphere (pbrt-v4 Sphere::Sample(ctx)).
  const float oneMinusCos = sphereConeOneMinusCos(light.center, light.radius, point);
  if (oneMinusCos <= 0.0f) return {};
  const Vec3 axis = (light.center - point).normalized();
  const float cosTheta = 1.0f - u.x() * oneMinusCos;
  const float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
  const float phi = 2.0f * kPi * u.y();
  const ShadingFrame frame = ShadingFrame::fromNormal(axis);
  const Vec3 direction = frame.toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta)).normalized();
  float distance = raySphereDistance(point, direction, light.center, light.radius);
  if (distance <= 0.0f) {
    // Grazing the silhouette in float precision: use the tangent distance.
    distance = std::sqrt(std::max(0.0f, (light.center - point).squaredNorm() - light.radius * light.radius));
  }
  LightSample s;
  s.direction = direction;
  s.distance = distance;
  s.radiance = light.radiance;
  s.pdf = 1.0f / (2.0f * kPi * oneMinusCos);
  s.normal = (point + distance * direction - light.center).normalized();
  return s;
}

float LightSampler::pdfAreaLight(int index, const Vec3& point, const Vec3& lightPoint, const Vec3& lightNormal) const {
  const AreaLight& light = lights_[index];
  if (light.shape == AreaLight::Shape::Sphere) {
    const float oneMinusCos = sphereConeOneMinusCos(light.center, light.radius, point);
    return oneMinusCos > 0.0f ? selectPdf_ / (2.0f * kPi * oneMinusCos) : 0.0f;
  }
  const Vec3 toLight = lightPoint - point;
  const float distance2 = toLight.squaredNorm();
  const float absCos = std::abs(lightNormal.dot(toLight)) / std::sqrt(distance2);
  if (absCos < 1e-7f) return 0.0f;
  return selectPdf_ * distance2 / (absCos * rectangleArea(light));
}

Color LightSampler::emitted(int index, const Vec3& towardsViewer) const {
  const AreaLight& light = lights_[index];
  // The emitting side is defined by the light's edges, not by the triangle winding.
  if (light.shape == AreaLight::Shape::Rectangle && !light.twoSided && rectangleNormal(light).dot(towardsViewer) <= 0.0f)
    return Color::Zero();
  return light.radiance;
}

Color LightSampler::background(const Vec3& direction) const {
  return environment_ ? environment_->radiance(direction) : uniformBackground_;
}

LightSampler::Background LightSampler::backgroundWithPdf(const Vec3& direction) const {
  if (!environment_) return {uniformBackground_, 0.0f};
  const EnvironmentSample e = environment_->lookup(direction);
  return {e.radiance, selectPdf_ * e.pdf};
}

}  // namespace lacrima
