// Moving least squares (Lin & Cheng 2013 section 4.2 step four, eqs. 8-14).
#include "lacrima/mesh/moving_least_squares.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lacrima/base/error.hpp"

namespace lacrima {
namespace moving_least_squares_test {

// A polynomial in up to 3 variables as a list of (exponents, coefficient), built by the test
// independently of the library's monomial enumeration.
struct Polynomial {
  std::vector<std::array<int, 3>> powers;
  std::vector<double> coefficients;

  double operator()(const Eigen::VectorXd& x) const {
    double sum = 0.0;
    for (size_t k = 0; k < powers.size(); ++k) {
      double term = coefficients[k];
      for (int j = 0; j < int(x.size()); ++j) term *= std::pow(x(j), powers[k][size_t(j)]);
      sum += term;
    }
    return sum;
  }
};

// All monomials of total degree <= r in d variables.
std::vector<std::array<int, 3>> monomials(int d, int r) {
  std::vector<std::array<int, 3>> out;
  for (int a = 0; a <= r; ++a)
    for (int b = 0; b <= (d >= 2 ? r : 0); ++b)
      for (int c = 0; c <= (d >= 3 ? r : 0); ++c)
        if (a + b + c <= r) out.push_back({a, b, c});
  return out;
}

// Random coefficients in [-1, 1] for every monomial of degree <= r; the pure x_0^r term gets
// coefficient 1 so that the polynomial has exactly degree r.
Polynomial randomPolynomial(int d, int r, std::mt19937& rng) {
  std::uniform_real_distribution<double> coef(-1.0, 1.0);
  Polynomial p;
  p.powers = monomials(d, r);
  for (const auto& e : p.powers) p.coefficients.push_back(e[0] == r && r > 0 ? 1.0 : coef(rng));
  return p;
}

Eigen::MatrixXd randomPoints(int n, int d, std::mt19937& rng, double extent = 1.0) {
  std::uniform_real_distribution<double> u(-extent, extent);
  Eigen::MatrixXd p(n, d);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < d; ++j) p(i, j) = u(rng);
  return p;
}

Eigen::MatrixXd sample(const Eigen::MatrixXd& points, const Polynomial& f) {
  Eigen::MatrixXd v(points.rows(), 1);
  for (Eigen::Index i = 0; i < points.rows(); ++i) v(i, 0) = f(points.row(i).transpose());
  return v;
}

// The paper's formula evaluated literally: raw monomials b(p) in the original coordinates,
// A = sum_i w_i b(p_i) b(p_i)^T, f(x) = b(x)^T A^-1 sum_i w_i b(p_i) f_i (Lin & Cheng 2013 eqs. 12-14).
// Only well conditioned for points near the origin; used as an oracle there.
double paperFormula(const Eigen::MatrixXd& points, const Eigen::VectorXd& values, int r, double epsilon,
                    const Eigen::VectorXd& x) {
  const auto powers = monomials(int(points.cols()), r);
  const auto basis = [&](const Eigen::VectorXd& p) {
    Eigen::VectorXd b(Eigen::Index(powers.size()));
    for (size_t k = 0; k < powers.size(); ++k) {
      double t = 1.0;
      for (int j = 0; j < int(p.size()); ++j) t *= std::pow(p(j), powers[k][size_t(j)]);
      b(Eigen::Index(k)) = t;
    }
    return b;
  };
  const Eigen::Index m = Eigen::Index(powers.size());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::VectorXd p = points.row(i).transpose();
    const double w = 1.0 / ((x - p).squaredNorm() + epsilon * epsilon);
    const Eigen::VectorXd b = basis(p);
    a += w * b * b.transpose();
    rhs += w * b * values(i);
  }
  return basis(x).dot(a.fullPivLu().solve(rhs));
}

