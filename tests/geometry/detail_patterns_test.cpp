// Detail pattern functions of Lin & Cheng 2013 section 3: the six heights against hand-computed values,
// their guards, the damping and applying a pattern to a mesh.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <set>
#include <vector>

#include "lacrima/face/detail_patterns.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima {
namespace detail_patterns_test {

// Expected values below were computed by hand (double precision) from the paper's formulas.

TEST(DetailPatterns, ForeheadWrinklesEq1) {
  // (1, 0), t = 0.5, alpha 2, beta 3: theta = 0, so e^(2 sin(1)^2).
  EXPECT_NEAR(foreheadWrinklePaperHeight(1.0f, 0.0f, 0.5f, 2.0f, 3.0f), 4.1212101112, 1e-5);
  EXPECT_NEAR(foreheadWrinkleHeight(1.0f, 0.0f, 0.5f, 2.0f, 3.0f), 3.1212101112, 1e-5);
  // x = 0 (the paper's arctan(y/0)): theta = pi/2, sin(1 - 0.5 * 1 - sin(pi/2)) = sin(-0.5).
  EXPECT_NEAR(foreheadWrinklePaperHeight(0.0f, 1.0f, 0.5f, 1.0f, 1.0f), 1.2584097832, 1e-5);
  EXPECT_NEAR(foreheadWrinkleHeight(0.0f, 1.0f, 0.5f, 1.0f, 1.0f), 0.2584097832, 1e-6);
  EXPECT_NEAR(foreheadWrinkleHeight(-0.0f, 1.0f, 0.5f, 1.0f, 1.0f), 0.2584097832, 1e-6);
  // x < 0 uses atan2: at (-1, 0) theta = pi, sin(1 - 0 - sin(0.5 pi)) = 0 (the paper's
  // arctan(0/-1) = 0 would give e^(sin(1)^2) here: documented difference in the half-plane x < 0).
  EXPECT_NEAR(foreheadWrinkleHeight(-1.0f, 0.0f, 0.5f, 1.0f, 0.5f), 0.0, 1e-6);
  // The origin (theta = 0) at any t, and t = 0: rest level removed, so 0 where the sine vanishes.
  EXPECT_EQ(foreheadWrinkleHeight(0.0f, 0.0f, 0.0f, 3.0f, 2.0f), 0.0f);
  EXPECT_EQ(foreheadWrinkleHeight(-0.0f, -0.0f, 1.5f, 3.0f, 2.0f), 0.0f);
  // Never below 0 for alpha >= 0, never above 0 for alpha < 0.
  for (float x = -1.0f; x <= 1.0f; x += 0.125f)
    for (float y = -1.0f; y <= 1.0f; y += 0.125f) {
      EXPECT_GE(foreheadWrinkleHeight(x, y, 0.3f, 0.5f, 2.0f), 0.0f);
      EXPECT_LE(foreheadWrinkleHeight(x, y, 0.3f, -0.5f, 2.0f), 0.0f);
    }
}

TEST(DetailPatterns, EyeCornerWrinklesEq2) {
  // (0, 2), t = 0.5, alpha 0.5, beta 0.3, gamma 3: theta = pi/2, sin(3 pi/2) = -1,
  // |2 + 0.5| = 2.5, 0.5 e^0.75.
  EXPECT_NEAR(eyeCornerWrinkleHeight(0.0f, 2.0f, 0.5f, 0.5f, 0.3f, 3.0f), 1.0585000083, 1e-5);
  // t = 0 and t near 0: alpha e^(beta r).
  EXPECT_NEAR(eyeCornerWrinkleHeight(0.6f, 0.8f, 0.0f, 0.5f, 0.3f, 3.0f), 0.5 * std::exp(0.3), 1e-6);
  EXPECT_NEAR(eyeCornerWrinkleHeight(0.6f, 0.8f, 1e-7f, 0.5f, 0.3f, 3.0f), 0.5 * std::exp(0.3), 1e-6);
  EXPECT_FLOAT_EQ(eyeCornerWrinkleHeight(0.0f, 0.0f, 0.0f, 0.5f, 0.3f, 3.0f), 0.5f);
}

TEST(DetailPatterns, CheekWrinklesEq3) {
  // (3, 4), t = 0.25, alpha 0.2, beta 2: r = 5, 0.2 sin(10.25).
  EXPECT_NEAR(cheekWrinkleHeight(3.0f, 4.0f, 0.25f, 0.2f, 2.0f), -0.1469396861, 1e-6);
  EXPECT_NEAR(cheekWrinkleHeight(0.0f, 0.0f, 0.0f, 0.2f, 2.0f), 0.0, 1e-7);
  EXPECT_NEAR(cheekWrinkleHeight(0.0f, 0.5f, 0.0f, 0.2f, 2.0f), 0.2 * std::sin(1.0), 1e-6);
}

TEST(DetailPatterns, FrownEq4) {
  // (1, 2), t = 0.5, alpha 0.1, beta 1.5: 0.1 sin(2 / 2).
  EXPECT_NEAR(frownHeight(1.0f, 2.0f, 0.5f, 0.1f, 1.5f), 0.0841470985, 1e-7);
  // beta + t = 0: divisor replaced by +1e-6, 0.1 sin(2e6).
  EXPECT_NEAR(frownHeight(1.0f, 2.0f, 0.5f, 0.1f, -0.5f), -0.0655714316, 1e-5);
  EXPECT_EQ(frownHeight(0.0f, 2.0f, 0.5f, 0.1f, -0.5f), 0.0f);  // x = 0: sin(0)
  // t near 0 with beta != 0 is regular.
  EXPECT_NEAR(frownHeight(1.0f, 2.0f, 1e-7f, 0.1f, 2.0f), 0.1 * std::sin(1.0), 1e-6);
}

TEST(DetailPatterns, DimpleEq5) {
  EXPECT_NEAR(dimpleHeight(0.6f, 0.8f, 0.5f), 0.4054651081, 1e-6);  // log(1.5)
  EXPECT_NEAR(dimpleHeight(0.0f, 0.0f, 1e-3f), -6.9077552790, 1e-5);  // log(1e-3), t near 0
  // x^2 + y^2 + t = 0: argument floored at 1e-6.
  EXPECT_NEAR(dimpleHeight(0.0f, 0.0f, 0.0f), -13.8155105580, 1e-5);
  EXPECT_NEAR(dimpleHeight(0.0f, 0.5f, -0.25f), -13.8155105580, 1e-5);
  EXPECT_NEAR(dimpleHeight(0.0f, 1.0f, 0.0f), 0.0, 1e-7);  // x = 0
}

TEST(DetailPatterns, EyePouchEq6) {
  // (0.5, 0.25), t = 2, alpha 0.25, beta -0.5, gamma 1.5: c = cos(1) + cos(-0.75), c^1.5 / 2.
  EXPECT_NEAR(eyePouchHeight(0.5f, 0.25f, 2.0f, 0.25f, -0.5f, 1.5f), 0.7172922715, 1e-6);
  // Negative base, fractional gamma: |cos 3 + cos 2|^0.5 / 1.
  EXPECT_NEAR(eyePouchHeight(3.0f, 2.0f, 1.0f, 0.0f, 0.0f, 0.5f), 1.1858074604, 1e-6);
  // t = 0: divisor floored at 1e-6, (1 + 1)^2 / 1e-6.
  EXPECT_NEAR(eyePouchHeight(0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 2.0f), 4e6, 1.0);
  EXPECT_NEAR(eyePouchHeight(0.0f, 0.0f, 1e-3f, 0.0f, 0.0f, 2.0f), 4e3, 1e-2);  // t near 0
  // Base ~0 with gamma < 0: floored at 1e-6, (1e-6)^-2 / 1.
  EXPECT_NEAR(eyePouchHeight(kPi, 0.0f, 1.0f, 0.0f, 0.0f, -2.0f), 1e12, 1e6);
  // gamma = 0: |c|^0 = 1 everywhere.
  EXPECT_FLOAT_EQ(eyePouchHeight(kPi, 0.0f, 2.0f, 0.0f, 0.0f, 0.0f), 0.5f);
}

TEST(DetailPatterns, CompositeIsTheSumOfHeights) {
  const std::vector<BasicDetailPattern> patterns = {{DetailPatternKind::CheekWrinkles, 0.2f, 2.0f, 0.0f},
                                                    {DetailPatternKind::Dimple, 0.0f, 0.0f, 0.0f},
                                                    {DetailPatternKind::ForeheadWrinkles, 1.0f, 1.0f, 0.0f}};
  const float expected = cheekWrinkleHeight(0.3f, -0.4f, 0.7f, 0.2f, 2.0f) + dimpleHeight(0.3f, -0.4f, 0.7f) +
                         foreheadWrinkleHeight(0.3f, -0.4f, 0.7f, 1.0f, 1.0f);
  EXPECT_NEAR(detailPatternHeight(patterns, 0.3f, -0.4f, 0.7f), expected, 1e-6);
  EXPECT_EQ(detailPatternHeight(std::span<const BasicDetailPattern>(), 0.3f, -0.4f, 0.7f), 0.0f);
  EXPECT_EQ(detailPatternHeight(patterns[1], 0.6f, 0.8f, 0.5f), dimpleHeight(0.6f, 0.8f, 0.5f));
}

TEST(DetailPatterns, NeverNaNOrInfOverTheRegionAndTime) {
  const std::vector<BasicDetailPattern> patterns = {
      {DetailPatternKind::ForeheadWrinkles, 2.0f, 3.5f, 0.0f},  {DetailPatternKind::ForeheadWrinkles, -1.0f, 0.5f, 0.0f},
      {DetailPatternKind::EyeCornerWrinkles, 0.5f, 0.3f, 3.0f}, {DetailPatternKind::EyeCornerWrinkles, 1.0f, 40.0f, 2.5f},
      {DetailPatternKind::CheekWrinkles, 0.2f, 5.0f, 0.0f},     {DetailPatternKind::Frown, 0.3f, -1.0f, 0.0f},
      {DetailPatternKind::Frown, 0.3f, 0.0f, 0.0f},             {DetailPatternKind::Dimple, 0.0f, 0.0f, 0.0f},
      {DetailPatternKind::EyePouch, 0.5f, -0.5f, 1.5f},        {DetailPatternKind::EyePouch, 1.0f, 1.0f, -0.7f},
      {DetailPatternKind::EyePouch, 0.0f, 0.0f, 0.0f},         {DetailPatternKind::EyePouch, 2.0f, 1.0f, 3.3f}};
  int evaluated = 0;
  for (int ti = 0; ti <= 40; ++ti) {
    const float t = 0.05f * float(ti);  // includes 0 and 1 (frown beta -1: beta + t = 0)
    for (int xi = -20; xi <= 20; ++xi)
      for (int yi = -20; yi <= 20; ++yi) {
        const float x = 0.05f * float(xi), y = 0.05f * float(yi);  // includes x = 0, y = 0
        for (const BasicDetailPattern& p : patterns) {
          ASSERT_TRUE(std::isfinite(detailPatternHeight(p, x, y, t))) << int(p.kind) << " " << x << " " << y << " " << t;
          ++evaluated;
        }
        ASSERT_TRUE(std::isfinite(detailPatternHeight(patterns, x, y, t)));
        ASSERT_TRUE(std::isfinite(foreheadWrinklePaperHeight(x, y, t, 2.0f, 3.5f)));
      }
  }
  EXPECT_GT(evaluated, 800000);
  // Overflow, huge and non-finite inputs are clamped or zeroed, never inf/NaN.
  EXPECT_EQ(eyeCornerWrinkleHeight(1000.0f, 0.0f, 0.0f, 1.0f, 1000.0f, 1.0f), std::numeric_limits<float>::max());
  EXPECT_TRUE(std::isfinite(foreheadWrinklePaperHeight(1.0f, 0.0f, 0.0f, 1e4f, 1.0f)));
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const BasicDetailPattern& p : patterns) {
    EXPECT_TRUE(std::isfinite(detailPatternHeight(p, nan, 0.0f, 1.0f)));
    EXPECT_TRUE(std::isfinite(detailPatternHeight(p, inf, 0.0f, 1.0f)));
    EXPECT_TRUE(std::isfinite(detailPatternHeight(p, 0.5f, 0.5f, nan)));
    EXPECT_TRUE(std::isfinite(detailPatternHeight(p, 0.5f, 0.5f, -inf)));
  }
}

