// Extracting the region of a mesh around a polyline (surface_region.hpp): nearest-point queries
// and the shedding tear strip built on the region are bitwise those of the full mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "lacrima/base/error.hpp"
#include "lacrima/tears/shedding_tear.hpp"
#include "lacrima/mesh/surface_region.hpp"
#include "height_field_support.hpp"

namespace lacrima {
namespace surface_region_test {

constexpr int kGrid = 60;       // quads per side
constexpr float kHalf = 0.03f;  // the sheet spans [-3 cm, 3 cm]^2, 1 mm quads

// A wavy sheet (a cheek-like bump with ripples), counter-clockwise seen from +z.
TriangleMesh wavySheet() {
  return test::heightFieldMesh(kGrid, kHalf, [](float px, float py) {
    return 0.01f * std::exp(-(px * px + py * py) / 0.0004f) + 0.0004f * std::sin(400.0f * px) * std::cos(300.0f * py);
  });
}

// A path over the bump, snapped to the sheet; few points so its chords sag below the surface.
std::vector<SurfacePoint> pathOn(const TriangleMesh& mesh) {
  std::vector<SurfacePoint> path;
  for (const Vec3& p : {Vec3(-0.006f, 0.012f, 0.01f), Vec3(-0.001f, 0.007f, 0.01f), Vec3(0.002f, 0.002f, 0.01f),
                        Vec3(0.001f, -0.006f, 0.01f), Vec3(-0.002f, -0.014f, 0.01f)})
    path.push_back(closestSurfacePoint(mesh, p));
  return path;
}

std::vector<Vec3> positionsOf(const TriangleMesh& mesh, const std::vector<SurfacePoint>& points) {
  std::vector<Vec3> out;
  for (const SurfacePoint& p : points) out.push_back(surfacePosition(mesh, p));
  return out;
}

bool samePoint(const SurfacePoint& a, const SurfacePoint& b) {
  return a.triangle == b.triangle && std::memcmp(a.barycentric.data(), b.barycentric.data(), sizeof(Vec3)) == 0;
}

float distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const float f = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0f, 1.0f);
  return (p - (a + f * (b - a))).norm();
}

TEST(SurfaceRegion, KeepsTrianglesNearThePolylineInOrderWithTheirVertices) {
  const TriangleMesh sheet = wavySheet();
  const std::vector<Vec3> line = positionsOf(
      sheet, {closestSurfacePoint(sheet, Vec3(-0.01f, 0.005f, 0.01f)), closestSurfacePoint(sheet, Vec3(0.01f, 0.005f, 0.01f))});
  const float radius = 0.003f;
  const SurfaceRegion region = extractSurfaceRegion(sheet, line, radius);
  ASSERT_GT(region.fullTriangles.size(), 0u);
  EXPECT_LT(region.fullTriangles.size(), sheet.triangleCount() / 4);
  EXPECT_TRUE(std::is_sorted(region.fullTriangles.begin(), region.fullTriangles.end()));
  ASSERT_EQ(region.mesh.triangleCount(), region.fullTriangles.size());
  for (size_t t = 0; t < region.fullTriangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(region.mesh.positions[region.mesh.indices[3 * t + k]],
                sheet.positions[sheet.indices[3 * size_t(region.fullTriangles[t]) + k]]);
  // A triangle with a corner within the radius is kept; one whose corners are all farther than
  // the radius plus twice its longest edge (its bounding sphere's reach) is not.
  for (size_t t = 0; t < sheet.triangleCount(); ++t) {
    float nearest = 1.0f, longestEdge = 0.0f;
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = sheet.positions[sheet.indices[3 * t + size_t(k)]];
      const Vec3& b = sheet.positions[sheet.indices[3 * t + size_t(k + 1) % 3]];
      nearest = std::min(nearest, distanceToSegment(a, line[0], line[1]));
      longestEdge = std::max(longestEdge, (b - a).norm());
    }
    const bool kept = std::binary_search(region.fullTriangles.begin(), region.fullTriangles.end(), uint32_t(t));
    if (nearest <= radius) {
      EXPECT_TRUE(kept) << t;
    }
    if (nearest > radius + 2.0f * longestEdge) {
      EXPECT_FALSE(kept) << t;
    }
  }
  const SurfacePoint inRegion{3, Vec3(0.2f, 0.3f, 0.5f)};
  EXPECT_EQ(region.toFull(inRegion).triangle, region.fullTriangles[3]);
  ASSERT_TRUE(region.fromFull(region.toFull(inRegion)).has_value());
  EXPECT_TRUE(samePoint(*region.fromFull(region.toFull(inRegion)), inRegion));
  EXPECT_FALSE(region.fromFull(SurfacePoint{0, Vec3(1, 0, 0)}).has_value()) << "a corner of the sheet, far away";
  EXPECT_THROW(region.toFull(SurfacePoint{uint32_t(region.fullTriangles.size()), Vec3(1, 0, 0)}), InputError);
  EXPECT_THROW(extractSurfaceRegion(sheet, {}, 0.01f), InputError);
  EXPECT_THROW(extractSurfaceRegion(sheet, line, -1.0f), InputError);
}

