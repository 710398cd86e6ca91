// Flow paths (steepest descent on triangle meshes): exact on planes, cylinders and a V-shaped
// crease, converging on a sphere, robust at vertices, edges, boundaries, seams and degenerate
// triangles, and bitwise repeatable.
#include "lacrima/mesh/surface_flow.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {
namespace surface_flow_test {

const Vec3 kDown(0.0f, -1.0f, 0.0f);

// Deterministic pseudo-random value in [-1, 1] for an integer pair.
float jitter(int i, int j, int salt) {
  uint32_t h = uint32_t(i) * 73856093u ^ uint32_t(j) * 19349663u ^ uint32_t(salt) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return float(h & 0xffffu) / 32767.5f - 1.0f;
}

// A grid of (n + 1)^2 vertices over params (u, v) in [0, 1]^2, interior vertices jittered by up
// to 0.3 cells, each cell split along a pseudo-randomly chosen diagonal.
struct Grid {
  int n;
  uint32_t vertex(int i, int j) const { return uint32_t(j * (n + 1) + i); }
};

template <typename Surface>
TriangleMesh jitteredGrid(int n, Surface surface) {
  TriangleMesh mesh;
  const Grid grid{n};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool interior = i > 0 && i < n && j > 0 && j < n;
      const float du = interior ? 0.3f * jitter(i, j, 1) : 0.0f, dv = interior ? 0.3f * jitter(i, j, 2) : 0.0f;
      mesh.positions.push_back(surface((float(i) + du) / float(n), (float(j) + dv) / float(n), i, j));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = grid.vertex(i, j), b = grid.vertex(i + 1, j), c = grid.vertex(i + 1, j + 1),
                     d = grid.vertex(i, j + 1);
      if (jitter(i, j, 3) > 0.0f)
        mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
      else
        mesh.indices.insert(mesh.indices.end(), {a, b, d, b, c, d});
    }
  return mesh;
}

// The inclined plane p = origin + u U + v V, u, v in [0, 1].
const Vec3 kOrigin(-0.5f, 0.3f, -0.5f), kU(1.0f, -0.4f, 0.1f), kV(0.2f, 0.3f, 1.0f);

TriangleMesh inclinedPlane(int n = 12) {
  return jitteredGrid(n, [](float u, float v, int, int) { return Vec3(kOrigin + u * kU + v * kV); });
}

Vec3 planeNormal() { return kU.cross(kV).normalized(); }

// Gravity projected onto the plane, unit length: the analytic steepest descent.
Vec3 planeDescent() {
  const Vec3 n = planeNormal();
  return (kDown - kDown.dot(n) * n).normalized();
}

float distanceToLine(const Vec3& p, const Vec3& origin, const Vec3& direction) {
  const Vec3 r = p - origin;
  return (r - r.dot(direction) * direction).norm();
}

void expectFiniteAndConsistent(const FlowPath& path) {
  ASSERT_FALSE(path.points.empty());
  ASSERT_EQ(path.positions.size(), path.points.size());
  ASSERT_EQ(path.arrival.size(), path.points.size());
  ASSERT_EQ(path.arcLength.size(), path.points.size());
  EXPECT_EQ(path.arcLength[0], 0.0f);
  for (size_t i = 0; i < path.points.size(); ++i) {
    EXPECT_TRUE(path.positions[i].allFinite()) << i;
    EXPECT_TRUE(path.points[i].barycentric.allFinite()) << i;
    EXPECT_GE(path.points[i].barycentric.minCoeff(), 0.0f) << i;
    EXPECT_NEAR(path.points[i].barycentric.sum(), 1.0f, 1e-6f) << i;
    if (i > 0) {
      EXPECT_GE(path.arcLength[i], path.arcLength[i - 1]) << i;
    }
  }
}

