// The skin's relief (furrows.hpp, skin_relief.hpp): the furrow network's height is the groove
// profile of the true distance to the Voronoi cell boundary (checked against a brute-force diagram
// over 125 cells), its gradient is the height's derivative, it is continuous; the hollows' sky
// fractions are the configuration factors they claim (checked by sampling cosine-weighted
// directions out of a pit and a groove); the albedo factor is 1 without cavity.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/materials/furrows.hpp"
#include "lacrima/materials/pores.hpp"
#include "lacrima/materials/sampling.hpp"
#include "lacrima/materials/skin.hpp"
#include "lacrima/materials/skin_relief.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace skin_relief_test {

constexpr float kScale = 5e-4f;  // 0.5 mm plateaus
constexpr float kDepth = 1.5e-5f;

// A random point of a patch of plane z = z0, 1 cm across (about 20 plateaus along each side).
Vec3 patchPoint(test::TestRng& rng, float z0 = 0.0123f) {
  return Vec3(0.01f * rng.uniform() - 0.003f, 0.01f * rng.uniform() + 0.2f, z0);
}

// The feature point of lattice cell (i, j, k) as furrows.cpp hashes it, in lattice units.
Vec3d featurePoint(int64_t i, int64_t j, int64_t k) {
  constexpr uint64_t kFurrowSeed = 0x6675727277ULL;
  const uint64_t h = mix64(kFurrowSeed ^ (uint64_t(i) * 0x9e3779b97f4a7c15ULL) ^ (uint64_t(j) * 0xc2b2ae3d27d4eb4fULL) ^
                           (uint64_t(k) * 0x165667b19e3779f9ULL));
  constexpr uint64_t kMask = (1u << 21) - 1;
  return Vec3d(double(i) + double(float(h >> 43) * 0x1p-21f), double(j) + double(float((h >> 22) & kMask) * 0x1p-21f),
               double(k) + double(float((h >> 1) & kMask) * 0x1p-21f));
}

// Distance (lattice units) from q to the boundary of its Voronoi cell, over the 5x5x5 cells
// around it: the nearest point c1, then the nearest bisector plane to any other point.
double bruteForceWallDistance(const Vec3d& q) {
  const int64_t ci = int64_t(std::floor(q.x())), cj = int64_t(std::floor(q.y())), ck = int64_t(std::floor(q.z()));
  std::vector<Vec3d> points;
  for (int64_t di = -2; di <= 2; ++di)
    for (int64_t dj = -2; dj <= 2; ++dj)
      for (int64_t dk = -2; dk <= 2; ++dk) points.push_back(featurePoint(ci + di, cj + dj, ck + dk));
  size_t nearest = 0;
  for (size_t i = 1; i < points.size(); ++i)
    if ((q - points[i]).squaredNorm() < (q - points[nearest]).squaredNorm()) nearest = i;
  double wall = 1e9;
  for (size_t i = 0; i < points.size(); ++i) {
    if (i == nearest) continue;
    const double d = ((q - points[i]).squaredNorm() - (q - points[nearest]).squaredNorm()) /
                     (2.0 * (points[i] - points[nearest]).norm());
    wall = std::min(wall, d);
  }
  return wall;
}

TEST(Furrows, DeterministicAndOffWithoutDepth) {
  test::TestRng rng(1);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 p = patchPoint(rng);
    EXPECT_EQ(furrowHeight(p, kScale, kDepth).height, furrowHeight(p, kScale, kDepth).height);
    EXPECT_EQ(furrowHeight(p, kScale, 0.0f).height, 0.0f);
    EXPECT_TRUE(furrowHeight(p, kScale, 0.0f).gradient == Vec3::Zero());
  }
}

