// Dripping tear (Lin & Cheng 2013 section 4.1, eq. 7): closed, oriented and finite over a whole
// animation, eq. 7 at the head vertices, the documented narrowing with t, placement along gravity
// and bitwise repeatability.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <vector>

#include "lacrima/tears/dripping_tear.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {
namespace dripping_tear_test {

constexpr int kRings = 24;  // headRings = 8
constexpr int kSegments = 16;

uint32_t circleVertex(int ring, int segment) { return uint32_t(1 + (ring - 1) * kSegments + segment); }

// Every frame of 0..2 s at 24 fps, plus times inside the guard and before the start frame.
std::vector<float> animationTimes() {
  std::vector<float> times = {-0.5f, 0.0f, 1e-30f, 1e-6f, 0.001f};
  for (int frame = 0; frame <= 48; ++frame) times.push_back(float(frame) / 24.0f);
  return times;
}

// Independent of findClosedMeshDefect: counts directed edges by hand.
void expectClosedAndOriented(const TriangleMesh& mesh) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t i = 0; i < mesh.indices.size(); i += 3)
    for (int k = 0; k < 3; ++k) ++directed[{mesh.indices[i + k], mesh.indices[i + (k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "directed edge " << edge.first << "->" << edge.second;
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u) << "open edge " << edge.first << "-" << edge.second;
  }
  EXPECT_EQ(long(mesh.vertexCount()) - long(directed.size() / 2) + long(mesh.triangleCount()), 2);
  EXPECT_EQ(findClosedMeshDefect(mesh), "");
}

// Volume centroid by signed tetrahedra against the origin (double precision).
Vec3d volumeCentroid(const TriangleMesh& mesh) {
  Vec3d sum = Vec3d::Zero();
  double volume = 0.0;
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const Vec3d a = mesh.positions[mesh.indices[i]].cast<double>();
    const Vec3d b = mesh.positions[mesh.indices[i + 1]].cast<double>();
    const Vec3d c = mesh.positions[mesh.indices[i + 2]].cast<double>();
    const double v = a.dot(b.cross(c)) / 6.0;
    volume += v;
    sum += v * (a + b + c) / 4.0;
  }
  return sum / volume;
}

TEST(DrippingTear, ClosedOrientedFiniteAndNonDegenerateOverTheAnimation) {
  const DrippingTearParams p;
  for (const float t : animationTimes()) {
    SCOPED_TRACE(testing::Message() << "t = " << t);
    const TriangleMesh mesh = makeDrippingTear(p, t, kRings, kSegments);
    ASSERT_EQ(findMeshDefect(mesh), "");  // includes non-finite positions and normals
    EXPECT_EQ(mesh.vertexCount(), size_t(2 + (kRings - 1) * kSegments));
    EXPECT_EQ(mesh.triangleCount(), size_t(2 * kSegments * (kRings - 1)));
    expectClosedAndOriented(mesh);
    EXPECT_GT(signedVolume(mesh), 0.0);
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
      const Vec3& a = mesh.positions[mesh.indices[i]];
      const float area2 = (mesh.positions[mesh.indices[i + 1]] - a).cross(mesh.positions[mesh.indices[i + 2]] - a).norm();
      ASSERT_GT(area2, 0.0f) << "degenerate triangle " << i / 3;
    }
    std::map<std::tuple<float, float, float>, int> seen;
    for (const Vec3& q : mesh.positions) ASSERT_EQ((seen[{q.x(), q.y(), q.z()}]++), 0) << "duplicated vertex";
  }
}