void expectOnPlaneDescentLine(const TriangleMesh& mesh, const FlowPath& path, const Vec3& d = planeDescent()) {
  const Vec3 p0 = path.positions[0];
  for (size_t i = 0; i < path.points.size(); ++i) {
    EXPECT_LT(distanceToLine(path.positions[i], p0, d), 1e-5f) << "point " << i;
    EXPECT_NEAR((path.positions[i] - p0).dot(d), path.arcLength[i], 1e-5f) << "point " << i;
    EXPECT_LT((surfacePosition(mesh, path.points[i]) - path.positions[i]).norm(), 1e-6f) << "point " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Plane
// ---------------------------------------------------------------------------------------------

TEST(FlowPathPlane, FollowsTheAnalyticSteepestDescentLineForTheRequestedLength) {
  const TriangleMesh mesh = inclinedPlane();
  const TriangleAdjacency adjacency = buildTriangleAdjacency(mesh);
  const SurfacePoint start = closestSurfacePoint(mesh, kOrigin + 0.1f * kU + 0.85f * kV);
  FlowPathOptions options;
  options.maxLength = 0.5f;
  const FlowPath path = traceFlowPath(mesh, adjacency, start, kDown, options);
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::MaxLength);
  EXPECT_FLOAT_EQ(path.length(), 0.5f);
  EXPECT_GT(path.points.size(), 6u) << "crosses several irregular triangles";
  expectOnPlaneDescentLine(mesh, path);
  EXPECT_LT((path.positions.back() - (path.positions[0] + 0.5f * planeDescent())).norm(), 1e-5f);
}

TEST(FlowPathPlane, StopsAtTheMeshBoundary) {
  const TriangleMesh mesh = inclinedPlane();
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh),
                                      closestSurfacePoint(mesh, kOrigin + 0.1f * kU + 0.85f * kV), kDown);
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::Boundary);
  expectOnPlaneDescentLine(mesh, path);
  // The end lies on the border of the parameter square.
  const Vec3 r = path.positions.back() - kOrigin;
  Eigen::Matrix<float, 3, 2> basis;
  basis << kU, kV;
  const Vec2 uv = basis.colPivHouseholderQr().solve(r);
  EXPECT_NEAR(std::min({uv.x(), uv.y(), 1.0f - uv.x(), 1.0f - uv.y()}), 0.0f, 1e-5f) << uv.transpose();
}

TEST(FlowPathPlane, FollowsTheMovedMeshWithTheRestAdjacency) {
  const TriangleMesh rest = inclinedPlane();
  const TriangleAdjacency adjacency = buildTriangleAdjacency(rest);
  const SurfacePoint start = closestSurfacePoint(rest, kOrigin + 0.1f * kU + 0.85f * kV);
  TriangleMesh moved = rest;
  const Affine3 tilt(Eigen::AngleAxisf(degreesToRadians(25.0f), Vec3(0.3f, 0.2f, 1.0f).normalized()));
  transformMesh(moved, tilt);
  FlowPathOptions options;
  options.maxLength = 0.3f;
  const FlowPath before = traceFlowPath(rest, adjacency, start, kDown, options);
  const FlowPath after = traceFlowPath(moved, adjacency, start, kDown, options);
  const Vec3 n = tilt.linear() * planeNormal();
  const Vec3 movedDescent = (kDown - kDown.dot(n) * n).normalized();
  EXPECT_EQ(after.stop, FlowStop::MaxLength);
  expectOnPlaneDescentLine(moved, after, movedDescent);
  EXPECT_GT((after.positions.back() - tilt * before.positions.back()).norm(), 0.02f)
      << "the path is recomputed on the moved surface, not carried along with it";
}

TEST(FlowPathPlane, StartsExactlyOnAVertexOrAnEdge) {
  const TriangleMesh mesh = inclinedPlane();
  const TriangleAdjacency adjacency = buildTriangleAdjacency(mesh);
  FlowPathOptions options;
  options.maxLength = 0.4f;
  const SurfacePoint onVertex = *vertexSurfacePoint(mesh, Grid{12}.vertex(5, 8));
  const SurfacePoint onEdge{222, Vec3(0.5f, 0.0f, 0.5f)};  // cell (3, 9)
  for (const SurfacePoint& start : {onVertex, onEdge}) {
    const FlowPath path = traceFlowPath(mesh, adjacency, start, kDown, options);
    expectFiniteAndConsistent(path);
    EXPECT_EQ(path.stop, FlowStop::MaxLength);
    EXPECT_FLOAT_EQ(path.length(), 0.4f);
    EXPECT_EQ(path.positions[0], surfacePosition(mesh, start));
    expectOnPlaneDescentLine(mesh, path);
  }
}

