#pragma once
// Moving least squares (MLS) approximation, as used by the shedding tear's step four in Lin & Cheng 2013
// (section 4.2, eqs. (8)-(14)): the noisy top surface of a tear is smoothed by fitting, at every
// evaluation point x, a polynomial of total degree r to all data by weighted least squares with
// weights that fall off with the distance to x.
#include <vector>

#include <Eigen/Core>

#include "lacrima/base/math.hpp"

namespace lacrima {

// f(x) = argmin over polynomials F of total degree r in d dimensions of
//   sum_i w(|x - p_i|) |F(p_i) - f_i|^2                                       (Lin & Cheng 2013 eq. 8, 10)
// with w(theta) = 1 / (theta^2 + epsilon^2)                                  (Lin & Cheng 2013, after eq. 10)
// evaluated at x as F(x) = b^T(x) c(x) with A(x) c(x) = sum_i w_i b(p_i) f_i (Lin & Cheng 2013 eqs. 9, 12-14).
// (Eq. 8 as printed has no square on the residual norm; eq. 10 and the normal equations 11-14 that
// the paper solves have it, so the square is used.)
//
// Points are d = 1, 2 or 3 dimensional (one point per row of `points`); values have k >= 1
// components (one row per point: a scalar field has k = 1, a displacement k = 3). Each component
// is fitted independently with the same weights, so k components cost one solve.
//
// Properties: every polynomial of total degree <= r is reproduced exactly (up to rounding); for
// epsilon > 0 the fit smooths (approximates) the data; epsilon = 0 makes w singular at the data
// points, which forces interpolation: evaluating exactly at a data point returns its value (the
// mean of the values of all points at exactly that position), the limit of the fit as
// epsilon -> 0. Each evaluation costs O(n m^2) for n points and m basis monomials; the weight
// has no compact support, so every point takes part.
//
// Throws InputError for: d not in 1..3, a point/value count mismatch, no value components, a
// degree outside 0..15, a negative or non-finite epsilon, non-finite points or values, fewer points
// than the m = (d+r)!/(d! r!) basis monomials, and points that do not determine a polynomial of
// degree r (for instance all on one line when d = 2, r = 1), which would make A(x) singular.
class MovingLeastSquares {
 public:
  MovingLeastSquares(Eigen::MatrixXd points, Eigen::MatrixXd values, int degree, double epsilon);

  // The fitted value f(x) (k components). Throws InputError if x has the wrong dimension or is
  // not finite.
  Eigen::VectorXd evaluate(const Eigen::VectorXd& x) const;

  int dimension() const { return int(points_.cols()); }
  int degree() const { return degree_; }
  double epsilon() const { return epsilon_; }
  // m = (d+r)!/(d! r!), the number of monomials of total degree <= r in d variables (Lin & Cheng 2013,
  // after eq. 10).
  static int basisSize(int dimension, int degree);

 private:
  Eigen::MatrixXd points_;              // n x d
  Eigen::MatrixXd values_;              // n x k
  std::vector<Eigen::Vector3i> powers_; // exponents of the m monomials, constant term first
  int degree_;
  double epsilon_;
};

// The shedding tear's use (Lin & Cheng 2013 section 4.2 step four): per-vertex heights along the base
// surface normal, given at the vertices' 2D parameter coordinates (u, v), smoothed by MLS of
// total degree `degree` in (u, v) and evaluated back at every vertex. `epsilon` is in (u, v)
// units: larger values smooth more, 0 interpolates (returns the heights unchanged). The tear's
// vertices "cannot go below the top surface", so the result is clamped to be no lower than the
// lowest input height (a fit of degree >= 1 can undershoot next to a bump). Throws InputError as
// MovingLeastSquares does.
std::vector<float> smoothHeightField(const std::vector<Vec2>& uv, const std::vector<float>& heights, int degree,
                                     double epsilon);

}  // namespace lacrima
