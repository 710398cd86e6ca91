// The default shot's story (scenes/shots/tear_closeup.json, docs/frames.md): its liquid tear
// overflows while the camera is on the eye (frames 38-48), and the drop hanging under the jaw lets
// go while the camera is on the jaw (frames 55-70) and falls clear of the skin. A change to the
// liquid model (sliding speeds, the path) can move the story out of its frames: this test says so,
// and the tear's wellStart / hangingContactRadius are then to be retuned.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lacrima/scenes/liquid_tear.hpp"
#include "shot_test_support.hpp"

namespace lacrima {
namespace {

class DefaultShotStory : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { shot_ = new Shot(loadShot(test::sourcePath("scenes/shots/tear_closeup.json"))); }
  static void TearDownTestSuite() {
    delete shot_;
    shot_ = nullptr;
  }
  static const ShotLiquidTear& tear() { return shot_->liquidTears.at(0); }
  static TearLiquidState stateAt(double frame) { return liquidTearStateAt(*shot_, tear(), frame); }

  static Shot* shot_;
};

Shot* DefaultShotStory::shot_ = nullptr;

TEST_F(DefaultShotStory, TheMeniscusOverflowsWhileTheCameraIsOnTheEye) {
  ASSERT_EQ(shot_->liquidTears.size(), 1u);
  int overflows = 0;
  for (int f = 39; f <= 48; ++f)
    if (stateAt(f).meniscusVolume < stateAt(f - 1).meniscusVolume) ++overflows;
  EXPECT_EQ(overflows, 1);
}

TEST_F(DefaultShotStory, TheHangingDropLetsGoOnCameraAndFallsClearOfTheSkin) {
  // Drops stay in the state once they fell (in the order they fell): the first new one.
  const size_t before = stateAt(shot_->frameStart).drops.size();
  int firstFall = 0;
  for (int f = shot_->frameStart + 1; f <= shot_->frameEnd && firstFall == 0; ++f)
    if (stateAt(f).drops.size() > before) firstFall = f;
  std::printf("[ story ] the first drop falls in frame %d\n", firstFall);
  ASSERT_GE(firstFall, 55);
  ASSERT_LE(firstFall, 70);
  // The skin as rendered at that frame; over the next two frames (quarter frames) every skin vertex
  // near the drop stays outside the drop as drawn (its ringing spheroid) by 5 % of its size: the
  // drop leaves the skin it hung from instead of passing through it.
  const Frame frame = buildFrame(*shot_, firstFall);
  const std::string skinName = "face/" + shot_->assets[0].gltf->primitives[tear().sourcePoint.primitive].name;
  const TriangleMesh* skin = nullptr;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == skinName) skin = &m.mesh;
  ASSERT_NE(skin, nullptr) << skinName;
  double closest = 1e9;  // the smallest ellipsoidal radius of a skin vertex (1: on the drop's surface)
  for (double f = firstFall; f <= firstFall + 2.0; f += 0.25) {
    const TearLiquidState state = stateAt(f);
    for (size_t d = before; d < state.drops.size(); ++d) {
      const DropView& drop = state.drops[d];
      for (const Vec3& v : skin->positions) {
        const Vec3d r = v.cast<double>() - drop.centre;
        if (r.norm() > 3.0 * drop.radius) continue;
        const double along = r.dot(drop.axis);
        const double across2 = std::max(0.0, r.squaredNorm() - along * along);
        const double e = drop.axes.equatorial, c = drop.axes.polar;
        closest = std::min(closest, std::sqrt(across2 / (e * e) + along * along / (c * c)));
      }
    }
  }
  std::printf("[ story ] closest skin vertex to the falling drop: %.3f of the drop's size\n", closest);
  EXPECT_GT(closest, 1.05);
}

}  // namespace
}  // namespace lacrima