// A regular grid on y = -(x + z) / 2, x, z in [0, 1]: the descent runs along the diagonal x = z,
// through the grid's vertices. Cells are split along that diagonal or across it.
TriangleMesh diagonalSlope(bool splitAlongDescent) {
  constexpr int n = 10;
  TriangleMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float x = float(i) / n, z = float(j) / n;
      mesh.positions.emplace_back(x, -0.5f * (x + z), z);
    }
  const Grid grid{n};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = grid.vertex(i, j), b = grid.vertex(i + 1, j), c = grid.vertex(i + 1, j + 1),
                     d = grid.vertex(i, j + 1);
      if (splitAlongDescent)
        mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
      else
        mesh.indices.insert(mesh.indices.end(), {a, b, d, b, c, d});
    }
  return mesh;
}

TEST(FlowPathPlane, PassesExactlyThroughVerticesOnTheWay) {
  for (const bool along : {true, false}) {
    const TriangleMesh mesh = diagonalSlope(along);
    const FlowPath path =
        traceFlowPath(mesh, buildTriangleAdjacency(mesh), closestSurfacePoint(mesh, Vec3(0.05f, -0.05f, 0.05f)), kDown);
    expectFiniteAndConsistent(path);
    EXPECT_EQ(path.stop, FlowStop::Boundary) << along;
    int atVertex = 0;
    for (size_t i = 0; i < path.points.size(); ++i) {
      EXPECT_NEAR(path.positions[i].x(), path.positions[i].z(), 1e-6f) << along << " point " << i;
      const Vec3& w = path.points[i].barycentric;
      atVertex += int(w.x() == 0.0f) + int(w.y() == 0.0f) + int(w.z() == 0.0f) == 2;
    }
    EXPECT_EQ(atVertex, 10) << along << ": every diagonal vertex from (0.1, 0.1) to the corner";
    EXPECT_LT((path.positions.back() - Vec3(1, -1, 1)).norm(), 1e-6f) << along;
    EXPECT_NEAR(path.length(), std::sqrt(3.0f) * 0.95f, 1e-5f) << along;
  }
}

TEST(FlowPathPlane, GravityAlongTheNormalOrZeroIsFlat) {
  const TriangleMesh mesh = inclinedPlane();
  const TriangleAdjacency adjacency = buildTriangleAdjacency(mesh);
  const SurfacePoint start = closestSurfacePoint(mesh, kOrigin + 0.5f * kU + 0.5f * kV);
  for (const Vec3& gravity : {Vec3(-9.81f * planeNormal()), Vec3(2.0f * planeNormal()), Vec3(Vec3::Zero())}) {
    const FlowPath path = traceFlowPath(mesh, adjacency, start, gravity);
    expectFiniteAndConsistent(path);
    EXPECT_EQ(path.stop, FlowStop::Flat) << flowStopName(path.stop);
    EXPECT_EQ(path.points.size(), 1u);
    EXPECT_EQ(path.length(), 0.0f);
  }
}

TEST(FlowPathPlane, CrossesAUvSeamOnlyWhenWelded) {
  TriangleMesh mesh = inclinedPlane();
  const FlowPath reference = traceFlowPath(mesh, buildTriangleAdjacency(mesh),
                                           closestSurfacePoint(mesh, kOrigin + 0.1f * kU + 0.85f * kV), kDown);
  // Split the mesh along grid column 6: triangles right of it use copies of its vertices.
  const Grid grid{12};
  std::vector<uint32_t> copyOf(mesh.vertexCount(), TriangleAdjacency::kNone);
  for (int j = 0; j <= 12; ++j) {
    copyOf[grid.vertex(6, j)] = uint32_t(mesh.positions.size());
    mesh.positions.push_back(mesh.positions[grid.vertex(6, j)]);
  }
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    bool right = false;
    for (int c = 0; c < 3; ++c) right = right || int(mesh.indices[3 * t + c] % 13) > 6;
    if (right)
      for (int c = 0; c < 3; ++c)
        if (copyOf[mesh.indices[3 * t + c]] != TriangleAdjacency::kNone)
          mesh.indices[3 * t + c] = copyOf[mesh.indices[3 * t + c]];
  }
  const SurfacePoint start = reference.points[0];
  const FlowPath welded = traceFlowPath(mesh, buildTriangleAdjacency(mesh, findCoincidentVertices(mesh)), start, kDown);
  EXPECT_EQ(welded.stop, FlowStop::Boundary);
  EXPECT_LT((welded.positions.back() - reference.positions.back()).norm(), 1e-6f) << "same end as unsplit";
  const FlowPath split = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, kDown);
  EXPECT_EQ(split.stop, FlowStop::Boundary);
  EXPECT_LT(split.length(), reference.length() - 0.05f) << "stops at the seam";
  expectOnPlaneDescentLine(mesh, welded);
  expectOnPlaneDescentLine(mesh, split);
}