TEST(DetailDamping, OneInsideZeroAtAndOutsideTheBorder) {
  const float a = 2.0f, b = 1.0f, inner = 0.5f;
  EXPECT_EQ(detailDamping(0.0f, 0.0f, a, b, inner), 1.0f);
  EXPECT_EQ(detailDamping(1.0f, 0.0f, a, b, inner), 1.0f);   // rho = 0.5
  EXPECT_EQ(detailDamping(0.0f, 0.5f, a, b, inner), 1.0f);   // rho = 0.5
  EXPECT_EQ(detailDamping(0.6f, 0.3f, a, b, inner), 1.0f);   // rho ~0.42
  EXPECT_EQ(detailDamping(2.0f, 0.0f, a, b, inner), 0.0f);   // border
  EXPECT_EQ(detailDamping(0.0f, -1.0f, a, b, inner), 0.0f);  // border
  EXPECT_EQ(detailDamping(0.0f, 1.5f, a, b, inner), 0.0f);
  EXPECT_EQ(detailDamping(1.9f, 0.9f, a, b, inner), 0.0f);
  EXPECT_EQ(detailDamping(std::numeric_limits<float>::quiet_NaN(), 0.0f, a, b, inner), 0.0f);
  // Halfway (rho = 0.75, s = 0.5): the smootherstep is 0.5; strictly decreasing along a ray.
  EXPECT_NEAR(detailDamping(1.5f, 0.0f, a, b, inner), 0.5f, 1e-6f);
  float previous = 1.0f;
  for (float x = 1.0f; x <= 2.0f; x += 0.01f) {
    const float d = detailDamping(x, 0.0f, a, b, inner);
    EXPECT_LE(d, previous);
    EXPECT_GE(d, 0.0f);
    previous = d;
  }
  // innerRadius 0: still 1 at the centre.
  EXPECT_EQ(detailDamping(0.0f, 0.0f, a, b, 0.0f), 1.0f);
  EXPECT_THROW(detailDamping(0.0f, 0.0f, 0.0f, b, inner), InputError);
  EXPECT_THROW(detailDamping(0.0f, 0.0f, a, -1.0f, inner), InputError);
  EXPECT_THROW(detailDamping(0.0f, 0.0f, a, b, 1.0f), InputError);
  EXPECT_THROW(detailDamping(0.0f, 0.0f, a, b, -0.1f), InputError);
}