TEST(Furrows, HeightIsTheGrooveProfileOfTheDistanceToTheVoronoiWall) {
  test::TestRng rng(2);
  int inGroove = 0, mismatches = 0;
  const int count = 20000;
  for (int k = 0; k < count; ++k) {
    const Vec3 p = patchPoint(rng);
    const double wall = bruteForceWallDistance(p.cast<double>() / double(kScale));
    const double t = wall / kFurrowHalfWidth;
    const double expected = t < 1.0 ? -kDepth * (1.0 - t * t) * (1.0 - t * t) : 0.0;
    const float height = furrowHeight(p, kScale, kDepth).height;
    ASSERT_LE(height, 0.0f);
    ASSERT_GE(height, -kDepth * 1.0001f);
    if (expected < 0.0) ++inGroove;
    // The 27 cells searched hold the nearest point and every wall within the groove's width
    // almost always; a miss would show as a groove where there is none, or none where there is.
    if (std::abs(height - expected) > 1e-3 * kDepth) ++mismatches;
  }
  EXPECT_LE(mismatches, count / 1000) << mismatches << " of " << count;
  // A slice through walls of about 2.4 area per unit volume (a jittered lattice's Voronoi walls;
  // Poisson-Voronoi has 2.91): grooves 2w = 0.12 wide cover about 0.29 of the surface.
  EXPECT_GT(inGroove, count / 5);
  EXPECT_LT(inGroove, count * 2 / 5);
}

TEST(Furrows, GradientMatchesFiniteDifferencesAwayFromJunctions) {
  test::TestRng rng(3);
  const double h = 1e-3 * kFurrowHalfWidth * kScale;
  int compared = 0, off = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p = patchPoint(rng);
    const FurrowHeight at = furrowHeight(p, kScale, kDepth);
    if (at.height == 0.0f) continue;
    ++compared;
    for (int axis = 0; axis < 2; ++axis) {  // along the patch (z is the plane's constant)
      Vec3 step = Vec3::Zero();
      step[axis] = float(h);
      const Vec3 plus = p + step, minus = p - step;
      const double fd = (double(furrowHeight(plus, kScale, kDepth).height) -
                         double(furrowHeight(minus, kScale, kDepth).height)) /
                        (double(plus[axis]) - double(minus[axis]));
      // Slopes reach depth / w * 1.54 ~ 0.77; float heights of 1.5e-5 m over 3e-8 m steps are
      // good to about 1e-3. Where two walls meet (a crease) the difference straddles both.
      if (std::abs(fd - double(at.gradient[axis])) > 2e-2) ++off;
    }
  }
  EXPECT_GT(compared, 3000);
  EXPECT_LE(off, compared / 50) << off << " of " << compared;
}

TEST(Furrows, HeightIsContinuousInPosition) {
  test::TestRng rng(4);
  const float step = 1e-3f * kFurrowHalfWidth * kScale;
  float maxJump = 0.0f;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p = patchPoint(rng);
    const Vec3 dir = rng.sphere();
    maxJump = std::max(maxJump, std::abs(furrowHeight(p, kScale, kDepth).height -
                                         furrowHeight(p + step * dir, kScale, kDepth).height));
  }
  // The steepest slope (1.54 depth / w) over the step is 2.3e-3 depth; a lost wall would jump
  // by up to the whole depth.
  EXPECT_LT(maxJump, 5e-3f * kDepth);
}

// Cosine-weighted directions out of the floor of a hollow (at depth delta on its axis) that leave
// through the opening: a disk of radius r (pit) or a slot of half-width w (groove, along y).
double sampledSkyFraction(bool pit, double opening, double delta) {
  test::TestRng rng(5);
  int through = 0;
  const int count = 400000;
  for (int k = 0; k < count; ++k) {
    const Vec3 d = sampleCosineHemisphere(rng.uniform2());
    const double reach = delta / std::max(double(d.z()), 1e-12);  // ray length to the opening's height
    const double x = d.x() * reach, y = d.y() * reach;
    if (pit ? x * x + y * y < opening * opening : std::abs(x) < opening) ++through;
  }
  return double(through) / count;
}