// ---------------------------------------------------------------------------------------------
// Sphere
// ---------------------------------------------------------------------------------------------

constexpr float kRadius = 0.7f;

// A UV sphere with its poles on the y axis; segment 0 starts at +x, longitude grows towards +z.
TriangleMesh uvSphere(int rings, int segments) {
  Mat3 axes;
  axes.col(0) = Vec3(kRadius, 0, 0);
  axes.col(1) = Vec3(0, 0, kRadius);
  axes.col(2) = Vec3(0, kRadius, 0);
  return makeEllipsoid(Vec3::Zero(), axes, rings, segments);
}

struct SphereRun {
  FlowPath path;
  float planeDeviation = 0.0f;  // largest distance to the vertical plane through start and y axis
};

// Starts at polar angle 0.6 rad, `facetFraction` of a facet's width into longitude column 0.
SphereRun runOnSphere(int rings, int segments, float facetFraction) {
  const TriangleMesh mesh = uvSphere(rings, segments);
  const float phi = facetFraction * 2.0f * kPi / float(segments), theta = 0.6f;
  const Vec3 onSphere =
      kRadius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  SphereRun run;
  run.path = traceFlowPath(mesh, buildTriangleAdjacency(mesh), closestSurfacePoint(mesh, onSphere), kDown);
  const Vec3 planeNormal = Vec3::UnitY().cross(run.path.positions[0]).normalized();
  for (const Vec3& p : run.path.positions)
    run.planeDeviation = std::max(run.planeDeviation, std::abs(planeNormal.dot(p)));
  return run;
}

void expectDescendsToTheSouthPole(const FlowPath& path) {
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::Pit) << flowStopName(path.stop);
  // Every piece descends (in float, the last micro-piece onto the pole may round to a tie).
  for (size_t i = 1; i < path.positions.size(); ++i) EXPECT_LE(path.positions[i].y(), path.positions[i - 1].y()) << i;
  EXPECT_LT(path.positions.back().y(), path.positions.front().y() - kRadius);
  EXPECT_LT((path.positions.back() - Vec3(0, -kRadius, 0)).norm(), 1e-6f);
}

TEST(FlowPathSphere, DescendsToTheBottomNearTheVerticalPlaneAndConvergesWithRefinement) {
  const SphereRun coarse = runOnSphere(32, 64, 0.25f);
  const SphereRun fine = runOnSphere(64, 128, 0.25f);
  expectDescendsToTheSouthPole(coarse.path);
  expectDescendsToTheSouthPole(fine.path);
  // Each flat facet sends the path along its own mid-meridian, a quarter facet from the start's:
  // the drift is at most R sin(quarter facet) and halves with the facet width.
  EXPECT_LT(coarse.planeDeviation, kRadius * std::sin(0.25f * 2.0f * kPi / 64.0f));
  EXPECT_LT(fine.planeDeviation, kRadius * std::sin(0.25f * 2.0f * kPi / 128.0f));
  EXPECT_LT(fine.planeDeviation, 0.6f * coarse.planeDeviation);
  RecordProperty("plane_deviation_over_R_64", std::to_string(coarse.planeDeviation / kRadius));
  RecordProperty("plane_deviation_over_R_128", std::to_string(fine.planeDeviation / kRadius));
  std::printf("sphere plane deviation / R: %.3g (64 segments), %.3g (128 segments)\n", coarse.planeDeviation / kRadius,
              fine.planeDeviation / kRadius);
}

TEST(FlowPathSphere, StartOnAFacetMidMeridianStaysInThePlane) {
  const SphereRun run = runOnSphere(32, 64, 0.5f);
  expectDescendsToTheSouthPole(run.path);
  EXPECT_LT(run.planeDeviation, 1e-5f * kRadius);
}