TEST(DrippingTear, VolumeIsAboutRightForTheDefaultShape) {
  // Default headAngle = pi/4: the widest scaled radius is 2 (at eta = 0, computed by hand from
  // the header's tail profile), so the drop fits in a cylinder of radius 2 alpha / t and length
  // 2 beta t; it must hold a good part of it.
  const DrippingTearParams p;
  const float t = 0.5f;
  const TriangleMesh mesh = makeDrippingTear(p, t, 96, 128);
  const double radius = 2.0 * p.alpha / t, length = 2.0 * p.beta * t;
  const double cylinder = std::numbers::pi * radius * radius * length;
  EXPECT_LT(signedVolume(mesh), cylinder);
  EXPECT_GT(signedVolume(mesh), 0.3 * cylinder);
  // The header's 13.45 alpha^2 beta / t (profile integrated numerically, outside this code).
  const double expected = 13.45 * double(p.alpha) * p.alpha * p.beta / t;
  EXPECT_NEAR(signedVolume(mesh), expected, 0.01 * expected);
  const Eigen::AlignedBox3f box = computeBounds(mesh);
  EXPECT_NEAR(box.sizes().x(), 2.0 * radius, 1e-3 * radius);  // v = 0 lies on the widest circle's x axis
  EXPECT_NEAR(box.sizes().z(), length, 1e-6);
}

TEST(DrippingTear, HeadVerticesAreEquationSevenByHand) {
  DrippingTearParams p;
  p.alpha = 0.002f;
  p.beta = 0.01f;
  p.lambda = 0.3f;
  const float t = 0.5f;
  const TriangleMesh mesh = makeDrippingTear(p, t, kRings, kSegments);
  const auto expectAt = [&](uint32_t vertex, float x, float y, float z) {
    SCOPED_TRACE(testing::Message() << "vertex " << vertex);
    EXPECT_NEAR(mesh.positions[vertex].x(), x, 1e-6f);
    EXPECT_NEAR(mesh.positions[vertex].y(), y, 1e-6f);
    EXPECT_NEAR(mesh.positions[vertex].z(), z, 1e-6f);
  };
  // Leading apex u = 0: (0, 0, beta t + lambda t) = (0, 0, 0.005 + 0.15).
  expectAt(0, 0.0f, 0.0f, 0.155f);
  // Rim, circle 8 (u = pi/4, tan = 1, cos = sqrt(1/2)), segment 0 (v = 0):
  // x = alpha / t = 0.004, y = 0, z = 0.005 sqrt(1/2) + 0.15.
  const float halfSqrt2 = std::sqrt(0.5f);
  expectAt(circleVertex(8, 0), 0.004f, 0.0f, 0.005f * halfSqrt2 + 0.15f);
  // Rim, segment 4 (v = pi/2): x = 0, y = 0.004.
  expectAt(circleVertex(8, 4), 0.0f, 0.004f, 0.005f * halfSqrt2 + 0.15f);
  // Circle 4 (u = pi/8, tan = sqrt(2) - 1, cos = sqrt(2 + sqrt(2)) / 2), segment 2 (v = pi/4):
  // x = y = 0.004 (sqrt(2) - 1) sqrt(1/2).
  const float tanPi8 = std::sqrt(2.0f) - 1.0f, cosPi8 = std::sqrt(2.0f + std::sqrt(2.0f)) / 2.0f;
  expectAt(circleVertex(4, 2), 0.004f * tanPi8 * halfSqrt2, 0.004f * tanPi8 * halfSqrt2, 0.005f * cosPi8 + 0.15f);
  // Trailing tip, eq. 7 at u = pi: (0, 0, -beta t + lambda t).
  expectAt(uint32_t(mesh.vertexCount() - 1), 0.0f, 0.0f, 0.145f);
  // And drippingTearEq7 agrees with the same hand values.
  EXPECT_NEAR(drippingTearEq7(p, kPi / 4.0f, 0.0f, t).x(), 0.004f, 1e-6f);
  EXPECT_NEAR(drippingTearEq7(p, kPi / 4.0f, 0.0f, t).z(), 0.005f * halfSqrt2 + 0.15f, 1e-6f);
  // Every head vertex is drippingTearEq7 at its (u, v).
  for (int r = 1; r <= 8; ++r)
    for (int s = 0; s < kSegments; ++s) {
      const Vec3 q = drippingTearEq7(p, p.headAngle * float(r) / 8.0f, 2.0f * kPi * float(s) / float(kSegments), t);
      EXPECT_EQ(mesh.positions[circleVertex(r, s)], q) << "circle " << r << " segment " << s;
    }
}