TEST(DetailDamping, DerivativeIsContinuousAcrossTheInnerRadiusAndTheBorder) {
  const float a = 2.0f, b = 1.0f, inner = 0.5f;
  const float h = 1e-3f;
  // Central-difference derivative along a direction at parameter s (point s * dir).
  auto derivative = [&](const Vec2& dir, float s) {
    const Vec2 p1 = (s + h) * dir, p0 = (s - h) * dir;
    return (detailDamping(p1.x(), p1.y(), a, b, inner) - detailDamping(p0.x(), p0.y(), a, b, inner)) / (2.0f * h);
  };
  // Directions with rho(s * dir) = s: the x axis, the y axis and a diagonal on the unit ellipse.
  const float c = std::sqrt(0.5f);
  for (const Vec2& dir : {Vec2(a, 0.0f), Vec2(0.0f, -b), Vec2(a * c, b * c)}) {
    for (float crossing : {inner, 1.0f}) {
      // The derivative just left and just right of the crossing agree and are ~0 (C1 with zero
      // slope there), while the maximum slope in between is O(1).
      const float left = derivative(dir, crossing - 2.0f * h), right = derivative(dir, crossing + 2.0f * h);
      EXPECT_NEAR(left, right, 2e-3f) << dir.transpose() << " at " << crossing;
      EXPECT_NEAR(left, 0.0f, 2e-3f);
      EXPECT_NEAR(right, 0.0f, 2e-3f);
    }
    // Along the whole ray, neighbouring derivative samples differ by O(step) (no jumps anywhere).
    float previous = derivative(dir, 0.3f), steepest = 0.0f;
    for (float s = 0.3f + 0.005f; s <= 1.2f; s += 0.005f) {
      const float d = derivative(dir, s);
      EXPECT_LT(std::abs(d - previous), 0.2f) << s;
      steepest = std::max(steepest, std::abs(d));
      previous = d;
    }
    EXPECT_NEAR(steepest, 3.75f, 0.05f);  // 15/8 / (1 - inner) per unit rho, at rho = 0.75
  }
}