// ---------------------------------------------------------------------------------------------
// Cylinders
// ---------------------------------------------------------------------------------------------

// An open cylinder of radius R: `segments` generators at angles angle0 + 2 pi k / segments,
// `rows` bands along the axis (t in [-1, 1]); `place(angle, t)` gives the position.
template <typename Place>
TriangleMesh cylinder(int segments, int rows, float angle0, Place place) {
  TriangleMesh mesh;
  for (int r = 0; r <= rows; ++r)
    for (int s = 0; s < segments; ++s)
      mesh.positions.push_back(
          place(angle0 + 2.0f * kPi * float(s) / float(segments), -1.0f + 2.0f * float(r) / float(rows)));
  const auto v = [segments](int r, int s) { return uint32_t(r * segments + s % segments); };
  for (int r = 0; r < rows; ++r)
    for (int s = 0; s < segments; ++s)
      mesh.indices.insert(mesh.indices.end(),
                          {v(r, s), v(r, s + 1), v(r + 1, s + 1), v(r, s), v(r + 1, s + 1), v(r + 1, s)});
  return mesh;
}

TriangleMesh horizontalCylinder(float angle0) {
  return cylinder(40, 10, angle0,
                  [](float a, float t) { return Vec3(kRadius * std::cos(a), kRadius * std::sin(a), t); });
}

FlowPath runOnHorizontalCylinder(const TriangleMesh& mesh, float z0) {
  const Vec3 start(kRadius * std::cos(0.3f), kRadius * std::sin(0.3f), z0);
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh), closestSurfacePoint(mesh, start), kDown);
  expectFiniteAndConsistent(path);
  for (size_t i = 0; i < path.positions.size(); ++i) EXPECT_NEAR(path.positions[i].z(), z0, 1e-6f) << i;
  for (size_t i = 1; i < path.positions.size(); ++i) EXPECT_LT(path.positions[i].y(), path.positions[i - 1].y()) << i;
  return path;
}

TEST(FlowPathCylinder, HorizontalStaysInItsCrossSectionAndEndsOnTheBottomCrease) {
  // A generator at -pi/2: the bottom is a horizontal crease between two facets.
  const FlowPath path = runOnHorizontalCylinder(horizontalCylinder(-0.5f * kPi), 0.37f);
  EXPECT_EQ(path.stop, FlowStop::Pit) << flowStopName(path.stop);
  EXPECT_NEAR(path.positions.back().y(), -kRadius, 1e-6f);
  EXPECT_NEAR(path.positions.back().x(), 0.0f, 1e-6f);
}

TEST(FlowPathCylinder, HorizontalEndsAtTheEdgeOfAFlatBottomFacet) {
  // Generators at -pi/2 +- half a facet: the bottom is a horizontal facet.
  const float half = kPi / 40.0f;
  const FlowPath path = runOnHorizontalCylinder(horizontalCylinder(-0.5f * kPi + half), -0.61f);
  EXPECT_EQ(path.stop, FlowStop::Pit) << flowStopName(path.stop);
  EXPECT_NEAR(path.positions.back().y(), -kRadius * std::cos(half), 1e-6f);
  EXPECT_NEAR(path.positions.back().x(), kRadius * std::sin(half), 1e-6f) << "the upper edge of the bottom facet";
}

TEST(FlowPathCylinder, VerticalRunsStraightDownAGeneratorToTheOpenEnd) {
  const TriangleMesh mesh =
      cylinder(24, 7, 0.1f, [](float a, float t) { return Vec3(kRadius * std::cos(a), t, kRadius * std::sin(a)); });
  const SurfacePoint start = closestSurfacePoint(mesh, Vec3(kRadius * std::cos(1.0f), 0.8f, kRadius * std::sin(1.0f)));
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, kDown);
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::Boundary);
  const Vec3 p0 = path.positions[0];
  for (size_t i = 0; i < path.positions.size(); ++i) {
    EXPECT_NEAR(path.positions[i].x(), p0.x(), 1e-6f) << i;
    EXPECT_NEAR(path.positions[i].z(), p0.z(), 1e-6f) << i;
  }
  EXPECT_NEAR(path.positions.back().y(), -1.0f, 1e-6f);
  EXPECT_NEAR(path.length(), p0.y() + 1.0f, 1e-5f);
}

