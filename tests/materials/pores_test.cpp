// The procedural pore field (pores.hpp): deterministic, analytic gradient, bounded tilt that never
// goes below the geometric surface, continuous in position, unbiased on average.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/base/hash.hpp"
#include "lacrima/materials/pores.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace pores_test {

constexpr float kScale = 3e-4f;  // 0.3 mm between pores
constexpr float kDepth = 3e-5f;  // 30 micrometre deep pits

// A random point of a patch of plane z = z0, 1 cm across (about 33 pores along each side).
Vec3 patchPoint(test::TestRng& rng, float z0 = 0.0123f) {
  return Vec3(0.01f * rng.uniform() - 0.003f, 0.01f * rng.uniform() + 0.2f, z0);
}

float angleDegrees(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.dot(b), -1.0f, 1.0f)) * 180.0f / kPi;
}

TEST(Pores, DeterministicAndOffWithoutDepth) {
  const Vec3 n(0.0f, 0.0f, 1.0f);
  test::TestRng rng(1);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 p = patchPoint(rng);
    EXPECT_TRUE(perturbNormalByPores(p, n, n, kScale, kDepth) == perturbNormalByPores(p, n, n, kScale, kDepth));
    EXPECT_TRUE(perturbNormalByPores(p, n, n, kScale, 0.0f) == n);
    EXPECT_EQ(poreHeight(p, kScale, 0.0f).height, 0.0f);
  }
}

TEST(Pores, GradientMatchesFiniteDifferencesAndPitsAreAsDeepAsGiven) {
  test::TestRng rng(2);
  const double h = 1e-3 * kScale;
  double maxErr = 0.0;
  float deepest = 0.0f;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 p = patchPoint(rng);
    const PoreHeight at = poreHeight(p, kScale, kDepth);
    ASSERT_LE(at.height, 0.0f);
    deepest = std::min(deepest, at.height);
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 step = Vec3::Zero();
      step[axis] = float(h);
      // Divide by the step the float positions really took (p is ~0.2 m: spacing 1.5e-8 m).
      const Vec3 plus = p + step, minus = p - step;
      const double fd = (double(poreHeight(plus, kScale, kDepth).height) -
                         double(poreHeight(minus, kScale, kDepth).height)) /
                        (double(plus[axis]) - double(minus[axis]));
      maxErr = std::max(maxErr, std::abs(fd - double(at.gradient[axis])));
    }
  }
  // Slopes are of order depth / radius ~ 0.3; the central difference is exact to O(h^2).
  EXPECT_LT(maxErr, 2e-3);
  // A pore's centre is kDepth deep (b(0) = 1); some random point comes within 80% of that.
  EXPECT_LT(deepest, -0.8f * kDepth);
  EXPECT_GE(deepest, -3.0f * kDepth);  // overlaps of at most a few pores
}

TEST(Pores, TiltIsBoundedAndNeverBelowTheGeometricSurface) {
  test::TestRng rng(3);
  const Vec3 ng(0.0f, 0.0f, 1.0f);
  // Shading normals from the geometric one up to 85 degrees away.
  float maxTilt = 0.0f;
  for (int k = 0; k < 40000; ++k) {
    const float theta = (k % 18) * 5.0f * kPi / 180.0f;
    const float phi = 2.0f * kPi * rng.uniform();
    const Vec3 ns(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    // A deep field: slopes would exceed the clamp without it.
    const Vec3 n = perturbNormalByPores(patchPoint(rng), ns, ng, kScale, 10.0f * kDepth);
    ASSERT_TRUE(n.allFinite());
    ASSERT_NEAR(n.norm(), 1.0f, 1e-5f);
    ASSERT_GE(n.dot(ng), kMinPoreCosToGeometric);
    const float tilt = angleDegrees(n, ns);
    ASSERT_LE(tilt, 45.0f + 1e-2f);
    maxTilt = std::max(maxTilt, tilt);
  }
  EXPECT_GT(maxTilt, 44.0f);  // the clamp is reached, so the bound above was tested
}

TEST(Pores, NormalIsContinuousInPosition) {
  test::TestRng rng(4);
  const Vec3 n(0.0f, 0.0f, 1.0f);
  const float step = 1e-3f * kScale;
  float maxJump = 0.0f;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p = patchPoint(rng);
    const Vec3 dir = rng.sphere();
    const Vec3 a = perturbNormalByPores(p, n, n, kScale, kDepth);
    const Vec3 b = perturbNormalByPores(p + step * dir, n, n, kScale, kDepth);
    maxJump = std::max(maxJump, (a - b).norm());
  }
  // Curvature of a pit: |d slope / d p| <= depth / scale * 4 / R^2 * 3 per lattice unit, ~0.013
  // over a 1e-3 lattice step; a cell-boundary discontinuity would show as a jump of order 0.1-1.
  EXPECT_LT(maxJump, 0.02f);
}

