#pragma once
// Directional albedo of a BSDF by quadrature, for tests: the integral of f(wo, wi) cos(theta_i)
// over the upper hemisphere, by the midpoint rule in (cos theta, phi) with cosSteps x phiSteps
// cells (use fine grids for sharp lobes).
#include <cmath>

#include "lacrima/materials/bsdf.hpp"

namespace lacrima::test {

inline Color directionalAlbedo(const Bsdf& bsdf, const Vec3& wo, int cosSteps, int phiSteps) {
  Color sum = Color::Zero();
  for (int i = 0; i < cosSteps; ++i) {
    const float c = (float(i) + 0.5f) / float(cosSteps), s = std::sqrt(1.0f - c * c);
    for (int j = 0; j < phiSteps; ++j) {
      const float phi = 2.0f * kPi * (float(j) + 0.5f) / float(phiSteps);
      sum += bsdf.eval(wo, Vec3(s * std::cos(phi), s * std::sin(phi), c)) * c;
    }
  }
  return sum * (2.0f * kPi / (float(cosSteps) * float(phiSteps)));
}

}  // namespace lacrima::test