// ---------------------------------------------------------------------------------------------
// V-shaped valley: y = -s z + k |x|, a crease along x = 0 sloping down towards +z
// ---------------------------------------------------------------------------------------------

constexpr float kSlope = 0.5f, kFlank = 0.8f, kLength = 2.0f;

TriangleMesh vValley() {
  // Columns i in [0, 16] map to x in [-1, 1]; column 8 is the crease and is not jittered.
  return jitteredGrid(16, [](float u, float v, int i, int) {
    const float x = i == 8 ? 0.0f : 2.0f * u - 1.0f, z = kLength * v;
    return Vec3(x, -kSlope * z + kFlank * std::abs(x), z);
  });
}

// The analytic path from (x0, z0) on the right flank at arc length s.
Vec3 vValleyPath(float x0, float z0, float s) {
  const Vec3 flank = Vec3(-kFlank, -(kFlank * kFlank + kSlope * kSlope), kSlope).normalized();
  const Vec3 start(x0, -kSlope * z0 + kFlank * x0, z0);
  const float toCrease = x0 / -flank.x();
  if (s <= toCrease) return start + s * flank;
  return start + toCrease * flank + (s - toCrease) * Vec3(0, -kSlope, 1).normalized();
}

TEST(FlowPathValley, ReachesTheCreaseAndFollowsItDownhill) {
  const TriangleMesh mesh = vValley();
  const float x0 = 0.6f, z0 = 0.2f;
  const SurfacePoint start = closestSurfacePoint(mesh, Vec3(x0, -kSlope * z0 + kFlank * x0, z0));
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, kDown);
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::Boundary) << "runs off the far end of the crease";
  int onCrease = 0;
  for (size_t i = 0; i < path.positions.size(); ++i) {
    EXPECT_LT((path.positions[i] - vValleyPath(x0, z0, path.arcLength[i])).norm(), 1e-5f) << "point " << i;
    onCrease += std::abs(path.positions[i].x()) < 1e-6f;
  }
  EXPECT_GE(onCrease, 8) << "the path walks along the crease's edges";
  EXPECT_LT((path.positions.back() - Vec3(0, -kSlope * kLength, kLength)).norm(), 1e-5f);
}

TEST(FlowPathValley, ResamplingGivesEvenlySpacedPointsOnTheBentPath) {
  const TriangleMesh mesh = vValley();
  const float x0 = 0.6f, z0 = 0.2f, spacing = 0.05f;
  const SurfacePoint start = closestSurfacePoint(mesh, Vec3(x0, -kSlope * z0 + kFlank * x0, z0));
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, kDown);
  const std::vector<SurfacePoint> samples = resampleFlowPath(path, spacing);
  const size_t whole = size_t(std::floor(path.length() / spacing));
  ASSERT_EQ(samples.size(), whole + 2) << "every spacing, plus the end";
  for (size_t k = 0; k <= whole; ++k)
    EXPECT_LT((surfacePosition(mesh, samples[k]) - vValleyPath(x0, z0, float(k) * spacing)).norm(), 2e-5f) << k;
  EXPECT_LT((surfacePosition(mesh, samples.back()) - path.positions.back()).norm(), 1e-6f);
}

// ---------------------------------------------------------------------------------------------
// Robustness
// ---------------------------------------------------------------------------------------------

