// The lacrimal meniscus strip thickening with the meniscus volume (meniscus_swelling.hpp): the
// swept volume equals the volume laid on, the thickness grows with the volume and falls off from
// the source, and nothing moves at volume 0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/meniscus_swelling.hpp"
#include "support/swept_volume.hpp"

namespace lacrima {
namespace meniscus_swelling_test {

// A strip 1.2 mm wide bent along an arc of radius 12 mm (like a lid margin), 4 cm long,
// counter-clockwise seen from +z with smooth normals, facing +z.
TriangleMesh lidStrip() {
  TriangleMesh mesh;
  const int along = 160, across = 4;
  const float radius = 0.012f, width = 0.0012f;
  for (int i = 0; i <= along; ++i)
    for (int j = 0; j <= across; ++j) {
      const float angle = -1.6f + 3.2f * float(i) / float(along);
      const float r = radius + width * (float(j) / float(across) - 0.5f);
      // A slight bulge towards +z in the middle of the width, like the meniscus's own rounding.
      const float x = float(j) / float(across) - 0.5f;
      mesh.positions.emplace_back(r * std::sin(angle), -r * std::cos(angle), 2e-4f * (1.0f - 4.0f * x * x));
    }
  for (int i = 0; i < along; ++i)
    for (int j = 0; j < across; ++j) {
      const uint32_t a = uint32_t(i * (across + 1) + j), b = a + 1, c = a + uint32_t(across + 1), d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  computeSmoothNormals(mesh);
  if (mesh.normals[0].z() < 0.0f)
    for (size_t t = 0; t < mesh.triangleCount(); ++t) std::swap(mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
  computeSmoothNormals(mesh);
  return mesh;
}

const Vec3 kSource(0.0f, -0.012f, 0.0f);  // the middle of the arc

TEST(MeniscusSwelling, SweptVolumeEqualsTheMeniscusVolume) {
  const TriangleMesh strip = lidStrip();
  const std::vector<float> weights = meniscusFalloffWeights(strip, kSource, 0.008f);
  for (double microlitres : {0.5, 2.0, 5.0, 8.0}) {
    TriangleMesh swollen = strip;
    const double volume = microlitres * 1e-9;
    const double peak = swellMeniscus(swollen, weights, volume);
    const double swept = test::sweptVolume(strip, swollen);
    std::printf("[ meniscus ] %.1f uL: peak thickness %.3f mm, swept %.4f uL\n", microlitres, peak * 1e3, swept * 1e9);
    // Measured with another split of the prisms into tetrahedra than the library's: their sides
    // are not planar, so the two measures differ slightly (0.5%).
    EXPECT_NEAR(swept, volume, 0.005 * volume) << microlitres;
    EXPECT_NEAR(sweptVolume(strip, swollen), volume, 1e-5 * volume) << microlitres;
    // The first-order thickness V / sum A w alone would miss by far on this strongly curved strip.
    double weightedArea = 0.0;
    const std::vector<double> areas = vertexAreas(strip);
    for (size_t v = 0; v < areas.size(); ++v) weightedArea += areas[v] * weights[v];
    if (microlitres >= 5.0) {
      EXPECT_LT(peak, 0.95 * volume / weightedArea) << microlitres;
    }
  }
}

TEST(MeniscusSwelling, ThicknessGrowsWithTheVolumeAndFallsOffFromTheSource) {
  const TriangleMesh strip = lidStrip();
  const std::vector<float> weights = meniscusFalloffWeights(strip, kSource, 0.008f);
  size_t nearest = 0, far = 0;
  for (size_t v = 0; v < strip.vertexCount(); ++v) {
    if ((strip.positions[v] - kSource).norm() < (strip.positions[nearest] - kSource).norm()) nearest = v;
    if ((strip.positions[v] - kSource).norm() > (strip.positions[far] - kSource).norm()) far = v;
  }
  double previousPeak = 0.0, previousNear = 0.0;
  for (double microlitres : {0.1, 1.0, 3.0, 6.0}) {
    TriangleMesh swollen = strip;
    const double peak = swellMeniscus(swollen, weights, microlitres * 1e-9);
    const double atSource = (swollen.positions[nearest] - strip.positions[nearest]).norm();
    EXPECT_GT(peak, previousPeak);
    EXPECT_GT(atSource, previousNear);
    EXPECT_EQ(swollen.positions[far], strip.positions[far]) << "beyond the falloff length nothing moves";
    // Along the outward normal.
    EXPECT_GT((swollen.positions[nearest] - strip.positions[nearest]).dot(strip.normals[nearest]), 0.99 * atSource);
    previousPeak = peak;
    previousNear = atSource;
  }
}

TEST(MeniscusSwelling, NothingMovesAtVolumeZero) {
  const TriangleMesh strip = lidStrip();
  TriangleMesh same = strip;
  EXPECT_EQ(swellMeniscus(same, meniscusFalloffWeights(strip, kSource, 0.008f), 0.0), 0.0);
  EXPECT_EQ(same.positions, strip.positions);
  EXPECT_EQ(same.normals, strip.normals);
}

TEST(MeniscusSwelling, FalloffWeightsAndVertexAreas) {
  const TriangleMesh strip = lidStrip();
  const std::vector<float> weights = meniscusFalloffWeights(strip, kSource, 0.008f);
  for (size_t v = 0; v < strip.vertexCount(); ++v) {
    const float d = (strip.positions[v] - kSource).norm() / 0.008f;
    EXPECT_NEAR(weights[v], d < 1.0f ? (1.0f - d * d) * (1.0f - d * d) : 0.0f, 1e-5f);
  }
  double total = 0.0, triangles = 0.0;
  for (double a : vertexAreas(strip)) total += a;
  for (size_t t = 0; t < strip.triangleCount(); ++t) {
    const uint32_t* v = &strip.indices[3 * t];
    const Vec3d a = strip.positions[v[0]].cast<double>();
    triangles += 0.5 * (strip.positions[v[1]].cast<double>() - a).cross(strip.positions[v[2]].cast<double>() - a).norm();
  }
  EXPECT_NEAR(total, triangles, 1e-6 * triangles);
  EXPECT_GT(total, 0.0012 * 0.012 * 3.2) << "the bent, bulging strip is larger than its flat width times length";
}

TEST(MeniscusSwelling, RejectsBadArguments) {
  TriangleMesh strip = lidStrip();
  EXPECT_THROW(meniscusFalloffWeights(strip, kSource, 0.0f), InputError);
  EXPECT_THROW(swellMeniscus(strip, std::vector<float>(3, 1.0f), 1e-9), InputError);
  EXPECT_THROW(swellMeniscus(strip, meniscusFalloffWeights(strip, kSource, 0.008f), -1e-9), InputError);
}

}  // namespace meniscus_swelling_test
}  // namespace lacrima
