// Moving least squares (Lin & Cheng 2013 section 4.2 step four, eqs. 8-14).
#include "lacrima/mesh/moving_least_squares.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "lacrima/base/error.hpp"

namespace lacrima {
namespace {

constexpr const char* kWhat = "moving least squares";

// Exponents (a, b, c) of all monomials u^a v^b w^c of total degree <= r in d variables (unused
// variables get exponent 0), ordered by total degree so that the constant monomial comes first.
std::vector<Eigen::Vector3i> monomialPowers(int d, int r) {
  std::vector<Eigen::Vector3i> powers;
  for (int total = 0; total <= r; ++total) {
    for (int a = total; a >= 0; --a) {
      if (d == 1) {
        if (a == total) powers.emplace_back(a, 0, 0);
        continue;
      }
      for (int b = total - a; b >= 0; --b) {
        const int c = total - a - b;
        if (d == 2 && c != 0) continue;
        powers.emplace_back(a, b, c);
      }
    }
  }
  return powers;
}

// The basis vector b(q) of Lin & Cheng 2013 eq. 9: the monomials of `powers` evaluated at q (d <= 3).
void evaluateBasis(const std::vector<Eigen::Vector3i>& powers, int r, const double* q, int d, double* out) {
  double table[3][16];  // table[j][e] = q_j^e; r is validated to be small enough in the constructor
  for (int j = 0; j < 3; ++j) {
    table[j][0] = 1.0;
    for (int e = 1; e <= r; ++e) table[j][e] = j < d ? table[j][e - 1] * q[j] : 0.0;
  }
  for (size_t k = 0; k < powers.size(); ++k) {
    const Eigen::Vector3i& a = powers[k];
    out[k] = table[0][a.x()] * table[1][a.y()] * table[2][a.z()];
  }
}

}  // namespace

int MovingLeastSquares::basisSize(int dimension, int degree) {
  // m = (d+r)!/(d! r!) (Lin & Cheng 2013, after eq. 10), as a product that stays exact in integers.
  long long m = 1;
  for (int i = 1; i <= dimension; ++i) m = m * (degree + i) / i;
  return int(m);
}

MovingLeastSquares::MovingLeastSquares(Eigen::MatrixXd points, Eigen::MatrixXd values, int degree, double epsilon)
    : points_(std::move(points)), values_(std::move(values)), degree_(degree), epsilon_(epsilon) {
  const Eigen::Index n = points_.rows();
  const int d = int(points_.cols());
  if (d < 1 || d > 3)
    throw InputError(fmt::format("{}: points have {} coordinates; 1, 2 or 3 are supported", kWhat, d));
  if (values_.rows() != n)
    throw InputError(fmt::format("{}: {} points but {} values; give one value per point", kWhat, n, values_.rows()));
  if (values_.cols() < 1) throw InputError(fmt::format("{}: values have no components", kWhat));
  if (degree_ < 0 || degree_ > 15)
    throw InputError(fmt::format("{}: degree must be between 0 and 15, got {}", kWhat, degree_));
  if (!std::isfinite(epsilon_) || epsilon_ < 0.0)
    throw InputError(fmt::format("{}: epsilon must be finite and >= 0, got {}", kWhat, epsilon_));
  const int m = basisSize(d, degree_);
  if (n < m)
    throw InputError(fmt::format("{}: a polynomial of degree {} in {} dimensions has {} coefficients and needs at "
                                 "least {} points, got {}",
                                 kWhat, degree_, d, m, m, n));
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!points_.row(i).allFinite()) throw InputError(fmt::format("{}: point {} is not finite", kWhat, i));
    if (!values_.row(i).allFinite()) throw InputError(fmt::format("{}: value {} is not finite", kWhat, i));
  }
  powers_ = monomialPowers(d, degree_);

  // A(x) = sum_i w_i b(p_i) b(p_i)^T (Lin & Cheng 2013 eq. 12) is singular for every x exactly when the
  // n x m matrix with rows b(p_i) is rank deficient, because all weights are positive (an
  // infinite weight at epsilon = 0 is handled separately in evaluate). Checking that once here
  // (centred and scaled as in evaluate) turns "A is singular" into an input error.
  const Eigen::RowVectorXd centroid = points_.colwise().mean();
  const double radius = (points_.rowwise() - centroid).rowwise().norm().maxCoeff();
  const double scale = radius > 0.0 ? 1.0 / radius : 1.0;
  Eigen::MatrixXd vandermonde(n, m);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::RowVectorXd q = (points_.row(i) - centroid) * scale;
    Eigen::RowVectorXd row(m);
    evaluateBasis(powers_, degree_, q.data(), d, row.data());
    vandermonde.row(i) = row;
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(vandermonde);
  qr.setThreshold(1e-9);
  if (qr.rank() < m)
    throw InputError(fmt::format("{}: the {} points do not determine a polynomial of degree {} in {} dimensions "
                                 "(they lie on a line, plane or other curve of degree <= {}); use a lower degree "
                                 "or more spread-out points",
                                 kWhat, n, degree_, d, degree_));
}