template <class F>
std::string inputErrorMessage(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

TEST(MovingLeastSquares, BasisSizeIsBinomial) {
  EXPECT_EQ(MovingLeastSquares::basisSize(1, 0), 1);
  EXPECT_EQ(MovingLeastSquares::basisSize(1, 2), 3);
  EXPECT_EQ(MovingLeastSquares::basisSize(2, 1), 3);
  EXPECT_EQ(MovingLeastSquares::basisSize(2, 2), 6);
  EXPECT_EQ(MovingLeastSquares::basisSize(3, 2), 10);
  EXPECT_EQ(MovingLeastSquares::basisSize(3, 3), 20);
  for (int d = 1; d <= 3; ++d)
    for (int r = 0; r <= 4; ++r) EXPECT_EQ(MovingLeastSquares::basisSize(d, r), int(monomials(d, r).size()));
}

// Every polynomial of total degree s <= r lies in the space the fit minimises over and has zero
// residual, so the fit returns it exactly in exact arithmetic, for any weights. Tolerance 1e-9:
// values are O(1) (|coefficients| <= 1, |x| <= 1.2, at most 10 monomials), the centred and scaled
// basis is O(1), so the rounding error is about cond(A) * 1e-16; 1e-9 leaves room for cond(A) up
// to ~1e6 (seen: max error ~1e-12), while the degree r+1 test below shows errors > 1e-3.
TEST(MovingLeastSquares, ReproducesPolynomialsOfDegreeAtMostR) {
  std::mt19937 rng(2024);
  for (int d = 1; d <= 3; ++d) {
    for (int r = 0; r <= 2; ++r) {
      const int m = MovingLeastSquares::basisSize(d, r);
      const Eigen::MatrixXd points = randomPoints(3 * m + 5, d, rng);
      for (int s = 0; s <= r; ++s) {
        const Polynomial f = randomPolynomial(d, s, rng);
        const Polynomial g = randomPolynomial(d, s, rng);
        Eigen::MatrixXd values(points.rows(), 2);  // two components fitted at once
        values.col(0) = sample(points, f);
        values.col(1) = sample(points, g);
        for (double epsilon : {0.3, 1e-3, 0.0}) {
          const MovingLeastSquares mls(points, values, r, epsilon);
          std::vector<Eigen::VectorXd> xs;
          for (int k = 0; k < 20; ++k) xs.push_back(randomPoints(1, d, rng, 1.2).row(0).transpose());
          xs.push_back(points.row(0).transpose());  // at a data point (the singular weight when epsilon = 0)
          for (const Eigen::VectorXd& x : xs) {
            SCOPED_TRACE(::testing::Message() << "d " << d << " r " << r << " s " << s << " eps " << epsilon
                                              << " x " << x.transpose());
            const Eigen::VectorXd fx = mls.evaluate(x);
            ASSERT_EQ(fx.size(), 2);
            EXPECT_NEAR(fx(0), f(x), 1e-9);
            EXPECT_NEAR(fx(1), g(x), 1e-9);
          }
        }
      }
    }
  }
}

// A polynomial of degree r+1 is outside the fitted space: the fit has a residual and is not exact
// (the reproduction test above would pass for any method that interpolates, this one would not).
TEST(MovingLeastSquares, DoesNotReproduceDegreeRPlusOne) {
  std::mt19937 rng(99);
  for (int d = 1; d <= 3; ++d) {
    for (int r = 0; r <= 2; ++r) {
      const int m = MovingLeastSquares::basisSize(d, r);
      const Eigen::MatrixXd points = randomPoints(3 * m + 5, d, rng);
      const Polynomial f = randomPolynomial(d, r + 1, rng);
      const MovingLeastSquares mls(points, sample(points, f), r, 0.3);
      double maxError = 0.0;
      for (int k = 0; k < 20; ++k) {
        const Eigen::VectorXd x = randomPoints(1, d, rng).row(0).transpose();
        maxError = std::max(maxError, std::abs(mls.evaluate(x)(0) - f(x)));
      }
      EXPECT_GT(maxError, 1e-3) << "d " << d << " r " << r;
    }
  }
}

// The centring and scaling inside evaluate change nothing mathematically: the result equals the
// paper's eq. 14 evaluated literally (well conditioned for points near the origin).
TEST(MovingLeastSquares, MatchesThePapersFormulaNearTheOrigin) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (int d = 1; d <= 3; ++d) {
    for (int r = 0; r <= 2; ++r) {
      const Eigen::MatrixXd points = randomPoints(3 * MovingLeastSquares::basisSize(d, r) + 5, d, rng);
      Eigen::MatrixXd values(points.rows(), 1);
      for (Eigen::Index i = 0; i < values.rows(); ++i) values(i, 0) = noise(rng);
      const MovingLeastSquares mls(points, values, r, 0.3);
      for (int k = 0; k < 10; ++k) {
        const Eigen::VectorXd x = randomPoints(1, d, rng).row(0).transpose();
        EXPECT_NEAR(mls.evaluate(x)(0), paperFormula(points, values.col(0), r, 0.3, x), 1e-9)
            << "d " << d << " r " << r;
      }
    }
  }
}

