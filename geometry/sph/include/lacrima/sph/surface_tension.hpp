#pragma once
// Surface tension and adhesion for SPH fluids (Akinci, Akinci & Teschner 2013, "Versatile Surface
// Tension and Adhesion for SPH Fluids", ACM TOG 32(6), 182), the forces on particle i:
//   cohesion   F_ij = -gamma m_i m_j C(|x_ij|) x_ij / |x_ij|                        (eq. 1)
//   curvature  F_ij = -gamma m_i (n_i - n_j),  n_i = h sum_j (m_j / rho_j) grad W_ij  (eqs. 2-3)
//   together   F_ij = K_ij (cohesion + curvature),  K_ij = 2 rho0 / (rho_i + rho_j)  (eq. 4)
//   adhesion   F_ik = -beta m_i Psi_k A(|x_ik|) x_ik / |x_ik|  to boundary particle k (eq. 6)
// with the spline C (eq. 2, support h):
//   C(r) = 32 / (pi h^9) * (h - r)^3 r^3                 for h/2 < r <= h,
//   C(r) = 32 / (pi h^9) * (2 (h - r)^3 r^3 - h^6 / 64)  for 0 < r <= h/2,
// (attractive beyond h/2, repulsive closer, so particles keep their spacing), and A (eq. 7):
//   A(r) = 0.007 / h^3.25 * (-4 r^2 / h + 6 r - 2 h)^(1/4)  for h/2 < r <= h, else 0.
// gamma ("surfaceTension" in FluidParams) and beta ("adhesion") are the paper's coefficients, not
// the physical surface tension: the paper tunes them by look. akinciGammaForSigma below relates
// gamma to a physical surface tension sigma (N/m) by how a drop rings.
#include "lacrima/base/math.hpp"

namespace lacrima::sph {

class CohesionSpline {
 public:
  explicit CohesionSpline(double supportRadius);
  double value(double r) const;

 private:
  double h_, scale_;
};

class AdhesionSpline {
 public:
  explicit AdhesionSpline(double supportRadius);
  double value(double r) const;

 private:
  double h_, scale_;
};

// gamma for a physical surface tension sigma (N/m), from how a free drop rings. The cohesion pulls
// with an acceleration of order gamma rho0 (m C(r) ~ rho0) within a layer of about h, so by
// dimensions sigma = c gamma rho0^2 r^2 (r the particle radius). c is measured, not derived: the
// period of a zero-gravity drop's l = 2 mode against Rayleigh 1879's
// omega^2 = 8 sigma / (rho0 R^3) (docs/sph.md "Calibration"). c grows with the drop's resolution
// (0.10 at 10 particle radii to the drop's radius, 0.114 at 15, 0.14 at 20, 0.158 at 30) because
// the cohesion acts in a surface layer of fixed thickness in particles; kSigmaPerGamma is its value
// at 20 (a 2 mm tear drop of 0.1 mm particles), so coarser drops ring a little slower than sigma
// says and finer ones a little faster.
inline constexpr double kSigmaPerGamma = 0.14;  // c above
double akinciGammaForSigma(double sigma, double restDensity, double particleRadius);
double sigmaForAkinciGamma(double gamma, double restDensity, double particleRadius);

}  // namespace lacrima::sph
