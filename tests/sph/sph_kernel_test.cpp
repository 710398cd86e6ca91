// The cubic spline kernel (sph_kernel.hpp): normalised, compact, its gradient the derivative of
// its value, and symmetric.
#include <gtest/gtest.h>

#include "lacrima/sph/sph_kernel.hpp"

namespace lacrima::sph {
namespace sph_kernel_test {

TEST(SphKernel, IntegratesToOneOverItsSupport) {
  const double h = 0.01;
  const CubicSplineKernel kernel(h);
  // Midpoint rule on a lattice of h / 40 over the support's bounding cube.
  const int n = 40;
  const double cell = h / n;
  double sum = 0.0;
  for (int i = -n; i < n; ++i)
    for (int j = -n; j < n; ++j)
      for (int k = -n; k < n; ++k) sum += kernel.value(cell * Vec3d(i + 0.5, j + 0.5, k + 0.5));
  EXPECT_NEAR(sum * cell * cell * cell, 1.0, 2e-4);
}

TEST(SphKernel, IsCompactAndContinuousAtItsJoints) {
  const double h = 0.02;
  const CubicSplineKernel kernel(h);
  EXPECT_EQ(kernel.value(h), 0.0);
  EXPECT_EQ(kernel.value(1.5 * h), 0.0);
  EXPECT_TRUE(kernel.gradient(Vec3d(1.2 * h, 0.0, 0.0)) == Vec3d::Zero());
  EXPECT_NEAR(kernel.value(0.5 * h - 1e-12), kernel.value(0.5 * h + 1e-12), 1e-6 * kernel.value(0.0));
  EXPECT_NEAR(kernel.value(0.0), 8.0 / (std::numbers::pi * h * h * h), 1e-9 * kernel.value(0.0));
}

TEST(SphKernel, GradientIsTheDerivativeOfTheValue) {
  const double h = 0.01;
  const CubicSplineKernel kernel(h);
  const double step = 1e-7 * h;
  double worst = 0.0;
  for (int n = 1; n < 200; ++n) {
    const double r = h * n / 200.0;
    const Vec3d direction = Vec3d(1.0, -2.0, 0.5).normalized();
    const Vec3d at = r * direction;
    const double numeric = (kernel.value(r + step) - kernel.value(r - step)) / (2.0 * step);
    const Vec3d g = kernel.gradient(at);
    worst = std::max(worst, (g - numeric * direction).norm() / kernel.gradient(0.5 * h * direction).norm());
    EXPECT_NEAR(kernel.gradient(-at).dot(direction), -g.dot(direction), 1e-9 * g.norm() + 1e-30);  // odd
  }
  EXPECT_LT(worst, 1e-5);
}

}  // namespace sph_kernel_test
}  // namespace lacrima::sph