// A 41 x 41 grid in the plane z = 0 over [-2, 2]^2 with tilted, non-unit normals.
struct GridMesh {
  TriangleMesh mesh;
  std::vector<Vec3> normals;
};

GridMesh makeGrid() {
  GridMesh g;
  for (int j = 0; j <= 40; ++j)
    for (int i = 0; i <= 40; ++i) {
      const float x = -2.0f + 0.1f * float(i), y = -2.0f + 0.1f * float(j);
      g.mesh.positions.emplace_back(x, y, 0.0f);
      g.normals.push_back(2.0f * Vec3(0.2f * x, -0.1f, 1.0f));
    }
  g.mesh.positions.emplace_back(-0.0f, 1.9f, -0.0f);  // outside the region, signed zeros
  g.normals.emplace_back(0.0f, 0.0f, 1.0f);
  g.mesh.positions.emplace_back(0.3f, -0.2f, 5.0f);  // above the centre, beyond maxNormalDistance
  g.normals.emplace_back(0.0f, 0.0f, 1.0f);
  return g;
}

DetailRegion makeRegion() {
  const float phi = 0.4f;
  DetailRegion region;
  region.center = Vec3(0.3f, -0.2f, 0.0f);
  region.tangentX = Vec3(std::cos(phi), std::sin(phi), 0.0f);
  region.tangentY = Vec3(-std::sin(phi), std::cos(phi), 0.0f);
  region.semiAxisA = 1.5f;
  region.semiAxisB = 0.8f;
  region.innerRadius = 0.4f;
  region.maxNormalDistance = 1.0f;
  return region;
}

