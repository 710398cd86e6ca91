#pragma once
// The cubic spline smoothing kernel of SPH in 3D (Monaghan 1992, "Smoothed particle hydrodynamics",
// Annu. Rev. Astron. Astrophys. 30, eq. 2.6, the M4 spline), written with its support radius h
// (W = 0 for r >= h) as in Koschier, Bender, Solenthaler & Teschner 2019 ("Smoothed Particle
// Hydrodynamics Techniques for the Physics Based Simulation of Fluids and Solids", Eurographics
// tutorial, eq. 4): with q = r / h and k = 8 / (pi h^3),
//   W(q) = k (6 q^3 - 6 q^2 + 1)   for q <= 1/2,
//   W(q) = 2 k (1 - q)^3           for 1/2 < q <= 1,
// normalised (the integral over space is 1), C2, with the gradient
//   grad W = (48 / (pi h^3)) q (3 q - 2) r / (r h)   for q <= 1/2,
//   grad W = -(48 / (pi h^3)) (1 - q)^2 r / (r h)    for 1/2 < q <= 1.
#include <cmath>
#include <numbers>

#include "lacrima/base/math.hpp"

namespace lacrima::sph {

class CubicSplineKernel {
 public:
  explicit CubicSplineKernel(double supportRadius)
      : h_(supportRadius), k_(8.0 / (std::numbers::pi * h_ * h_ * h_)), l_(48.0 / (std::numbers::pi * h_ * h_ * h_)) {}

  double supportRadius() const { return h_; }

  double value(double r) const {
    const double q = r / h_;
    if (q > 1.0) return 0.0;
    if (q <= 0.5) return k_ * (6.0 * q * q * q - 6.0 * q * q + 1.0);
    const double s = 1.0 - q;
    return 2.0 * k_ * s * s * s;
  }
  double value(const Vec3d& r) const { return value(r.norm()); }

  Vec3d gradient(const Vec3d& r) const {
    const double length = r.norm();
    const double q = length / h_;
    if (q > 1.0 || length < 1e-12 * h_) return Vec3d::Zero();
    const Vec3d direction = r / (length * h_);
    if (q <= 0.5) return l_ * q * (3.0 * q - 2.0) * direction;
    const double s = 1.0 - q;
    return -l_ * s * s * direction;
  }

 private:
  double h_, k_, l_;
};

}  // namespace lacrima::sph
