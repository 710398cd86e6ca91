// Liquid tears and the face around them: the lacrimal fluid strip (M_LacrimalFluid)
// swells by the simulated meniscus volume near the tear's source and relaxes after the overflow;
// the skin along the flow path is refined ("trailRefinement") so the per-vertex wet trail
// resolves; exact messages for a bad "trailRefinement".
#include <gtest/gtest.h>

#include <chrono>

#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "shot_support.hpp"
#include "support/swept_volume.hpp"

namespace lacrima {
namespace liquid_meniscus_trail_test {

using test::ictFaceShot;
using test::writeShot;

// The default shot's tear (left inner eye corner, landmark 42): 6 uL/s from frame 1, overflow at
// 8 uL (1.33 s, frame 33) spilling 6 uL.
const std::string kTear =
    R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 42}, "material": "water",
       "rate": 6, "overflowVolume": 8, "spillVolume": 6}])";
constexpr int kFrames = 48;

Shot loadTearShot(const std::string& name, const std::string& tear = kTear) {
  return loadShot(writeShot(name, ictFaceShot(tear, "", "", kFrames)));
}

// The rendered mesh of a primitive of the face.
const TriangleMesh& primitiveOf(const Frame& frame, const Shot& shot, size_t primitive) {
  const std::string name = "face/" + shot.assets[0].gltf->primitives[primitive].name;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == name) return m.mesh;
  ADD_FAILURE() << "no mesh " << name;
  return frame.meshes.front().mesh;
}

double largestDisplacement(const TriangleMesh& from, const TriangleMesh& to) {
  double largest = 0.0;
  for (size_t v = 0; v < from.vertexCount(); ++v)
    largest = std::max(largest, double((to.positions[v] - from.positions[v]).norm()));
  return largest;
}

TEST(LiquidTearMeniscus, TheStripNearTheSourceIsFound) {
  const Shot shot = loadTearShot("meniscus_found.json");
  const ShotLiquidTear& tear = shot.liquidTears[0];
  ASSERT_GE(tear.meniscusPrimitive, 0);
  EXPECT_EQ(shot.assets[0].gltf->primitives[size_t(tear.meniscusPrimitive)].part, "M_LacrimalFluid");
  size_t weighted = 0;
  for (float w : tear.meniscusWeights) weighted += w > 0.0f;
  EXPECT_GT(weighted, 10u);
  EXPECT_LT(weighted, tear.meniscusWeights.size()) << "only near the source";
  // A source far from the eyes (the cheek, a point) swells no strip.
  const Shot cheek = loadTearShot("meniscus_cheek.json", test::replaced(kTear, R"({"landmark": 42})", "[0.035, 0.0, 0.1]"));
  EXPECT_EQ(cheek.liquidTears[0].meniscusPrimitive, -1);
}

TEST(LiquidTearMeniscus, SwellsByTheSimulatedVolumeThenRelaxesAfterTheOverflow) {
  const Shot shot = loadTearShot("meniscus_swell.json");
  const Shot dry = loadTearShot("meniscus_dry.json", "");  // no tear: the strip as posed
  const ShotLiquidTear& tear = shot.liquidTears[0];
  const size_t strip = size_t(tear.meniscusPrimitive);
  const TriangleMesh rest = primitiveOf(buildFrame(dry, 1), dry, strip);
  // Frame 1 is t = 0: no meniscus yet, the strip as without the tear, bitwise.
  FrameBuilder builder(shot);
  const TriangleMesh atStart = primitiveOf(builder.build(1), shot, strip);
  EXPECT_EQ(atStart.positions, rest.positions);
  EXPECT_EQ(atStart.normals, rest.normals);

  double previous = 0.0;
  for (int f : {4, 10, 20, 32}) {
    const double volume = builder.liquidTearStateAt(0, f).meniscusVolume;
    const TriangleMesh swollen = primitiveOf(builder.build(f), shot, strip);
    const double swept = test::sweptVolume(rest, swollen);
    const double thickness = largestDisplacement(rest, swollen);
    std::printf("[ meniscus ] frame %d: %.2f uL, swept %.3f uL, thickest %.3f mm\n", f, volume * 1e9, swept * 1e9,
                thickness * 1e3);
    // The library solves for the volume with one split of its prisms into tetrahedra, this test
    // measures with another (non-planar prism sides differ slightly) and float vertices: 1%.
    EXPECT_NEAR(swept, volume, 0.01 * volume) << f;
    EXPECT_GT(thickness, previous) << f;
    previous = thickness;
  }
  // After the overflow at 8 uL (frame 33) the meniscus holds 2 uL: the strip relaxes.
  const double after = largestDisplacement(rest, primitiveOf(builder.build(35), shot, strip));
  EXPECT_LT(after, 0.5 * previous);
  EXPECT_GT(after, 0.0);
}

TEST(LiquidTearTrail, SkinAlongThePathIsRefinedWithoutChangingItsShape) {
  std::vector<size_t> triangles;
  for (int levels : {0, 1, 2}) {
    const auto start = std::chrono::steady_clock::now();
    const Shot shot = loadTearShot("trail_" + std::to_string(levels) + ".json",
                                   test::replaced(kTear, R"("spillVolume": 6)",
                                                  R"("spillVolume": 6, "trailRefinement": )" + std::to_string(levels)));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const ShotLiquidTear& tear = shot.liquidTears[0];
    triangles.push_back(shot.assets[0].gltf->primitives[tear.sourcePoint.primitive].mesh.triangleCount());
    std::printf("[ trail ] trailRefinement %d: %zu skin triangles, path %.4f m, loaded in %.2f s\n", levels,
                triangles.back(), tear.path.length(), seconds);
    if (levels > 0) {
      EXPECT_GT(triangles.back(), triangles[size_t(levels) - 1]);
    }
  }
  // The path is traced on the smoothed skin carried over to the refined vertices: it runs where it
  // ran on the unrefined skin (same length to 1%).
  const Shot coarse = loadTearShot("trail_c.json", test::replaced(kTear, R"("spillVolume": 6)",
                                                                  R"("spillVolume": 6, "trailRefinement": 0)"));
  const Shot fine = loadTearShot("trail_f.json", kTear);  // the default, 2 levels
  const FlowPath& a = coarse.liquidTears[0].path;
  const FlowPath& b = fine.liquidTears[0].path;
  EXPECT_NEAR(b.length(), a.length(), 0.01 * a.length());
  EXPECT_LT((b.positions.back() - a.positions.back()).norm(), 1e-3f);
}

TEST(LiquidTearTrail, BadTrailRefinementGivesAnExactMessage) {
  auto expect = [](const std::string& name, const std::string& value, const std::string& message) {
    test::expectSingleError(
        name, ictFaceShot(test::replaced(kTear, R"("spillVolume": 6)", R"("spillVolume": 6, "trailRefinement": )" + value),
                          "", "", kFrames),
        message);
  };
  expect("trail_4.json", "4", "/tears/0/trailRefinement: expected an integer in [0, 3], found 4");
  expect("trail_half.json", "1.5", "/tears/0/trailRefinement: expected an integer in [0, 3], found 1.5");
}

}  // namespace liquid_meniscus_trail_test
}  // namespace lacrima