bool bitwiseEqual(const Vec3& p, const Vec3& q) {
  for (int k = 0; k < 3; ++k)
    if (std::bit_cast<uint32_t>(p[k]) != std::bit_cast<uint32_t>(q[k])) return false;
  return true;
}

const std::vector<BasicDetailPattern> kCheekAndDimple = {{DetailPatternKind::CheekWrinkles, 0.1f, 3.0f, 0.0f},
                                                         {DetailPatternKind::Dimple, 0.0f, 0.0f, 0.0f}};

TEST(ApplyDetailPattern, MovesInsideVerticesAlongTheNormalAndLeavesOthersBitwiseUnchanged) {
  GridMesh g = makeGrid();
  const std::vector<Vec3> before = g.mesh.positions;
  const DetailRegion region = makeRegion();
  DetailPatternApplication app;
  app.patterns = kCheekAndDimple;
  app.time = 0.7f;
  app.heightScale = 0.05f;
  app.coordinateScale = 2.0f;
  const size_t moved = applyDetailPattern(g.mesh, g.normals, region, app);

  size_t inside = 0, inner = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    const Vec3 d = before[i] - region.center;
    const float x = d.dot(region.tangentX), y = d.dot(region.tangentY);
    const float rho = std::hypot(x / region.semiAxisA, y / region.semiAxisB);
    if (rho >= 1.0f || std::abs(d.z()) > region.maxNormalDistance) {
      EXPECT_TRUE(bitwiseEqual(g.mesh.positions[i], before[i])) << i;
      continue;
    }
    ++inside;
    const float damping = detailDamping(x, y, region.semiAxisA, region.semiAxisB, region.innerRadius);
    if (rho <= region.innerRadius) {
      EXPECT_EQ(damping, 1.0f);
      ++inner;
    }
    const float height = cheekWrinkleHeight(2.0f * x, 2.0f * y, 0.7f, 0.1f, 3.0f) + dimpleHeight(2.0f * x, 2.0f * y, 0.7f);
    const Vec3 expected = before[i] + g.normals[i].normalized() * (0.05f * damping * height);
    const Vec3 offset = g.mesh.positions[i] - before[i];
    EXPECT_LT((g.mesh.positions[i] - expected).norm(), 1e-6f) << i;
    // Along the normal: no component perpendicular to it.
    EXPECT_LT(offset.cross(g.normals[i].normalized()).norm(), 1e-6f) << i;
  }
  EXPECT_GT(inner, 20u);
  EXPECT_GT(inside, inner + 50u);
  EXPECT_LE(moved, inside);
  EXPECT_GT(moved, inside - 5u);  // only vertices with exactly zero displacement (the border) skip
  EXPECT_TRUE(bitwiseEqual(g.mesh.positions[g.mesh.positions.size() - 2], Vec3(-0.0f, 1.9f, -0.0f)));
  EXPECT_TRUE(bitwiseEqual(g.mesh.positions.back(), Vec3(0.3f, -0.2f, 5.0f)));
}

