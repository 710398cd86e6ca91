// Akinci et al. 2013's cohesion and adhesion splines; see surface_tension.hpp.
#include "lacrima/sph/surface_tension.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima::sph {

CohesionSpline::CohesionSpline(double supportRadius)
    : h_(supportRadius), scale_(32.0 / (std::numbers::pi * std::pow(supportRadius, 9))) {}

double CohesionSpline::value(double r) const {
  if (r <= 0.0 || r > h_) return 0.0;
  const double outer = (h_ - r) * (h_ - r) * (h_ - r) * r * r * r;
  if (2.0 * r > h_) return scale_ * outer;
  return scale_ * (2.0 * outer - std::pow(h_, 6) / 64.0);
}

AdhesionSpline::AdhesionSpline(double supportRadius) : h_(supportRadius), scale_(0.007 / std::pow(supportRadius, 3.25)) {}

double AdhesionSpline::value(double r) const {
  if (2.0 * r <= h_ || r > h_) return 0.0;
  return scale_ * std::pow(std::max(0.0, -4.0 * r * r / h_ + 6.0 * r - 2.0 * h_), 0.25);
}

double akinciGammaForSigma(double sigma, double restDensity, double particleRadius) {
  return sigma / (kSigmaPerGamma * restDensity * restDensity * particleRadius * particleRadius);
}

double sigmaForAkinciGamma(double gamma, double restDensity, double particleRadius) {
  return gamma * kSigmaPerGamma * restDensity * restDensity * particleRadius * particleRadius;
}

}  // namespace lacrima::sph