TEST(SkinRelief, HollowsSeeTheConfigurationFactorsOfTheirOpenings) {
  SkinParams pores;
  pores.poreScale = 3e-4f;
  pores.poreDepth = 3e-5f;
  SkinParams furrows;
  furrows.furrowScale = kScale;
  furrows.furrowDepth = kDepth;
  test::TestRng rng(6);
  int checkedPits = 0, checkedGrooves = 0;
  for (int k = 0; k < 20000 && (checkedPits < 3 || checkedGrooves < 3); ++k) {
    const Vec3 p = patchPoint(rng);
    const float pore = poreHeight(p, pores.poreScale, pores.poreDepth).height;
    if (pore < -0.5f * pores.poreDepth && pore > -pores.poreDepth && checkedPits < 3) {  // one pit, deep enough
      const double expected = sampledSkyFraction(true, kPoreRadius * pores.poreScale, -pore);
      EXPECT_NEAR(skinReliefAt(pores, p).visibility, expected, 3e-3);
      ++checkedPits;
    }
    const float groove = furrowHeight(p, kScale, kDepth).height;
    if (groove < -0.5f * kDepth && checkedGrooves < 3) {
      const double expected = sampledSkyFraction(false, kFurrowHalfWidth * kScale, -groove);
      EXPECT_NEAR(skinReliefAt(furrows, p).visibility, expected, 3e-3);
      ++checkedGrooves;
    }
  }
  EXPECT_EQ(checkedPits, 3);
  EXPECT_EQ(checkedGrooves, 3);
}

TEST(SkinRelief, AlbedoFactorFollowsTheCavityAndIsOneOnPlateaus) {
  SkinParams skin;
  skin.poreDepth = 3e-5f;
  skin.furrowScale = kScale;
  skin.furrowDepth = kDepth;
  test::TestRng rng(7);
  float darkest = 1.0f;
  int plateaus = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 p = patchPoint(rng);
    const SkinRelief relief = skinReliefAt(skin, p);
    ASSERT_GT(relief.visibility, 0.0f);
    ASSERT_LE(relief.visibility, 1.0f);
    skin.cavity = 0.0f;
    ASSERT_EQ(cavityAlbedoFactor(skin, relief), 1.0f);
    skin.cavity = 1.0f;
    const float full = cavityAlbedoFactor(skin, relief);
    skin.cavity = 0.5f;
    EXPECT_NEAR(cavityAlbedoFactor(skin, relief), 0.5f * (1.0f + full), 1e-6f);
    darkest = std::min(darkest, full);
    if (poreHeight(p, skin.poreScale, skin.poreDepth).height == 0.0f && furrowHeight(p, kScale, kDepth).height == 0.0f) {
      ++plateaus;
      EXPECT_EQ(relief.visibility, 1.0f);
      EXPECT_TRUE(relief.gradient == Vec3::Zero());
    }
  }
  EXPECT_GT(plateaus, 20000 / 3);
  // The deepest hollow: a 30 um pit of radius 90 um (F = 0.9) in a 15 um groove of half-width
  // 30 um (F = 0.89): about 0.8; deeper where pits overlap.
  EXPECT_LT(darkest, 0.85f);
  EXPECT_GT(darkest, 0.5f);
}

TEST(SkinRelief, SkinWithoutFurrowsTiltsItsNormalExactlyAsThePoresDo) {
  SkinParams skin;
  skin.poreDepth = 3e-5f;
  const SkinBsdf bsdf(skin);
  const Vec3 n(0.0f, 0.0f, 1.0f);
  test::TestRng rng(8);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p = patchPoint(rng);
    ASSERT_TRUE(bsdf.perturbShadingNormal(p, n, n) == perturbNormalByPores(p, n, n, skin.poreScale, skin.poreDepth));
    // A BSDF built with the relief's gradient at p tilts the same way as one that evaluates it.
    ASSERT_TRUE(SkinBsdf(skin, skinReliefAt(skin, p).gradient).perturbShadingNormal(p, n, n) ==
                bsdf.perturbShadingNormal(p, n, n));
  }
  EXPECT_TRUE(SkinBsdf(SkinParams{}).perturbShadingNormal(Vec3(0.1f, 0.2f, 0.3f), n, n) == n);
}

}  // namespace skin_relief_test
}  // namespace lacrima
