// Open dielectric sheets (MeshInstance::thinSheet, materials/thin_dielectric.hpp) in whole
// renders: a water sheet in a uniform furnace keeps the furnace's radiance (nothing lost, no
// medium entered), and a sheet lying a few micrometres on a surface, as the ICT face's tear line
// lies on the lid margin, does not hide that surface.
#include <gtest/gtest.h>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace thin_sheet_test {

// A 4 m water rectangle filling the view of a camera 1 m in front of it, tilted by 35 degrees,
// in a uniform white environment.
Frame sheetInFurnace(bool thinSheet) {
  Frame frame;
  frame.materials.push_back(Material{"water", SmoothDielectricParams{kTearIor, Color::Ones()}, Color::Zero()});
  MeshInstance sheet(makeRectangle(Vec3::Zero(), Vec3(4, 0, 0), Vec3(0, 4 * 0.819f, 4 * 0.574f)), 0);
  sheet.thinSheet = thinSheet;
  frame.meshes.push_back(sheet);
  frame.uniformBackground = Color::Ones();
  frame.camera = test::lookAt(Vec3(0, 0, 1.2f), Vec3::Zero(), 30.0f);
  frame.settings = test::smallSettings(16, 16, 8);
  return frame;
}

TEST(ThinSheet, AWaterSheetInAFurnaceKeepsItsRadiance) {
  // Reflected and transmitted light both see the white environment: R + T = 1 exactly.
  test::expectMean(renderFrame(sheetInFurnace(true)), 1.0, 1e-4);
}

TEST(ThinSheet, AsAClosedVolumeTheSameSheetWouldTrapThePathInWater) {
  // The same sheet as a volume boundary: the camera ray refracts into "water" and leaves to the
  // environment with the 1/n^2 radiance scaling, about half the furnace. What the thin sheet fixes.
  const test::MeanEstimate e = test::channelMean(renderFrame(sheetInFurnace(false)), 0);
  EXPECT_LT(e.mean, 0.7);
}

// A grey floor at y = 0 lit by a white sky, a black floor 1 cm below it, and a water sheet
// `gap` metres above the grey floor, parallel to it, seen from 1 m above at 40 degrees.
Frame sheetOnAFloor(float gap, bool withSheet) {
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color::Constant(0.5f)}, Color::Zero()});
  frame.materials.push_back(Material{"black", DiffuseParams{Color::Zero()}, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{kTearIor, Color::Ones()}, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  MeshInstance below = test::largeFloor(1);
  for (Vec3& p : below.mesh.positions) p.y() = -0.01f;
  frame.meshes.push_back(below);
  if (withSheet) {
    MeshInstance sheet = test::largeFloor(2);
    for (Vec3& p : sheet.mesh.positions) p.y() = gap;
    sheet.thinSheet = true;
    frame.meshes.push_back(sheet);
  }
  frame.uniformBackground = Color::Ones();
  frame.camera = test::lookAt(Vec3(0, 1.0f, 1.2f), Vec3(0, 0, 0), 20.0f);
  frame.settings = test::smallSettings(16, 64, 8);
  return frame;
}

TEST(ThinSheet, ASheetMicrometresAboveASurfaceDoesNotHideIt) {
  // 5 um: far inside the 1e-4-of-the-coordinates origin offset (100 um here) that a ray leaving
  // the sheet from an offset origin would jump, into the black floor below.
  const Film bare = renderFrame(sheetOnAFloor(0.0f, false));
  const Film covered = renderFrame(sheetOnAFloor(5e-6f, true));
  const double bareMean = test::channelMean(bare, 1).mean, coveredMean = test::channelMean(covered, 1).mean;
  EXPECT_GT(bareMean, 0.3);
  // The sheet only reflects a little sky (brighter) and dims what passes (darker): within 15 %.
  EXPECT_NEAR(coveredMean, bareMean, 0.15 * bareMean);
  for (size_t p = 0; p < covered.rgba.size(); p += 4) ASSERT_GT(covered.rgba[p + 1], 0.1f) << "pixel " << p / 4;
}

}  // namespace thin_sheet_test
}  // namespace lacrima
