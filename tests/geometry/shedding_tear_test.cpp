// Shedding tear (Lin & Cheng 2013 section 4.2 steps 1-5): surface coordinates, a closed outward tear on a
// skin mesh, never below the skin while the skin deforms, monotonic growth (step 5), upward-only
// noise (step 4) and bitwise repeatability.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/tears/shedding_tear.hpp"
#include "height_field_support.hpp"

namespace lacrima {
namespace shedding_tear_test {

constexpr int kGrid = 24;          // quads per side of the skin patch
constexpr float kHalf = 0.02f;     // the patch spans [-2 cm, 2 cm]^2, faces 1.67 mm > strip spacing

// A flat skin patch in the xy plane, counter-clockwise seen from +z (its outside).
TriangleMesh flatSkin() {
  return test::heightFieldMesh(kGrid, kHalf, [](float, float) { return 0.0f; });
}

// Same topology, moved vertices.
TriangleMesh deformed(const TriangleMesh& rest, const std::function<Vec3(const Vec3&)>& f) {
  TriangleMesh m = rest;
  for (Vec3& p : m.positions) p = f(p);
  return m;
}

// Bends the patch around the y axis with radius r: sign +1 curls it up towards the tear
// (concave), -1 away (convex); then a ripple along y and a scale.
Vec3 bend(const Vec3& p, float r, float sign, float ripple, float scale) {
  const float a = p.x() / r;
  Vec3 q(r * std::sin(a), p.y(), sign * r * (1.0f - std::cos(a)));
  q.z() += ripple * std::sin(p.y() * 300.0f);
  return q * scale;
}

std::vector<TriangleMesh> deformationSequence(const TriangleMesh& rest) {
  std::vector<TriangleMesh> seq = {rest};
  for (int k = 1; k <= 4; ++k) {
    const float r = 0.12f / float(k);  // down to 3 cm radius
    seq.push_back(deformed(rest, [&](const Vec3& p) { return bend(p, r, 1.0f, 0.0005f * k, 1.0f + 0.1f * k); }));
    seq.push_back(deformed(rest, [&](const Vec3& p) { return bend(p, r, -1.0f, 0.0005f * k, 1.0f - 0.1f * k); }));
  }
  return seq;
}

// A gently curving path down the patch (from y = +1.5 cm to -1.5 cm), as surface points.
std::vector<SurfacePoint> tearPath(const TriangleMesh& rest) {
  std::vector<SurfacePoint> path;
  for (int k = 0; k <= 6; ++k) {
    const float y = 0.015f - 0.005f * float(k);
    path.push_back(closestSurfacePoint(rest, Vec3(0.004f * std::sin(float(k)), y, 0.0f)));
  }
  return path;
}

SheddingTearParams noisyParams() {
  SheddingTearParams p;
  p.noiseDensity = 0.2f;
  p.seed = 42;
  return p;
}

// Smallest signed distance of the tear's vertices to the skin: to the nearest skin point, along
// that skin triangle's normal.
float lowestAboveSkin(const TriangleMesh& tear, const TriangleMesh& skin) {
  float lowest = std::numeric_limits<float>::infinity();
  for (const Vec3& v : tear.positions) {
    const SurfacePoint c = closestSurfacePoint(skin, v);
    lowest = std::min(lowest, (v - surfacePosition(skin, c)).dot(triangleNormal(skin, c.triangle)));
  }
  return lowest;
}

TEST(SurfacePoint, FollowsTheTriangle) {
  TriangleMesh skin = flatSkin();
  const SurfacePoint sp{5, Vec3(0.2f, 0.3f, 0.5f)};
  const uint32_t* idx = &skin.indices[15];
  const Vec3 expected = 0.2f * skin.positions[idx[0]] + 0.3f * skin.positions[idx[1]] + 0.5f * skin.positions[idx[2]];
  EXPECT_TRUE(surfacePosition(skin, sp).isApprox(expected));
  const TriangleMesh moved = deformed(skin, [](const Vec3& p) { return Vec3(2 * p.x(), p.y() + 1, p.z()); });
  EXPECT_NEAR(surfacePosition(moved, sp).x(), 2 * expected.x(), 1e-6f);
  EXPECT_NEAR(surfacePosition(moved, sp).y(), expected.y() + 1, 1e-6f);
  // closestSurfacePoint finds a point on the surface back.
  const SurfacePoint back = closestSurfacePoint(skin, expected + Vec3(0, 0, 0.01f));
  EXPECT_TRUE(surfacePosition(skin, back).isApprox(expected, 1e-5f));
  EXPECT_TRUE(triangleNormal(skin, 5).isApprox(Vec3(0, 0, 1)));
  EXPECT_THROW(surfacePosition(skin, SurfacePoint{uint32_t(skin.triangleCount()), Vec3(1, 0, 0)}), InputError);
  EXPECT_THROW(surfacePosition(skin, SurfacePoint{0, Vec3(0.5f, 0.6f, 0.0f)}), InputError);
  EXPECT_THROW(surfacePosition(skin, SurfacePoint{0, Vec3(1.5f, -0.5f, 0.0f)}), InputError);
}

TEST(SheddingTear, ClosedOutwardAndAboveTheSkinWhileTheSkinDeforms) {
  const TriangleMesh rest = flatSkin();
  const std::vector<SurfacePoint> path = tearPath(rest);
  const std::vector<TriangleMesh> skins = deformationSequence(rest);
  for (const SheddingTearParams& params : {SheddingTearParams{}, noisyParams()})
    for (float t : {0.0f, 0.55f, 1.3f, 3.0f}) {
      const SheddingTearStrip strip = buildSheddingTearStrip(rest, path, params, t);
      ASSERT_GE(strip.rows, 2);
      for (const TriangleMesh& skin : skins) {
        const TriangleMesh tear = sheddingTearMesh(skin, strip, params.baseOffset);
        ASSERT_EQ(findMeshDefect(tear), "");
        ASSERT_EQ(findClosedMeshDefect(tear), "") << "t = " << t;
        EXPECT_GT(signedVolume(tear), 0.0) << "t = " << t;
        // Lin & Cheng 2013 section 4.2 step 4: "the vertices cannot go below" - here, below the skin.
        EXPECT_GE(lowestAboveSkin(tear, skin), 0.5f * params.baseOffset) << "t = " << t;
      }
    }
}

TEST(SheddingTear, BaseHoversAndEdgesMeetTheSkin) {
  const TriangleMesh rest = flatSkin();
  const SheddingTearParams params;
  const TriangleMesh tear = buildSheddingTear(rest, tearPath(rest), params, 1.0f);
  float lowest = 1, highest = -1;
  for (const Vec3& v : tear.positions) {
    lowest = std::min(lowest, v.z());
    highest = std::max(highest, v.z());
  }
  EXPECT_NEAR(lowest, params.baseOffset, 1e-7f);
  // The head bulges above the body's thickness (Lin & Cheng 2013 section 4.2 step 3).
  EXPECT_GT(highest, params.baseOffset + params.thickness * 1.2f);
  EXPECT_LE(highest, params.baseOffset + params.thickness * (1.0f + params.headBulge) + 1e-7f);
  // Volume close to the lens cross-section (2/3 width thickness) times the length.
  const double body = 2.0 / 3.0 * params.width * params.thickness * (0.02 - params.headLength);
  EXPECT_GT(signedVolume(tear), 0.8 * body);
  EXPECT_LT(signedVolume(tear), 2.0 * body);
}

// Lin & Cheng 2013 section 4.2 step 3: the head is thicker than the body and its leading cap is narrowed
// to tipFraction of the width.
TEST(SheddingTear, RoundedHeadAtTheLeadingEnd) {
  const TriangleMesh rest = flatSkin();
  const SheddingTearParams params;
  const SheddingTearStrip strip = buildSheddingTearStrip(rest, tearPath(rest), params, 1.0f);
  const int c = strip.columns, mid = c / 2;
  auto at = [&](int i, int j) { return surfacePosition(rest, strip.points[size_t(i * c + j)]); };
  const int last = strip.rows - 1;
  EXPECT_NEAR((at(last, 0) - at(last, c - 1)).norm(), params.tipFraction * params.width, 1e-5f);
  EXPECT_NEAR((at(0, 0) - at(0, c - 1)).norm(), params.width, 1e-5f);
  int thickest = 0;
  for (int i = 0; i < strip.rows; ++i)
    if (strip.thickness[size_t(i * c + mid)] > strip.thickness[size_t(thickest * c + mid)]) thickest = i;
  EXPECT_GT(strip.coordinates[size_t(thickest * c)].x(), strip.length - params.headLength);
  EXPECT_LT(strip.coordinates[size_t(thickest * c)].x(), strip.length);
  EXPECT_NEAR(strip.thickness[size_t(thickest * c + mid)], params.thickness * (1 + params.headBulge),
              0.05f * params.thickness);
  EXPECT_FLOAT_EQ(strip.thickness[size_t(mid)], params.thickness);  // the body at the start
  EXPECT_NEAR(strip.thickness[size_t(last * c + mid)],
              params.thickness * (1 + params.headBulge) * params.tipFraction, 1e-7f);
}

TEST(SheddingTear, TailTapersFromTheSourceAndLeavesTheRestAsItWas) {
  const TriangleMesh rest = flatSkin();
  SheddingTearParams params;
  const SheddingTearStrip blunt = buildSheddingTearStrip(rest, tearPath(rest), params, 1.0f);
  params.tailLength = 0.004f;
  const SheddingTearStrip tapered = buildSheddingTearStrip(rest, tearPath(rest), params, 1.0f);
  ASSERT_EQ(tapered.rows, blunt.rows);
  const int c = tapered.columns, mid = c / 2;
  auto width = [&](const SheddingTearStrip& s, int i) {
    return (surfacePosition(rest, s.points[size_t(i * c)]) - surfacePosition(rest, s.points[size_t(i * c + c - 1)])).norm();
  };
  EXPECT_NEAR(width(tapered, 0), params.tipFraction * params.width, 1e-5f) << "a small lens at the source";
  EXPECT_NEAR(tapered.thickness[size_t(mid)], params.tipFraction * params.thickness, 1e-7f);
  float previous = 0.0f;
  for (int i = 0; i < tapered.rows; ++i) {
    const float a = tapered.coordinates[size_t(i * c)].x();
    if (a > params.tailLength) {  // beyond the tail: bitwise the blunt strip
      EXPECT_EQ(tapered.thickness[size_t(i * c + mid)], blunt.thickness[size_t(i * c + mid)]) << i;
      continue;
    }
    EXPECT_GE(tapered.thickness[size_t(i * c + mid)], previous) << "widens and thickens away from the source";
    previous = tapered.thickness[size_t(i * c + mid)];
  }
  EXPECT_EQ(findClosedMeshDefect(sheddingTearMesh(rest, tapered, params.baseOffset)), "");
  params.tailLength = -1.0f;
  EXPECT_THROW(buildSheddingTearStrip(rest, tearPath(rest), params, 1.0f), InputError);
}

TEST(SheddingTear, GrowsMonotonically) {
  const TriangleMesh rest = flatSkin();
  const std::vector<SurfacePoint> path = tearPath(rest);
  double previousVolume = 0;
  float previousLength = 0;
  int previousRows = 0;
  for (int k = 0; k <= 40; ++k) {
    const float t = -1.5f + 0.1f * float(k);  // h from -0.5 cm (empty) past the path's end
    const TriangleMesh tear = buildSheddingTear(rest, path, SheddingTearParams{}, t);
    const double v = tear.positions.empty() ? 0.0 : signedVolume(tear);
    EXPECT_GE(v, previousVolume) << "t = " << t;
    previousVolume = v;
    const SheddingTearStrip noisy = buildSheddingTearStrip(rest, path, noisyParams(), t);
    EXPECT_GE(noisy.length, previousLength);
    EXPECT_GE(noisy.rows, previousRows);
    previousLength = noisy.length;
    previousRows = noisy.rows;
  }
  EXPECT_GT(previousVolume, 0.0);
  EXPECT_TRUE(buildSheddingTear(rest, path, SheddingTearParams{}, -1.5f).positions.empty());
}

TEST(SheddingTear, NoiseOnlyRaisesTheTop) {
  const TriangleMesh rest = flatSkin();
  const std::vector<SurfacePoint> path = tearPath(rest);
  const SheddingTearStrip plain = buildSheddingTearStrip(rest, path, SheddingTearParams{}, 1.0f);
  const SheddingTearStrip noisy = buildSheddingTearStrip(rest, path, noisyParams(), 1.0f);
  ASSERT_EQ(plain.thickness.size(), noisy.thickness.size());
  int raised = 0;
  for (size_t k = 0; k < plain.thickness.size(); ++k) {
    EXPECT_GE(noisy.thickness[k], plain.thickness[k]);
    if (noisy.thickness[k] > plain.thickness[k] + 1e-6f) ++raised;
    if (k % size_t(plain.columns) == 0 || k % size_t(plain.columns) == size_t(plain.columns - 1)) {
      EXPECT_EQ(noisy.thickness[k], 0.0f);  // the edges stay on the skin
    }
  }
  EXPECT_GT(raised, 10);
}

TEST(SheddingTear, SameSeedBitwiseSameMesh) {
  const TriangleMesh rest = flatSkin();
  const std::vector<SurfacePoint> path = tearPath(rest);
  const TriangleMesh a = buildSheddingTear(rest, path, noisyParams(), 0.8f);
  const TriangleMesh b = buildSheddingTear(rest, path, noisyParams(), 0.8f);
  ASSERT_EQ(a.positions.size(), b.positions.size());
  ASSERT_EQ(a.indices, b.indices);
  EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(Vec3)), 0);
  SheddingTearParams other = noisyParams();
  other.seed = 43;
  const TriangleMesh c = buildSheddingTear(rest, path, other, 0.8f);
  EXPECT_NE(std::memcmp(a.positions.data(), c.positions.data(), a.positions.size() * sizeof(Vec3)), 0);
}

TEST(SheddingTear, RejectsBadInput) {
  const TriangleMesh rest = flatSkin();
  const std::vector<SurfacePoint> path = tearPath(rest);
  EXPECT_THROW(buildSheddingTear(rest, {path[0]}, SheddingTearParams{}, 1.0f), InputError);
  SheddingTearParams p;
  p.width = 0;
  EXPECT_THROW(buildSheddingTear(rest, path, p, 1.0f), InputError);
  p = {};
  p.acrossSamples = 2;
  EXPECT_THROW(buildSheddingTear(rest, path, p, 1.0f), InputError);
  p = {};
  p.baseOffset = 0;
  EXPECT_THROW(buildSheddingTear(rest, path, p, 1.0f), InputError);
  p = {};
  p.noiseDensity = 1.5f;
  EXPECT_THROW(buildSheddingTear(rest, path, p, 1.0f), InputError);
  EXPECT_THROW(buildSheddingTear(rest, path, SheddingTearParams{}, std::nanf("")), InputError);
}

}  // namespace shedding_tear_test
}  // namespace lacrima