TEST(DrippingTear, TailJoinsTheHeadSmoothlyAndIsPointed) {
  // Scaled profile at the default headAngle: the first tail circle continues the head's outward
  // slope (radius still grows past the rim), the widest circle has radius 2 alpha / t, the last
  // circle before the tip is narrower than the rim.
  const DrippingTearParams p;
  const float t = 1.0f;
  const TriangleMesh mesh = makeDrippingTear(p, t, kRings, kSegments);
  const auto radiusOf = [&](int ring) { return mesh.positions[circleVertex(ring, 0)].x(); };
  EXPECT_GT(radiusOf(9), radiusOf(8));
  float widest = 0.0f;
  for (int r = 1; r < kRings; ++r) widest = std::max(widest, radiusOf(r));
  EXPECT_NEAR(widest, 2.0f * p.alpha / t, 0.02f * p.alpha / t);
  EXPECT_LT(radiusOf(kRings - 1), radiusOf(8));
  for (int r = 1; r < kRings; ++r) EXPECT_GT(radiusOf(r), 0.0f);
  for (int r = 1; r + 1 < kRings; ++r) EXPECT_GT(mesh.positions[circleVertex(r, 0)].z(), mesh.positions[circleVertex(r + 1, 0)].z());
}

TEST(DrippingTear, NarrowsAndElongatesAsTimeGrows) {
  const DrippingTearParams p;
  float previousRatio = INFINITY, previousWidth = INFINITY, previousLength = 0.0f, firstK = NAN;
  for (const float t : animationTimes()) {
    if (t <= p.minTime) continue;
    SCOPED_TRACE(testing::Message() << "t = " << t);
    const Eigen::AlignedBox3f box = computeBounds(makeDrippingTear(p, t, kRings, kSegments));
    const float width = box.sizes().x(), length = box.sizes().z();
    EXPECT_LT(width, previousWidth);
    EXPECT_GT(length, previousLength);
    EXPECT_LT(width / length, previousRatio);
    // width / length is proportional to alpha / (beta t^2), as documented.
    const float k = width / length * t * t * p.beta / p.alpha;
    // The same for every t (one shape, only scaled); about 2 = widest scaled diameter 4 over
    // scaled length 2 (the tessellation samples the widest circle only approximately).
    if (std::isnan(firstK)) firstK = k;
    EXPECT_NEAR(k, firstK, 1e-4f);
    EXPECT_NEAR(k, 2.0f, 0.01f);
    previousRatio = width / length;
    previousWidth = width;
    previousLength = length;
  }
}

TEST(DrippingTear, ShapeIsFrozenBelowMinTimeButTheCentreStillFalls) {
  DrippingTearParams p;
  p.lambda = 0.2f;
  const TriangleMesh atGuard = makeDrippingTear(p, p.minTime, kRings, kSegments);
  const TriangleMesh atZero = makeDrippingTear(p, 0.0f, kRings, kSegments);
  const TriangleMesh early = makeDrippingTear(p, 0.1f, kRings, kSegments);
  const TriangleMesh before = makeDrippingTear(p, -1.0f, kRings, kSegments);
  const float fallAtGuard = p.lambda * p.minTime;
  for (size_t i = 0; i < atGuard.vertexCount(); ++i) {
    EXPECT_EQ(atZero.positions[i].head<2>(), atGuard.positions[i].head<2>());
    EXPECT_NEAR(atZero.positions[i].z(), atGuard.positions[i].z() - fallAtGuard, 1e-6f);
    EXPECT_NEAR(early.positions[i].z(), atGuard.positions[i].z() - fallAtGuard + p.lambda * 0.1f, 1e-6f);
    EXPECT_EQ(before.positions[i], atZero.positions[i]);
  }
  EXPECT_EQ(drippingTearShapeTime(p, 0.0f), p.minTime);
  EXPECT_EQ(drippingTearShapeTime(p, 1.0f), 1.0f);
}