TEST(FlowPathRobustness, DegenerateTrianglesAreSkipped) {
  const TriangleMesh clean = inclinedPlane();
  TriangleMesh mesh = clean;
  const SurfacePoint start = closestSurfacePoint(mesh, kOrigin + 0.1f * kU + 0.85f * kV);
  // A sliver on every edge of every triangle (a new vertex at the edge's midpoint), a triangle
  // using a vertex twice, and a triangle collapsed to a point.
  const size_t triangles = mesh.triangleCount();
  for (size_t t = 0; t < triangles; ++t)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = mesh.indices[3 * t + e], b = mesh.indices[3 * t + (e + 1) % 3];
      mesh.positions.push_back(0.5f * (mesh.positions[a] + mesh.positions[b]));
      mesh.indices.insert(mesh.indices.end(), {a, b, uint32_t(mesh.positions.size() - 1)});
    }
  mesh.indices.insert(mesh.indices.end(), {5, 5, 6});
  for (int k = 0; k < 3; ++k) mesh.positions.push_back(Vec3(0.1f, 0.2f, 0.3f));
  const uint32_t p = uint32_t(mesh.positions.size());
  mesh.indices.insert(mesh.indices.end(), {p - 3, p - 2, p - 1});

  const FlowPath reference = traceFlowPath(clean, buildTriangleAdjacency(clean), start, kDown);
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, kDown);
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::Boundary);
  ASSERT_EQ(path.positions.size(), reference.positions.size());
  for (size_t i = 0; i < path.positions.size(); ++i) EXPECT_EQ(path.positions[i], reference.positions[i]) << i;

  // Starting inside a zero-area triangle: nowhere to go, and no NaN.
  const uint32_t collapsed = uint32_t(mesh.triangleCount() - 1);
  const FlowPath stuck = traceFlowPath(mesh, buildTriangleAdjacency(mesh), {collapsed, Vec3(0.2f, 0.3f, 0.5f)}, kDown);
  expectFiniteAndConsistent(stuck);
  EXPECT_EQ(stuck.stop, FlowStop::Degenerate);
  EXPECT_EQ(stuck.points.size(), 1u);
}

TEST(FlowPathRobustness, MaxStepsBoundsThePath) {
  const TriangleMesh mesh = uvSphere(16, 32);
  FlowPathOptions options;
  options.maxSteps = 3;
  const FlowPath path = traceFlowPath(mesh, buildTriangleAdjacency(mesh),
                                      closestSurfacePoint(mesh, Vec3(0.3f, 0.6f, 0.1f)), kDown, options);
  expectFiniteAndConsistent(path);
  EXPECT_EQ(path.stop, FlowStop::MaxSteps);
  EXPECT_EQ(path.points.size(), 4u);
}

TEST(FlowPathRobustness, SameInputGivesBitwiseTheSameOutput) {
  const TriangleMesh mesh = uvSphere(24, 48);
  const SurfacePoint start = closestSurfacePoint(mesh, Vec3(0.3f, 0.6f, 0.1f));
  const Vec3 gravity(0.3f, -9.0f, 1.2f);
  const FlowPath a = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, gravity);
  const FlowPath b = traceFlowPath(mesh, buildTriangleAdjacency(mesh), start, gravity);
  ASSERT_EQ(a.points.size(), b.points.size());
  ASSERT_GT(a.points.size(), 10u);
  EXPECT_EQ(a.stop, b.stop);
  EXPECT_EQ(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.arcLength.data(), b.arcLength.data(), a.arcLength.size() * sizeof(float)), 0);
  for (size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].triangle, b.points[i].triangle);
    EXPECT_EQ(std::memcmp(a.points[i].barycentric.data(), b.points[i].barycentric.data(), sizeof(Vec3)), 0);
  }
}

TEST(FlowPathRobustness, RejectsInvalidInput) {
  const TriangleMesh mesh = inclinedPlane(4);
  const TriangleAdjacency adjacency = buildTriangleAdjacency(mesh);
  const SurfacePoint start{0, Vec3(0.2f, 0.3f, 0.5f)};
  const float nan = std::nanf("");
  EXPECT_THROW(traceFlowPath(mesh, adjacency, start, Vec3(0, nan, 0)), InputError);
  EXPECT_THROW(traceFlowPath(mesh, adjacency, {999, Vec3(1, 0, 0)}, kDown), InputError);
  EXPECT_THROW(traceFlowPath(mesh, adjacency, {0, Vec3(0.7f, 0.7f, 0.7f)}, kDown), InputError);
  EXPECT_THROW(traceFlowPath(inclinedPlane(5), adjacency, start, kDown), InputError) << "another topology";
  FlowPathOptions options;
  options.maxLength = -1.0f;
  EXPECT_THROW(traceFlowPath(mesh, adjacency, start, kDown, options), InputError);
  options = {};
  options.maxSteps = 0;
  EXPECT_THROW(traceFlowPath(mesh, adjacency, start, kDown, options), InputError);
  EXPECT_THROW(buildTriangleAdjacency(mesh, std::vector<uint32_t>(3, 0)), InputError);
  EXPECT_THROW(resampleFlowPath(FlowPath{}, 0.0f), InputError);
  EXPECT_TRUE(resampleFlowPath(FlowPath{}, 0.1f).empty());
}