TEST(Pores, MeanNormalIsTheUnperturbedOne) {
  test::TestRng rng(5);
  const Vec3 n(0.0f, 0.0f, 1.0f);
  Vec3d sum = Vec3d::Zero();
  int tilted = 0;
  const int count = 200000;
  for (int k = 0; k < count; ++k) {
    const Vec3 t = perturbNormalByPores(patchPoint(rng), n, n, kScale, kDepth);
    sum += t.cast<double>();
    if (angleDegrees(t, n) > 2.0f) ++tilted;
  }
  const Vec3d mean = sum / count;
  EXPECT_LT(std::hypot(mean.x(), mean.y()), 3e-3);
  // Pits cover about 4/3 pi R^3 = 11% of a slice of the lattice; most of a pit is tilted > 2 deg.
  EXPECT_GT(tilted, count / 20);
  EXPECT_LT(tilted, count / 4);
}

// The field as pores.hpp defines it, summed over all 27 surrounding cells (the implementation
// visits only the cells that can reach the point): the same hashed centres (pores.cpp).
PoreHeight poreHeightOverAll27Cells(const Vec3& p, float scale, float depth) {
  constexpr uint64_t kPoreSeed = 0x706f726573ULL;
  const Vec3d q = p.cast<double>() / double(scale);
  const int64_t ci = int64_t(std::floor(q.x())), cj = int64_t(std::floor(q.y())), ck = int64_t(std::floor(q.z()));
  const Vec3 local = (q - Vec3d(double(ci), double(cj), double(ck))).cast<float>();
  constexpr float invR2 = 1.0f / (kPoreRadius * kPoreRadius);
  float sumB = 0.0f;
  Vec3 sumGrad = Vec3::Zero();
  for (int64_t di = -1; di <= 1; ++di)
    for (int64_t dj = -1; dj <= 1; ++dj)
      for (int64_t dk = -1; dk <= 1; ++dk) {
        const int64_t i = ci + di, j = cj + dj, k = ck + dk;
        const uint64_t cell = hashCombine(hashCombine(hashCombine(kPoreSeed, uint64_t(i)), uint64_t(j)), uint64_t(k));
        const Vec3 centre = Vec3(float(i) + uint64ToUnitFloat(hashCombine(cell, 0)),
                                 float(j) + uint64ToUnitFloat(hashCombine(cell, 1)),
                                 float(k) + uint64ToUnitFloat(hashCombine(cell, 2))) -
                            Vec3(float(ci), float(cj), float(ck));
        const Vec3 d = local - centre;
        const float s = d.squaredNorm() * invR2;
        if (s >= 1.0f) continue;
        sumB += (1.0f - s) * (1.0f - s);
        sumGrad += (-4.0f * (1.0f - s) * invR2) * d;
      }
  return {-depth * sumB, (-depth / scale) * sumGrad};
}

// Visiting only the cells that can reach a point loses nothing: bitwise the sum over all 27, also
// near cell faces and corners (points snapped to them) and far from the origin.
TEST(Pores, NearbyCellsGiveTheSumOverAll27) {
  test::TestRng rng(6);
  int inPits = 0;
  for (int k = 0; k < 200000; ++k) {
    Vec3 p = patchPoint(rng, 0.0123f + 0.001f * rng.uniform());
    if (k % 4 == 1) p = (p / kScale).array().round().matrix() * kScale;  // on a lattice corner
    if (k % 4 == 2) p.x() = std::round(p.x() / kScale) * kScale;          // on a cell face
    if (k % 4 == 3) p += Vec3(-1.7f, 2.3f, 0.9f);                         // far from the origin
    const PoreHeight fast = poreHeight(p, kScale, kDepth), all = poreHeightOverAll27Cells(p, kScale, kDepth);
    ASSERT_EQ(fast.height, all.height) << "at " << p.transpose();
    ASSERT_TRUE(fast.gradient == all.gradient) << "at " << p.transpose();
    inPits += all.height < 0.0f ? 1 : 0;
  }
  EXPECT_GT(inPits, 10000);  // the comparison covers many points inside pits, not only flat skin
}

}  // namespace pores_test
}  // namespace lacrima
