// Camera::focusOnSurface: the renderer focuses the thin lens on the first surface the view axis
// meets at mid-shutter, as a focus puller follows the subject. The distance is exact (a floor at
// a known depth, still and moving), the image is the one focused there by hand, and an axis that
// meets nothing keeps the given distance.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace focus_on_surface_test {

// The camera 1 m above the soft-shadow scene's floor (y = 0) and 2 m back, looking at a point
// 1 m below the floor: the view axis (0, -2, -4)/sqrt(20) meets the floor sqrt(20)/2 m away,
// half way to the look-at point (whose distance, sqrt(20), is the focus the shot would give).
const float kFloorDistance = std::sqrt(20.0f) / 2.0f;

Frame lensOverTheFloor() {
  Frame frame = test::softShadowFrame(30.0f);
  frame.camera = test::lookAt(Vec3(0, 1, 2), Vec3(0, -1, -2), 30.0f);
  frame.camera.lensRadius = 0.05f;
  frame.camera.focusDistance = 2.0f * kFloorDistance;
  frame.camera.focusOnSurface = true;
  frame.settings = test::smallSettings(16, 8, 2);
  return frame;
}

float focusOf(const Frame& frame, Film* film = nullptr) {
  RenderStats stats;
  Film image = renderFrame(frame, &stats);
  if (film) *film = std::move(image);
  return stats.focusDistance;
}

TEST(FocusOnSurface, FocusesOnTheFirstSurfaceOnTheViewAxis) {
  EXPECT_NEAR(focusOf(lensOverTheFloor()), kFloorDistance, 1e-5f);
}

TEST(FocusOnSurface, TheImageIsTheOneFocusedThereByHand) {
  Film focused, byHand, atLookAt;
  const float distance = focusOf(lensOverTheFloor(), &focused);
  Frame manual = lensOverTheFloor();
  manual.camera.focusOnSurface = false;
  manual.camera.focusDistance = distance;
  focusOf(manual, &byHand);
  EXPECT_TRUE(test::bitwiseEqual(focused.rgba, byHand.rgba));
  manual.camera.focusDistance = 2.0f * kFloorDistance;
  focusOf(manual, &atLookAt);
  EXPECT_FALSE(test::bitwiseEqual(focused.rgba, atLookAt.rgba)) << "the focus must change the picture";
}

// The floor rises 0.2 m over the shutter: at mid-shutter it is 0.1 m up, 0.9 of the way.
TEST(FocusOnSurface, AMovingSurfaceIsFocusedAtMidShutter) {
  Frame frame = lensOverTheFloor();
  MeshInstance& floor = frame.meshes[0];
  for (const Vec3& p : floor.mesh.positions) floor.positionsAtClose.push_back(p + Vec3(0, 0.2f, 0));
  EXPECT_NEAR(focusOf(frame), 0.9f * kFloorDistance, 1e-5f);
}

TEST(FocusOnSurface, APinholeHasNoFocusToFind) {
  Frame frame = lensOverTheFloor();
  frame.camera.lensRadius = 0.0f;
  EXPECT_EQ(focusOf(frame), 2.0f * kFloorDistance);
}

TEST(FocusOnSurface, AnAxisThatMeetsNothingKeepsTheGivenDistance) {
  Frame frame = lensOverTheFloor();
  frame.camera = test::lookAt(Vec3(0, 1, 2), Vec3(0, 1.5f, 3), 30.0f);  // up and away, over the light
  frame.camera.lensRadius = 0.05f;
  frame.camera.focusDistance = 1.25f;
  frame.camera.focusOnSurface = true;
  EXPECT_EQ(focusOf(frame), 1.25f);
}

}  // namespace focus_on_surface_test
}  // namespace lacrima