Eigen::VectorXd MovingLeastSquares::evaluate(const Eigen::VectorXd& x) const {
  const int d = dimension();
  if (x.size() != d)
    throw InputError(fmt::format("{}: evaluation point has {} coordinates, expected {}", kWhat, x.size(), d));
  if (!x.allFinite()) throw InputError(fmt::format("{}: evaluation point is not finite", kWhat));
  const Eigen::Index n = points_.rows();
  const int m = int(powers_.size());

  // theta_i^2 + epsilon^2, the reciprocal of the weight w(theta_i) (Lin & Cheng 2013, after eq. 10).
  const double eps2 = epsilon_ * epsilon_;
  Eigen::VectorXd offsets(n);
  double radius2 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double theta2 = (points_.row(i).transpose() - x).squaredNorm();
    radius2 = std::max(radius2, theta2);
    offsets(i) = theta2 + eps2;
  }
  const double minOffset = offsets.minCoeff();
  if (minOffset == 0.0) {
    // epsilon = 0 and x is a data point: w is infinite there (Lin & Cheng 2013: "setting epsilon to zero
    // results in a singularity at theta = 0, which forces the MLS fit function to interpolate").
    // The limit epsilon -> 0 of the fit is the value at that point, or the mean of the values of
    // all points that sit exactly at x (their weights are equal and dominate all others).
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(values_.cols());
    int count = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (offsets(i) == 0.0) {
        sum += values_.row(i).transpose();
        ++count;
      }
    }
    return sum / double(count);
  }

  // Numerical robustness. The paper's formulation (eqs. 12-14) with raw monomials b(p_i) is
  // exact but badly conditioned: for points near |p| ~ 1000 and r = 2 the entries of A range
  // over ~1e12 and cond(A) is roughly the square of that, which exhausts double precision. The
  // polynomial space of degree <= r is invariant under translation and scaling of the
  // coordinates, so the same minimiser F is found with the basis b((p - x) / h), where the
  // points are centred on the evaluation point x and scaled by their largest distance h to it:
  // the monomials are then all O(1) and of comparable size, and F(x) = b(0)^T c = c_0 because
  // every non-constant monomial vanishes at q = 0. Centring on x also makes the rows of the
  // heavily weighted points near x close to b(0) = e_0, so a huge weight (epsilon -> 0) touches
  // essentially only A_00 instead of swamping all of A. A common factor of the weights does not
  // change the minimiser either, so they are divided by the largest one (no overflow as
  // theta, epsilon -> 0). A is symmetric positive definite (full rank checked in the
  // constructor), solved by Eigen's pivoted LDL^T.
  const double scale = radius2 > 0.0 ? 1.0 / std::sqrt(radius2) : 1.0;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, values_.cols());
  Eigen::VectorXd b(m);
  double q[3] = {0.0, 0.0, 0.0};
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int j = 0; j < d; ++j) q[j] = (points_(i, j) - x(j)) * scale;
    evaluateBasis(powers_, degree_, q, d, b.data());
    const double w = minOffset / offsets(i);  // w(theta_i) / max_i w(theta_i)
    a.selfadjointView<Eigen::Lower>().rankUpdate(b, w);       // sum_i w_i b(p_i) b(p_i)^T (eq. 12, left)
    rhs.noalias() += (w * b) * values_.row(i);                 // sum_i w_i b(p_i) f_i      (eq. 12, right)
  }
  // c(x) = A^-1 sum_i w_i b(p_i) f_i (Lin & Cheng 2013 eq. 13); f(x) = b^T(x) c(x) = c_0 (eq. 14).
  const Eigen::LDLT<Eigen::MatrixXd, Eigen::Lower> ldlt(a);  // reads only the lower triangle filled above
  const Eigen::MatrixXd c = ldlt.solve(rhs);
  return c.row(0).transpose();
}

std::vector<float> smoothHeightField(const std::vector<Vec2>& uv, const std::vector<float>& heights, int degree,
                                     double epsilon) {
  if (uv.size() != heights.size())
    throw InputError(fmt::format("{}: {} (u, v) coordinates but {} heights; give one height per vertex", kWhat,
                                 uv.size(), heights.size()));
  Eigen::MatrixXd points(Eigen::Index(uv.size()), 2);
  Eigen::MatrixXd values(Eigen::Index(uv.size()), 1);
  for (size_t i = 0; i < uv.size(); ++i) {
    points.row(Eigen::Index(i)) = uv[i].cast<double>().transpose();
    values(Eigen::Index(i), 0) = double(heights[i]);
  }
  const MovingLeastSquares mls(std::move(points), std::move(values), degree, epsilon);
  // Lin & Cheng 2013 step four: "the vertices cannot go below the top surface", so the smoothed heights
  // keep the lowest input height as a floor.
  const float floor = *std::min_element(heights.begin(), heights.end());
  std::vector<float> smoothed(uv.size());
  for (size_t i = 0; i < uv.size(); ++i) {
    const double h = mls.evaluate(uv[i].cast<double>())(0);
    smoothed[i] = std::max(floor, float(h));
  }
  return smoothed;
}

}  // namespace lacrima