// w = 1/(theta^2 + eps^2) is singular at theta = 0 when eps = 0, which forces interpolation
// (Lin & Cheng 2013); for eps > 0 the error at a data point shrinks with eps. It does so monotonically
// only once eps is well below the distance delta to the nearest other point (for eps ~ delta the
// neighbour's weight competes and the error can grow), then like eps^2: the error must fall from
// eps = delta to 0.1 delta, and then by at least tenfold per decade down to 1e-5 delta (or reach
// rounding).
TEST(MovingLeastSquares, InterpolatesAsEpsilonShrinks) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (int d = 1; d <= 3; ++d) {
    for (int r = 0; r <= 2; ++r) {
      const Eigen::MatrixXd points = randomPoints(3 * MovingLeastSquares::basisSize(d, r) + 10, d, rng);
      Eigen::MatrixXd values(points.rows(), 1);
      for (Eigen::Index i = 0; i < values.rows(); ++i) values(i, 0) = noise(rng);
      for (Eigen::Index k = 0; k < 5; ++k) {
        const Eigen::VectorXd x = points.row(k).transpose();
        double delta = std::numeric_limits<double>::infinity();
        for (Eigen::Index i = 0; i < points.rows(); ++i)
          if (i != k) delta = std::min(delta, (points.row(i).transpose() - x).norm());
        SCOPED_TRACE(::testing::Message() << "d " << d << " r " << r << " point " << k << " delta " << delta);
        const auto errorAt = [&](double epsilon) {
          return std::abs(MovingLeastSquares(points, values, r, epsilon).evaluate(x)(0) - values(k, 0));
        };
        double previous = errorAt(0.1 * delta);
        EXPECT_LT(previous, errorAt(delta));
        for (double factor : {1e-2, 1e-3, 1e-4, 1e-5}) {
          const double epsilon = factor * delta;
          const double error = errorAt(epsilon);
          EXPECT_TRUE(error < previous / 10.0 || error < 1e-12) << "eps " << epsilon << ": " << error << " after "
                                                                << previous;
          previous = error;
        }
        EXPECT_LT(previous, 1e-6);
        EXPECT_EQ(MovingLeastSquares(points, values, r, 0.0).evaluate(x)(0), values(k, 0));
      }
    }
  }
}

TEST(MovingLeastSquares, EpsilonZeroAtCoincidentPointsReturnsTheirMean) {
  Eigen::MatrixXd points(5, 2);
  points << 0, 0, 1, 0, 0, 1, 1, 1, 0, 0;
  Eigen::MatrixXd values(5, 3);
  values << 1, 10, -1, 5, 5, 5, 5, 5, 5, 5, 5, 5, 3, 20, -3;
  const MovingLeastSquares mls(points, values, 1, 0.0);
  const Eigen::VectorXd f = mls.evaluate(Eigen::Vector2d(0, 0));
  EXPECT_EQ(f, Eigen::Vector3d(2, 15, -2));
  // Next to the doubled point the fit approaches the same limit.
  EXPECT_NEAR(mls.evaluate(Eigen::Vector2d(1e-7, 0))(0), 2.0, 1e-5);
}

