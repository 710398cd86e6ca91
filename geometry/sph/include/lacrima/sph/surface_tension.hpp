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
// gamma (N/m-like, "surfaceTension" in FluidParams) and beta ("adhesion") are the paper's
// coefficients, not the physical surface tension: the paper tunes them by look.
#include "lacrima/geometry/math.hpp"

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

}  // namespace lacrima::sph