// ---------------------------------------------------------------------------------------------
// Adjacency
// ---------------------------------------------------------------------------------------------

TEST(TriangleAdjacency, LinksSharedEdgesBothWaysAndListsVertexStars) {
  const TriangleMesh mesh = uvSphere(8, 12);
  const TriangleAdjacency adjacency = buildTriangleAdjacency(mesh);
  ASSERT_EQ(adjacency.twin.size(), mesh.indices.size());
  for (size_t h = 0; h < adjacency.twin.size(); ++h) {
    const uint32_t twin = adjacency.twin[h];
    ASSERT_NE(twin, TriangleAdjacency::kNone) << "the sphere is closed";
    EXPECT_EQ(adjacency.twin[twin], h);
    const size_t t = h / 3, e = h % 3, u = twin / 3, f = twin % 3;
    EXPECT_EQ(mesh.indices[3 * t + e], mesh.indices[3 * u + (f + 1) % 3]) << "opposite orientation";
    EXPECT_EQ(mesh.indices[3 * t + (e + 1) % 3], mesh.indices[3 * u + f]);
  }
  const uint32_t pole = 0;  // the north pole touches `segments` triangles
  EXPECT_EQ(adjacency.starOffsets[pole + 1] - adjacency.starOffsets[pole], 12u);
  for (uint32_t i = adjacency.starOffsets[pole]; i < adjacency.starOffsets[pole + 1]; ++i)
    EXPECT_EQ(mesh.indices[adjacency.starCorners[i]], pole);
}

// ---------------------------------------------------------------------------------------------
// The ICT face skin (UV seams welded): a real mesh
// ---------------------------------------------------------------------------------------------

TEST(FlowPathIctFace, PathsFromManyStartsDescendAndEndCleanly) {
  const GltfAsset asset = loadGltfAsset(test::faceAssetPath());
  const auto skin = std::find_if(asset.primitives.begin(), asset.primitives.end(),
                                 [](const GltfPrimitive& p) { return p.part == "M_Face"; });
  ASSERT_NE(skin, asset.primitives.end());
  const TriangleMesh& mesh = skin->mesh;
  const TriangleAdjacency welded = buildTriangleAdjacency(mesh, skin->weldMap);
  const TriangleAdjacency unwelded = buildTriangleAdjacency(mesh);
  int pits = 0, boundaries = 0, flats = 0, seamStops = 0;
  size_t pieces = 0;
  for (uint32_t t = 0; t < mesh.triangleCount(); t += 61) {
    const SurfacePoint start{t, Vec3(0.2f, 0.3f, 0.5f)};
    const FlowPath path = traceFlowPath(mesh, welded, start, kDown);
    expectFiniteAndConsistent(path);
    ASSERT_TRUE(path.stop == FlowStop::Pit || path.stop == FlowStop::Boundary || path.stop == FlowStop::Flat)
        << "triangle " << t << ": " << flowStopName(path.stop);
    for (size_t i = 1; i < path.positions.size(); ++i)
      ASSERT_LE(path.positions[i].y(), path.positions[i - 1].y() + 1e-7f) << "triangle " << t << ", point " << i;
    pits += path.stop == FlowStop::Pit;
    boundaries += path.stop == FlowStop::Boundary;
    flats += path.stop == FlowStop::Flat;
    pieces += path.points.size() - 1;
    // Without welding, the same start can stop early at a UV seam, never go further.
    const FlowPath cut = traceFlowPath(mesh, unwelded, start, kDown);
    EXPECT_LE(cut.length(), path.length() + 1e-6f) << "triangle " << t;
    seamStops += cut.length() < path.length() - 1e-6f;
  }
  EXPECT_GT(seamStops, 0) << "some paths cross a UV seam of the face";
  std::printf("ICT face: %d pits, %d boundary, %d flat, %zu pieces; %d paths cross a UV seam\n", pits, boundaries,
              flats, pieces, seamStops);
}

}  // namespace surface_flow_test
}  // namespace lacrima