// Shifting all points and x by a large offset must not change the result: raw monomials at
// |p| ~ 1e6 would make A(x) hopelessly ill-conditioned (entries up to 1e24 for r = 2), the
// centring on x removes that. Tolerance 1e-7: coordinates near 1e6 carry rounding of ~1e-10, and
// the fitted function's slope is O(10).
TEST(MovingLeastSquares, IsTranslationInvariant) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  const Eigen::Vector3d shift(1e6, -7e5, 4e5);
  for (int d = 1; d <= 3; ++d) {
    for (int r = 0; r <= 2; ++r) {
      const Eigen::MatrixXd points = randomPoints(3 * MovingLeastSquares::basisSize(d, r) + 10, d, rng);
      Eigen::MatrixXd values(points.rows(), 1);
      for (Eigen::Index i = 0; i < values.rows(); ++i) values(i, 0) = noise(rng);
      const Eigen::RowVectorXd offset = shift.head(d).transpose();
      const Eigen::MatrixXd shifted = points.rowwise() + offset;
      for (double epsilon : {0.2, 0.0}) {
        const MovingLeastSquares near(points, values, r, epsilon);
        const MovingLeastSquares far(shifted, values, r, epsilon);
        for (int k = 0; k < 10; ++k) {
          const Eigen::VectorXd x = randomPoints(1, d, rng).row(0).transpose();
          const Eigen::VectorXd xFar = x + offset.transpose();
          EXPECT_NEAR(near.evaluate(x)(0), far.evaluate(xFar)(0), 1e-7) << "d " << d << " r " << r << " eps " << epsilon;
        }
      }
    }
  }
}

// A noisy plane as the tear's height field: heights along the normal over a (u, v) grid.
TEST(SmoothHeightField, ReducesNoiseOnAPlane) {
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.0f, 0.05f);
  std::vector<Vec2> uv;
  std::vector<float> heights, plane;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) {
      const Vec2 p(float(i) / 20.0f, float(j) / 20.0f);
      uv.push_back(p);
      plane.push_back(0.5f + 0.3f * p.x() - 0.2f * p.y());
      heights.push_back(plane.back() + noise(rng));
    }
  }
  const auto residualVariance = [&](const std::vector<float>& h) {
    double sum = 0.0, sum2 = 0.0;
    for (size_t i = 0; i < h.size(); ++i) {
      const double e = double(h[i]) - double(plane[i]);
      sum += e;
      sum2 += e * e;
    }
    const double mean = sum / double(h.size());
    return sum2 / double(h.size()) - mean * mean;
  };
  const double before = residualVariance(heights);
  for (int degree : {1, 2}) {
    const std::vector<float> smoothed = smoothHeightField(uv, heights, degree, 0.1);
    ASSERT_EQ(smoothed.size(), heights.size());
    const double after = residualVariance(smoothed);
    EXPECT_LT(after, 0.2 * before) << "degree " << degree << ": " << after << " vs " << before;
  }
  // epsilon = 0 interpolates: the heights come back unchanged.
  EXPECT_EQ(smoothHeightField(uv, heights, 1, 0.0), heights);
}

// Lin & Cheng 2013: the raised vertices "cannot go below the top surface". A fit of degree 2 next to a
// bump undershoots; the smoothed field keeps the lowest input height (0) as its floor.
TEST(SmoothHeightField, NeverGoesBelowTheLowestInputHeight) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Vec2> uv;
  std::vector<float> heights;
  for (int i = 0; i <= 15; ++i) {
    for (int j = 0; j <= 15; ++j) {
      uv.emplace_back(float(i) / 15.0f, float(j) / 15.0f);
      heights.push_back(unit(rng) < 0.1f ? 0.05f * unit(rng) : 0.0f);  // sparse random bumps
    }
  }
  Eigen::MatrixXd points(Eigen::Index(uv.size()), 2), values(Eigen::Index(uv.size()), 1);
  for (size_t i = 0; i < uv.size(); ++i) {
    points.row(Eigen::Index(i)) = uv[i].cast<double>().transpose();
    values(Eigen::Index(i), 0) = heights[i];
  }
  const MovingLeastSquares mls(points, values, 2, 0.02);
  double lowestRawFit = 0.0;
  for (const Vec2& p : uv) lowestRawFit = std::min(lowestRawFit, mls.evaluate(p.cast<double>())(0));
  ASSERT_LT(lowestRawFit, 0.0) << "the unclamped fit should undershoot somewhere for this test to mean anything";

  const std::vector<float> smoothed = smoothHeightField(uv, heights, 2, 0.02);
  float lowest = 1.0f, highest = 0.0f;
  for (float h : smoothed) {
    lowest = std::min(lowest, h);
    highest = std::max(highest, h);
  }
  EXPECT_EQ(lowest, 0.0f);
  EXPECT_GT(highest, 0.0f);
}