TEST(DrippingTear, CentroidFallsWithLambdaTPlusAFixedShareOfBetaT) {
  DrippingTearParams p;
  p.lambda = 0.5f;
  // centroid z = lambda t + c beta t with one c for all t (the shape only scales).
  double c = NAN;
  for (const float t : {0.25f, 0.5f, 1.0f, 1.5f, 2.0f}) {
    const Vec3d centroid = volumeCentroid(makeDrippingTear(p, t, 48, 64));
    EXPECT_NEAR(centroid.x(), 0.0, 1e-8);
    EXPECT_NEAR(centroid.y(), 0.0, 1e-8);
    const double share = (centroid.z() - double(p.lambda) * t) / (double(p.beta) * t);
    if (std::isnan(c)) c = share;
    EXPECT_NEAR(share, c, 1e-3) << "t = " << t;
  }
  EXPECT_NEAR(c, 0.003, 0.003);  // the header's c for the default headAngle
}

TEST(DrippingTear, PlacementAlignsTheAxisWithGravityAndTheOriginWithTheStart) {
  DrippingTearParams p;
  p.lambda = p.beta;  // the tip stays at the start point while the drop grows
  const Vec3 start(0.03f, 1.6f, 0.1f);
  for (const Vec3& gravity : {Vec3(0.0f, -9.81f, 0.0f), Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 0.0f, 2.0f), Vec3(0.3f, -1.0f, 0.2f)}) {
    SCOPED_TRACE(testing::Message() << "gravity " << gravity.transpose());
    const float t = 0.75f;
    TriangleMesh mesh = makeDrippingTear(p, t, kRings, kSegments);
    placeDrippingTear(mesh, start, gravity);
    const Vec3 down = gravity.normalized();
    const Vec3 tip = mesh.positions.back(), lead = mesh.positions.front();
    EXPECT_LT((tip - start).norm(), 1e-6f);  // (lambda - beta) t = 0
    EXPECT_LT((lead - (start + down * (2.0f * p.beta * t))).norm(), 1e-6f);
    EXPECT_EQ(findMeshDefect(mesh), "");
    EXPECT_EQ(findClosedMeshDefect(mesh), "");
    EXPECT_GT(signedVolume(mesh), 0.0);  // a rotation keeps the winding outward
    // Every circle is centred on the axis: its mean lies on the line start + k down.
    for (int r = 1; r < kRings; ++r) {
      Vec3 mean = Vec3::Zero();
      for (int s = 0; s < kSegments; ++s) mean += mesh.positions[circleVertex(r, s)];
      mean /= float(kSegments);
      const Vec3 offset = mean - start;
      EXPECT_LT((offset - down * offset.dot(down)).norm(), 5e-6f) << "circle " << r;
    }
    // The leading apex normal points along gravity, the tip's against it.
    EXPECT_GT(mesh.normals.front().dot(down), 0.999f);
    EXPECT_LT(mesh.normals.back().dot(down), -0.999f);
  }
}

TEST(DrippingTear, FallingDropLeavesTheStartAlongGravity) {
  DrippingTearParams p;
  p.lambda = 1.0f;
  const Vec3 start(0.0f, 1.5f, 0.0f), gravity(0.0f, -1.0f, 0.0f);
  for (const float t : {0.5f, 1.0f}) {
    TriangleMesh mesh = makeDrippingTear(p, t, kRings, kSegments);
    placeDrippingTear(mesh, start, gravity);
    EXPECT_NEAR(mesh.positions.back().y(), 1.5f - (p.lambda - p.beta) * t, 1e-5f);
    EXPECT_NEAR(mesh.positions.front().y(), 1.5f - (p.lambda + p.beta) * t, 1e-5f);
  }
}

