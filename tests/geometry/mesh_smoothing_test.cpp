// Taubin lambda/mu smoothing: keeps the topology, removes a small random bump, leaves a plane and a
// wide bump (the large-scale shape) alone, holds the boundary and keeps welded seam copies together.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "geometry/height_field_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/mesh_smoothing.hpp"

namespace lacrima {
namespace mesh_smoothing_test {

using test::heightFieldMesh;

std::vector<uint32_t> identityWeld(const TriangleMesh& mesh) {
  std::vector<uint32_t> weld(mesh.positions.size());
  for (size_t i = 0; i < weld.size(); ++i) weld[i] = uint32_t(i);
  return weld;
}

// Deterministic noise in [-1, 1] per grid point (an integer hash, same on every platform).
float noise(float x, float y) {
  // Multiplied as unsigned: the signed product overflowed (UBSan); the wrapped value is the same.
  uint32_t h = (uint32_t(int32_t(std::lround(x * 1000.0f))) * 73856093u) ^
               (uint32_t(int32_t(std::lround(y * 1000.0f))) * 19349663u);
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return float(h % 20001u) / 10000.0f - 1.0f;
}

float plane(float x, float y) { return 0.3f * x - 0.2f * y + 0.1f; }

// Over the vertices at least 0.2 from the sheet's rim (the rim is held fixed, so it keeps its noise).
double rmsDeviation(const TriangleMesh& mesh, float (*reference)(float, float)) {
  double sum = 0.0;
  int count = 0;
  for (const Vec3& p : mesh.positions) {
    if (std::abs(p.x()) > 0.8f || std::abs(p.y()) > 0.8f) continue;
    sum += std::pow(double(p.z() - reference(p.x(), p.y())), 2);
    ++count;
  }
  return std::sqrt(sum / double(count));
}

TEST(TaubinSmoothing, KeepsTopologyAndTheOtherAttributes) {
  TriangleMesh mesh = heightFieldMesh(12, 1.0f, [](float x, float y) { return plane(x, y) + 0.05f * noise(x, y); });
  for (const Vec3& p : mesh.positions) mesh.uvs.emplace_back(p.x(), p.y());
  const TriangleMesh smoothed = taubinSmoothed(mesh, identityWeld(mesh));
  EXPECT_EQ(smoothed.indices, mesh.indices);
  EXPECT_EQ(smoothed.uvs, mesh.uvs);
  EXPECT_EQ(smoothed.positions.size(), mesh.positions.size());
  EXPECT_TRUE(smoothed.normals.empty());  // the input had none
  EXPECT_NE(smoothed.positions, mesh.positions);
}

TEST(TaubinSmoothing, RemovesARandomBumpButNotAPlane) {
  const TriangleMesh flat = heightFieldMesh(24, 1.0f, plane);
  const TriangleMesh flatSmoothed = taubinSmoothed(flat, identityWeld(flat));
  EXPECT_LT(rmsDeviation(flatSmoothed, plane), 1e-6);
  for (size_t i = 0; i < flat.positions.size(); ++i)
    EXPECT_LT((flatSmoothed.positions[i] - flat.positions[i]).norm(), 1e-5f) << i;

  const TriangleMesh bumpy = heightFieldMesh(24, 1.0f, [](float x, float y) { return plane(x, y) + 0.02f * noise(x, y); });
  const double before = rmsDeviation(bumpy, plane);
  const double after = rmsDeviation(taubinSmoothed(bumpy, identityWeld(bumpy)), plane);
  EXPECT_GT(before, 0.01);
  EXPECT_LT(after, before / 3.0) << before << " -> " << after;
}

TEST(TaubinSmoothing, KeepsTheLargeScaleShape) {
  // A bump 0.5 wide on a 48-cell sheet (about 12 edges across): Taubin's pass band keeps it.
  auto wide = [](float x, float y) { return 0.2f * std::exp(-(x * x + y * y) / (2.0f * 0.25f)); };
  const TriangleMesh mesh = heightFieldMesh(48, 1.0f, wide);
  const TriangleMesh smoothed = taubinSmoothed(mesh, identityWeld(mesh));
  float peak = 0.0f;
  for (const Vec3& p : smoothed.positions) peak = std::max(peak, p.z());
  EXPECT_GT(peak, 0.95f * 0.2f);
  EXPECT_LT(peak, 1.05f * 0.2f);
}

TEST(TaubinSmoothing, HoldsTheBoundaryAndKeepsWeldedCopiesTogether) {
  TriangleMesh mesh = heightFieldMesh(10, 1.0f, [](float x, float y) { return 0.05f * noise(x, y); });
  // Split the sheet along the column x = 0 (vertex 5 of each row) into two copies, as a UV seam does.
  std::vector<uint32_t> weld = identityWeld(mesh);
  const int columns = 11;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    float cx = 0.0f;
    for (int k = 0; k < 3; ++k) cx += mesh.positions[mesh.indices[3 * t + k]].x() / 3.0f;
    if (cx < 0.0f) continue;  // the left half keeps the original seam vertices
    for (int k = 0; k < 3; ++k) {
      uint32_t& v = mesh.indices[3 * t + k];
      if (v % columns != 5) continue;
      mesh.positions.push_back(mesh.positions[v]);
      weld.push_back(v);
      v = uint32_t(mesh.positions.size() - 1);
    }
  }
  const TriangleMesh smoothed = taubinSmoothed(mesh, weld);
  for (size_t v = 0; v < mesh.positions.size(); ++v) EXPECT_EQ(smoothed.positions[v], smoothed.positions[weld[v]]) << v;
  // The seam's interior vertices are not boundary: they move. The sheet's rim does not.
  EXPECT_NE(smoothed.positions[5 * columns + 5], mesh.positions[5 * columns + 5]);
  for (int i = 0; i < columns; ++i) {
    EXPECT_EQ(smoothed.positions[size_t(i)], mesh.positions[size_t(i)]);
    EXPECT_EQ(smoothed.positions[size_t(i * columns)], mesh.positions[size_t(i * columns)]);
  }
}

TEST(TaubinSmoothing, RejectsBadOptionsAndMaps) {
  const TriangleMesh mesh = heightFieldMesh(2, 1.0f, plane);
  EXPECT_THROW(taubinSmoothed(mesh, {0, 1}), InputError);
  EXPECT_THROW(taubinSmoothed(mesh, identityWeld(mesh), TaubinOptions{1, 0.5f, -0.4f}), InputError);
  EXPECT_THROW(taubinSmoothed(mesh, identityWeld(mesh), TaubinOptions{-1, 0.5f, -0.53f}), InputError);
}

}  // namespace mesh_smoothing_test
}  // namespace lacrima