TEST(MovingLeastSquares, RejectsBadInputWithExactMessages) {
  const Eigen::MatrixXd square = (Eigen::MatrixXd(5, 2) << 0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.3).finished();
  const Eigen::MatrixXd five = Eigen::MatrixXd::Ones(5, 1);
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(Eigen::MatrixXd::Random(5, 4), five, 1, 0.1); }),
            "moving least squares: points have 4 coordinates; 1, 2 or 3 are supported");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(Eigen::MatrixXd(5, 0), five, 1, 0.1); }),
            "moving least squares: points have 0 coordinates; 1, 2 or 3 are supported");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, Eigen::MatrixXd::Ones(4, 1), 1, 0.1); }),
            "moving least squares: 5 points but 4 values; give one value per point");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, Eigen::MatrixXd(5, 0), 1, 0.1); }),
            "moving least squares: values have no components");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, five, -1, 0.1); }),
            "moving least squares: degree must be between 0 and 15, got -1");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, five, 1, -0.1); }),
            "moving least squares: epsilon must be finite and >= 0, got -0.1");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, five, 1, std::nan("")); }),
            "moving least squares: epsilon must be finite and >= 0, got nan");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, five, 2, 0.1); }),
            "moving least squares: a polynomial of degree 2 in 2 dimensions has 6 coefficients and needs at least 6 "
            "points, got 5");
  Eigen::MatrixXd badPoints = square;
  badPoints(2, 1) = std::numeric_limits<double>::infinity();
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(badPoints, five, 1, 0.1); }),
            "moving least squares: point 2 is not finite");
  Eigen::MatrixXd badValues = five;
  badValues(3, 0) = std::nan("");
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(square, badValues, 1, 0.1); }),
            "moving least squares: value 3 is not finite");
  // Collinear points cannot fix a plane (A(x) would be singular for every x) ...
  const Eigen::MatrixXd line = (Eigen::MatrixXd(4, 2) << 0, 0, 1, 1, 2, 2, 3, 3).finished();
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(line, Eigen::MatrixXd::Ones(4, 1), 1, 0.1); }),
            "moving least squares: the 4 points do not determine a polynomial of degree 1 in 2 dimensions (they lie "
            "on a line, plane or other curve of degree <= 1); use a lower degree or more spread-out points");
  // ... and points on a circle cannot fix a quadric (x^2 + y^2 - 1 vanishes on all of them).
  Eigen::MatrixXd circle(12, 2);
  for (int i = 0; i < 12; ++i) circle.row(i) << std::cos(0.5 * i), std::sin(0.5 * i);
  EXPECT_EQ(inputErrorMessage([&] { MovingLeastSquares(circle, Eigen::MatrixXd::Ones(12, 1), 2, 0.1); }),
            "moving least squares: the 12 points do not determine a polynomial of degree 2 in 2 dimensions (they lie "
            "on a line, plane or other curve of degree <= 2); use a lower degree or more spread-out points");
  EXPECT_NO_THROW(MovingLeastSquares(circle, Eigen::MatrixXd::Ones(12, 1), 1, 0.1));

  const MovingLeastSquares mls(square, five, 1, 0.1);
  EXPECT_EQ(inputErrorMessage([&] { mls.evaluate(Eigen::Vector3d(0, 0, 0)); }),
            "moving least squares: evaluation point has 3 coordinates, expected 2");
  EXPECT_EQ(inputErrorMessage([&] { mls.evaluate(Eigen::Vector2d(0, std::nan(""))); }),
            "moving least squares: evaluation point is not finite");

  EXPECT_EQ(inputErrorMessage([&] { smoothHeightField({Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, {0.0f, 1.0f}, 1, 0.1); }),
            "moving least squares: 3 (u, v) coordinates but 2 heights; give one height per vertex");
  EXPECT_EQ(inputErrorMessage([&] { smoothHeightField({}, {}, 2, 0.1); }),
            "moving least squares: a polynomial of degree 2 in 2 dimensions has 6 coefficients and needs at least 6 "
            "points, got 0");
}

}  // namespace moving_least_squares_test
}  // namespace lacrima
