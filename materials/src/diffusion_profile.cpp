// Christensen & Burley 2015 diffusion profile; see diffusion_profile.hpp for the model.
#include "lacrima/materials/diffusion_profile.hpp"

#include <algorithm>
#include <cmath>

namespace lacrima {

namespace {

constexpr float kEnergyWithinMaxRadius = 0.99f;
constexpr float kShortWeight = 0.25f;  // the exp(-r/d) component's share of the energy
constexpr float kLongWeight = 0.75f;   // the exp(-r/(3d)) component's

// P(r < radius) of an exponential of mean `mean`.
float exponentialCdf(float radius, float mean) { return -std::expm1(-radius / mean); }

// The untruncated radius CDF of the mixture, 1 - exp(-r/d)/4 - 3 exp(-r/(3d))/4.
float mixtureCdf(float radius, float d) {
  return kShortWeight * exponentialCdf(radius, d) + kLongWeight * exponentialCdf(radius, 3.0f * d);
}

// maxRadius / d: the mixture's CDF depends on r / d only, so one bisection serves every profile.
float maxRadiusInShapes() {
  static const float ratio = [] {
    float lo = 0.0f, hi = 40.0f;  // CDF(40 d) > 0.999
    for (int i = 0; i < 48; ++i) {
      const float mid = 0.5f * (lo + hi);
      (mixtureCdf(mid, 1.0f) < kEnergyWithinMaxRadius ? lo : hi) = mid;
    }
    return hi;
  }();
  return ratio;
}

// The CDFs at maxRadius, functions of maxRadius / d alone (see maxRadiusInShapes): computed once,
// as every probe needs them many times (nine radiusPdf calls) and makes its profile per hit.
struct CdfsAtMaxRadius {
  float mixture, shortComponent, longComponent;
};

const CdfsAtMaxRadius& cdfsAtMaxRadius() {
  static const CdfsAtMaxRadius cdfs{mixtureCdf(maxRadiusInShapes(), 1.0f), exponentialCdf(maxRadiusInShapes(), 1.0f),
                                    exponentialCdf(maxRadiusInShapes(), 3.0f)};
  return cdfs;
}

}  // namespace

float burleyDiffuseTransmissionScaling(float albedo) {
  const float offset = albedo - 0.8f;
  return 1.9f - albedo + 3.5f * offset * offset;
}

DiffusionProfile::DiffusionProfile(const Color& albedo, const Color& meanFreePath) {
  for (int c = 0; c < 3; ++c) {
    albedo_[c] = std::clamp(albedo[c], 0.0f, 1.0f);
    shape_[c] = std::max(meanFreePath[c], 1e-9f) / burleyDiffuseTransmissionScaling(albedo_[c]);
    maxRadius_[c] = maxRadiusInShapes() * shape_[c];
  }
}

Color DiffusionProfile::eval(float r) const {
  Color result;
  for (int c = 0; c < 3; ++c) {
    const float d = shape_[c];
    result[c] = r < maxRadius_[c] ? albedo_[c] * (std::exp(-r / d) + std::exp(-r / (3.0f * d))) /
                                        (8.0f * kPi * d * r * kEnergyWithinMaxRadius)
                                  : 0.0f;
  }
  return result;
}

float DiffusionProfile::radiusPdf(int channel, float r) const {
  const float d = shape_[channel];
  if (r < 0.0f || r >= maxRadius_[channel]) return 0.0f;
  const float untruncated = kShortWeight * std::exp(-r / d) / d + kLongWeight * std::exp(-r / (3.0f * d)) / (3.0f * d);
  return untruncated / cdfsAtMaxRadius().mixture;
}

float DiffusionProfile::sampleRadius(int channel, float u) const {
  // The truncated mixture is a mixture of the truncated components, each weighted by the share
  // of its energy inside maxRadius; each is inverted exactly.
  const float d = shape_[channel], rMax = maxRadius_[channel];
  const CdfsAtMaxRadius& cdfs = cdfsAtMaxRadius();
  const float shortInside = kShortWeight * cdfs.shortComponent;
  const float longInside = kLongWeight * cdfs.longComponent;
  const float pShort = shortInside / (shortInside + longInside);
  const bool shortComponent = u < pShort;
  const float mean = shortComponent ? d : 3.0f * d;
  const float v = shortComponent ? u / pShort : (u - pShort) / (1.0f - pShort);
  const float inside = shortComponent ? cdfs.shortComponent : cdfs.longComponent;
  const float r = -mean * std::log1p(-std::min(v, 0.99999994f) * inside);
  return std::min(r, std::nextafter(rMax, 0.0f));
}

}  // namespace lacrima