namespace lacrima {
namespace mesh_smoothing_test {

// The smoother set up once (a liquid tear smooths every frame's deformation with it) is the same
// filter: bitwise taubinSmoothed on the mesh's own positions, and linear (smoothing a sum is the
// sum of the smoothings, up to rounding), which is what lets a pose be smoothed as a reference plus
// its deformation.
TEST(TaubinSmoother, IsTaubinSmoothedAndLinear) {
  const TriangleMesh bumpy = heightFieldMesh(16, 1.0f, [](float x, float y) { return plane(x, y) + 0.02f * noise(x, y); });
  const TaubinOptions options{5, 0.5f, -0.53f};
  const TaubinSmoother smoother(bumpy, identityWeld(bumpy), options);
  EXPECT_EQ(smoother.smoothed(bumpy.positions), taubinSmoothed(bumpy, identityWeld(bumpy), options).positions);
  std::vector<Vec3> deformation(bumpy.positions.size()), sum(bumpy.positions.size());
  for (size_t v = 0; v < deformation.size(); ++v) {
    deformation[v] = Vec3(0.01f * noise(bumpy.positions[v].y(), bumpy.positions[v].x()), 0.0f, 0.003f);
    sum[v] = bumpy.positions[v] + deformation[v];
  }
  const std::vector<Vec3> whole = smoother.smoothed(sum), base = smoother.smoothed(bumpy.positions),
                          part = smoother.smoothed(deformation);
  double worst = 0.0;
  for (size_t v = 0; v < whole.size(); ++v) worst = std::max(worst, double((whole[v] - base[v] - part[v]).norm()));
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(double((part[40] - deformation[40]).norm()), 1e-4);  // the deformation itself was smoothed
  EXPECT_THROW(smoother.smoothed(std::vector<Vec3>(3, Vec3::Zero())), InputError);
}

}  // namespace mesh_smoothing_test
}  // namespace lacrima