TEST(SurfaceRegion, NearestPointsWithinTheGuaranteeAreThoseOfTheFullMesh) {
  const TriangleMesh sheet = wavySheet();
  const std::vector<Vec3> line = positionsOf(sheet, pathOn(sheet));
  const float radius = 0.004f;
  const SurfaceRegion region = extractSurfaceRegion(sheet, line, radius);
  int checked = 0;
  for (int i = 0; i < 400; ++i) {
    // Points around the polyline, some off the surface (deterministic spread).
    const float s = float(i) / 400.0f;
    const size_t seg = size_t(s * float(line.size() - 1));
    const float f = s * float(line.size() - 1) - float(seg);
    const Vec3 onLine = line[seg] + f * (line[seg + 1] - line[seg]);
    const Vec3 q = onLine + 0.0015f * Vec3(std::sin(7.0f * float(i)), std::cos(11.0f * float(i)), std::sin(3.0f * float(i)));
    const SurfacePoint full = closestSurfacePoint(sheet, q);
    if ((q - onLine).norm() + (q - surfacePosition(sheet, full)).norm() > radius) continue;
    ++checked;
    ASSERT_TRUE(samePoint(region.toFull(closestSurfacePoint(region.mesh, q)), full)) << "query " << i;
  }
  EXPECT_GT(checked, 300);
}

void expectSameStrip(const SheddingTearStrip& a, const SheddingTearStrip& b) {
  ASSERT_EQ(a.rows, b.rows);
  ASSERT_EQ(a.columns, b.columns);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (size_t k = 0; k < a.points.size(); ++k) ASSERT_TRUE(samePoint(a.points[k], b.points[k])) << "grid point " << k;
  EXPECT_EQ(a.coordinates, b.coordinates);
  EXPECT_EQ(a.thickness, b.thickness);
  EXPECT_EQ(a.length, b.length);
}

TEST(SurfaceRegion, SheddingTearStripOnTheRegionIsBitwiseTheFullMeshStrip) {
  const TriangleMesh sheet = wavySheet();
  const std::vector<SurfacePoint> path = pathOn(sheet);
  SheddingTearParams params;
  params.width = 0.005f;
  params.sampleSpacing = 0.001f;
  params.acrossSamples = 7;
  params.start = 0.0f;
  params.speed = 0.02f;
  params.noiseDensity = 0.3f;
  const std::vector<Vec3> line = positionsOf(sheet, path);
  const SurfaceRegion region = extractSurfaceRegion(sheet, line, stripRegionRadius(line, params.width));
  EXPECT_LT(region.fullTriangles.size(), sheet.triangleCount() / 3) << "a region, not the whole sheet";
  std::vector<SurfacePoint> regionPath;
  for (const SurfacePoint& p : path) {
    ASSERT_TRUE(region.fromFull(p).has_value());
    regionPath.push_back(*region.fromFull(p));
  }
  for (float t : {0.3f, 1.0f, 5.0f}) {
    SheddingTearStrip onRegion = buildSheddingTearStrip(region.mesh, regionPath, params, t);
    for (SurfacePoint& p : onRegion.points) p = region.toFull(p);
    const SheddingTearStrip onFull = buildSheddingTearStrip(sheet, path, params, t);
    ASSERT_GE(onFull.rows, 2) << "t = " << t;
    expectSameStrip(onRegion, onFull);
  }
  // The radius matters: a region of half the width loses grid points at the strip's edges.
  const SurfaceRegion narrow = extractSurfaceRegion(sheet, line, 0.25f * params.width);
  std::vector<SurfacePoint> narrowPath;
  for (const SurfacePoint& p : path) narrowPath.push_back(*narrow.fromFull(p));
  SheddingTearStrip onNarrow = buildSheddingTearStrip(narrow.mesh, narrowPath, params, 5.0f);
  const SheddingTearStrip onFull = buildSheddingTearStrip(sheet, path, params, 5.0f);
  size_t differing = 0;
  for (size_t k = 0; k < onFull.points.size(); ++k)
    differing += samePoint(narrow.toFull(onNarrow.points[k]), onFull.points[k]) ? 0 : 1;
  EXPECT_GT(differing, 0u);
}

}  // namespace surface_region_test
}  // namespace lacrima