TEST(DrippingTear, SameInputsGiveBitwiseTheSameMesh) {
  DrippingTearParams p;
  p.alpha = 0.0007f;
  p.headAngle = 0.9f;
  for (const float t : {0.0f, 0.3f, 1.7f}) {
    TriangleMesh a = makeDrippingTear(p, t, 20, 30), b = makeDrippingTear(p, t, 20, 30);
    placeDrippingTear(a, Vec3(0.1f, 0.2f, 0.3f), Vec3(0.1f, -1.0f, 0.0f));
    placeDrippingTear(b, Vec3(0.1f, 0.2f, 0.3f), Vec3(0.1f, -1.0f, 0.0f));
    ASSERT_EQ(a.positions.size(), b.positions.size());
    ASSERT_EQ(a.indices, b.indices);
    for (size_t i = 0; i < a.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(std::bit_cast<uint32_t>(a.positions[i][k]), std::bit_cast<uint32_t>(b.positions[i][k]));
        ASSERT_EQ(std::bit_cast<uint32_t>(a.normals[i][k]), std::bit_cast<uint32_t>(b.normals[i][k]));
      }
  }
}

TEST(DrippingTear, OtherHeadAnglesStayClosedAndOriented) {
  DrippingTearParams p;
  for (const float angle : {0.05f, 0.5f, 1.2f, 1.5f}) {
    p.headAngle = angle;
    for (const float t : {0.0f, 2.0f}) {
      SCOPED_TRACE(testing::Message() << "headAngle " << angle << " t " << t);
      const TriangleMesh mesh = makeDrippingTear(p, t, 12, 8);
      ASSERT_EQ(findMeshDefect(mesh), "");
      EXPECT_EQ(findClosedMeshDefect(mesh), "");
      EXPECT_GT(signedVolume(mesh), 0.0);
    }
  }
  // The minimal tessellation is a closed double pyramid.
  const TriangleMesh tiny = makeDrippingTear(DrippingTearParams{}, 1.0f, 2, 3);
  EXPECT_EQ(tiny.vertexCount(), 5u);
  EXPECT_EQ(findClosedMeshDefect(tiny), "");
  EXPECT_GT(signedVolume(tiny), 0.0);
}

TEST(DrippingTear, RejectsBadInput) {
  const DrippingTearParams good;
  EXPECT_THROW(makeDrippingTear(good, NAN), InputError);
  EXPECT_THROW(makeDrippingTear(good, INFINITY), InputError);
  EXPECT_THROW(makeDrippingTear(good, 1.0f, 1, 8), InputError);
  EXPECT_THROW(makeDrippingTear(good, 1.0f, 8, 2), InputError);
  for (auto bad : {&DrippingTearParams::alpha, &DrippingTearParams::beta, &DrippingTearParams::minTime, &DrippingTearParams::headAngle}) {
    DrippingTearParams p = good;
    p.*bad = 0.0f;
    EXPECT_THROW(makeDrippingTear(p, 1.0f), InputError);
    p.*bad = NAN;
    EXPECT_THROW(makeDrippingTear(p, 1.0f), InputError);
  }
  DrippingTearParams p = good;
  p.headAngle = kPi / 2.0f;
  EXPECT_THROW(makeDrippingTear(p, 1.0f), InputError);
  p = good;
  p.lambda = INFINITY;
  EXPECT_THROW(makeDrippingTear(p, 1.0f), InputError);
  TriangleMesh mesh = makeDrippingTear(good, 1.0f, 4, 4);
  EXPECT_THROW(placeDrippingTear(mesh, Vec3::Zero(), Vec3::Zero()), InputError);
  EXPECT_THROW(placeDrippingTear(mesh, Vec3(NAN, 0, 0), Vec3(0, -1, 0)), InputError);
}

}  // namespace dripping_tear_test
}  // namespace lacrima
