// GGX microfacet distribution; see microfacet.hpp for parameters and sources.
#include "lacrima/materials/microfacet.hpp"

#include <limits>

namespace lacrima {

float roughnessToAlpha(float roughness) {
  // alpha = roughness^2 (Burley 2012, "Specular D").
  return std::clamp(roughness * roughness, kMinAlpha, 1.0f);
}

GgxDistribution::GgxDistribution(float alpha) : alpha_(std::clamp(alpha, kMinAlpha, 1.0f)) {}

float GgxDistribution::D(const Vec3& wm) const {
  if (wm.z() <= 0.0f) return 0.0f;
  // D = alpha^2 / (pi (sin^2 + alpha^2 cos^2)^2): Walter 2007 eq. 33 multiplied through by cos^4
  // (finite at grazing wm). sin^2 = x^2 + y^2 rather than 1 - z^2 keeps its precision near the
  // pole, where narrow lobes (alpha ~ 1e-3) live.
  const float a2 = alpha_ * alpha_;
  const float sin2 = wm.x() * wm.x() + wm.y() * wm.y();
  const float cos2 = wm.z() * wm.z();
  const float denom = sin2 + a2 * cos2;
  return a2 / (kPi * denom * denom);
}

float GgxDistribution::lambda(const Vec3& w) const {
  const float cos2 = w.z() * w.z();
  if (cos2 <= 0.0f) return std::numeric_limits<float>::infinity();
  const float sin2 = w.x() * w.x() + w.y() * w.y();  // precise near the pole, see D()
  const float alpha2Tan2 = alpha_ * alpha_ * sin2 / cos2;
  // Lambda = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2 (Heitz 2014 eq. 72).
  return 0.5f * (std::sqrt(1.0f + alpha2Tan2) - 1.0f);
}

float GgxDistribution::G1(const Vec3& w) const {
  // G1 = 1 / (1 + Lambda) (Heitz 2014 eq. 43).
  return 1.0f / (1.0f + lambda(w));
}

float GgxDistribution::G(const Vec3& wo, const Vec3& wi) const {
  // Height-correlated Smith G2 (Heitz 2014 eq. 99).
  return 1.0f / (1.0f + lambda(wo) + lambda(wi));
}

float GgxDistribution::visibleD(const Vec3& w, const Vec3& wm) const {
  const float cosW = std::abs(w.z());
  if (cosW == 0.0f) return 0.0f;
  // Only facets that face w (or -w when w is below the surface) are visible.
  const float visibleCos = std::copysign(1.0f, w.z()) * w.dot(wm);
  if (visibleCos <= 0.0f) return 0.0f;
  // D_w(wm) = G1(w) max(0, w.wm) D(wm) / cos theta_w (Heitz 2018 eq. 1).
  return G1(w) * visibleCos * D(wm) / cosW;
}

Vec3 GgxDistribution::sampleVisibleNormal(const Vec3& w, const Vec2& u) const {
  // Stretch the view direction into the hemispherical configuration (Heitz 2018 Listing 1, step 1);
  // a direction below the surface is mirrored to the upper side.
  Vec3 wh = Vec3(alpha_ * w.x(), alpha_ * w.y(), w.z()).normalized();
  if (wh.z() < 0.0f) wh = -wh;
  // Orthonormal basis around wh (Listing 1, step 2).
  const float lensq = wh.x() * wh.x() + wh.y() * wh.y();
  const Vec3 t1 = lensq > 0.0f ? Vec3(-wh.y(), wh.x(), 0.0f) / std::sqrt(lensq) : Vec3(1.0f, 0.0f, 0.0f);
  const Vec3 t2 = wh.cross(t1);
  // Uniform point on the unit disk, warped onto the projected visible hemisphere (Listing 1, step 3).
  const float r = std::sqrt(u.x());
  const float phi = 2.0f * kPi * u.y();
  const float p1 = r * std::cos(phi);
  float p2 = r * std::sin(phi);
  const float s = 0.5f * (1.0f + wh.z());
  p2 = (1.0f - s) * safeSqrt(1.0f - p1 * p1) + s * p2;
  // Reproject onto the hemisphere (Listing 1, step 4).
  const Vec3 nh = p1 * t1 + p2 * t2 + safeSqrt(1.0f - p1 * p1 - p2 * p2) * wh;
  // Unstretch back to the ellipsoid configuration (Listing 1, step 5).
  return Vec3(alpha_ * nh.x(), alpha_ * nh.y(), std::max(1e-6f, nh.z())).normalized();
}

}  // namespace lacrima