TEST(ApplyDetailPattern, PatternOriginShiftsThePatternButNotTheDamping) {
  GridMesh g = makeGrid();
  const std::vector<Vec3> before = g.mesh.positions;
  const DetailRegion region = makeRegion();
  const std::vector<BasicDetailPattern> forehead = {{DetailPatternKind::ForeheadWrinkles, 1.0f, 2.0f, 0.0f}};
  DetailPatternApplication app;
  app.patterns = forehead;
  app.time = 0.5f;
  app.heightScale = 0.05f;
  app.coordinateScale = 2.0f;
  app.patternOrigin = Vec2(0.25f, -1.5f);  // below the region, outside it
  applyDetailPattern(g.mesh, g.normals, region, app);
  size_t checked = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    const Vec3 d = before[i] - region.center;
    const float x = d.dot(region.tangentX), y = d.dot(region.tangentY);
    const float damping = detailDamping(x, y, region.semiAxisA, region.semiAxisB, region.innerRadius);
    if (std::abs(d.z()) > region.maxNormalDistance || damping == 0.0f) {
      EXPECT_TRUE(bitwiseEqual(g.mesh.positions[i], before[i])) << i;
      continue;
    }
    const float height = foreheadWrinkleHeight(2.0f * (x - 0.25f), 2.0f * (y + 1.5f), 0.5f, 1.0f, 2.0f);
    const Vec3 expected = before[i] + g.normals[i].normalized() * (0.05f * damping * height);
    EXPECT_LT((g.mesh.positions[i] - expected).norm(), 1e-6f) << i;
    ++checked;
  }
  EXPECT_GT(checked, 100u);
  app.patternOrigin = Vec2(std::nanf(""), 0.0f);
  EXPECT_THROW(applyDetailPattern(g.mesh, g.normals, region, app), InputError);
}

TEST(ApplyDetailPattern, RandomValidSubsetIsReproducibleForASeedAndDiffersForAnother) {
  const DetailRegion region = makeRegion();
  DetailPatternApplication app;
  app.patterns = kCheekAndDimple;
  app.time = 0.7f;
  app.heightScale = 0.05f;
  auto movedSet = [&](uint64_t seed, std::vector<Vec3>* positions) {
    GridMesh g = makeGrid();
    const std::vector<Vec3> before = g.mesh.positions;
    app.selection = {0.5f, seed};
    const size_t count = applyDetailPattern(g.mesh, g.normals, region, app);
    std::set<size_t> moved;
    for (size_t i = 0; i < before.size(); ++i)
      if (!bitwiseEqual(g.mesh.positions[i], before[i])) {
        moved.insert(i);
        EXPECT_TRUE(isValidDetailVertex(i, app.selection)) << i;  // invalid vertices never move
      }
    EXPECT_EQ(count, moved.size());
    if (positions) *positions = g.mesh.positions;
    return moved;
  };
  std::vector<Vec3> first, second;
  const std::set<size_t> a = movedSet(7, &first), a2 = movedSet(7, &second), b = movedSet(8, nullptr);
  EXPECT_EQ(a, a2);
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) EXPECT_TRUE(bitwiseEqual(first[i], second[i]));
  EXPECT_NE(a, b);

  // About half of the region's vertices are valid; all of them with fraction 1, none with 0.
  app.selection = {1.0f, 7};
  GridMesh all = makeGrid();
  const size_t everyInside = applyDetailPattern(all.mesh, all.normals, region, app);
  EXPECT_GT(a.size(), everyInside * 3 / 10);
  EXPECT_LT(a.size(), everyInside * 7 / 10);
  app.selection = {0.0f, 7};
  GridMesh none = makeGrid();
  EXPECT_EQ(applyDetailPattern(none.mesh, none.normals, region, app), 0u);
  // Validity is per vertex index: the fraction of valid indices over many is close to the fraction.
  size_t valid = 0;
  for (size_t i = 0; i < 100000; ++i) valid += isValidDetailVertex(i, {0.25f, 123});
  EXPECT_NEAR(double(valid) / 100000.0, 0.25, 0.01);
}

TEST(ApplyDetailPattern, RejectsBadArguments) {
  GridMesh g = makeGrid();
  DetailPatternApplication app;
  app.patterns = kCheekAndDimple;
  DetailRegion region = makeRegion();
  std::vector<Vec3> fewNormals(3, Vec3::UnitZ());
  EXPECT_THROW(applyDetailPattern(g.mesh, fewNormals, region, app), std::invalid_argument);
  region.tangentY = region.tangentX;
  EXPECT_THROW(applyDetailPattern(g.mesh, g.normals, region, app), InputError);
  region = makeRegion();
  region.semiAxisB = 0.0f;
  EXPECT_THROW(applyDetailPattern(g.mesh, g.normals, region, app), InputError);
  region = makeRegion();
  app.selection.fraction = 1.5f;
  EXPECT_THROW(applyDetailPattern(g.mesh, g.normals, region, app), InputError);
  app.selection.fraction = 1.0f;
  app.heightScale = std::numeric_limits<float>::infinity();
  EXPECT_THROW(applyDetailPattern(g.mesh, g.normals, region, app), InputError);
}

}  // namespace detail_patterns_test
}  // namespace lacrima
