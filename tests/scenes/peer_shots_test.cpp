// The shots of the Cycles peer comparison (tools/peers, docs/peers.md) stay loadable and inside
// what tools/peers/cycles_scene.py reproduces exactly: Lambertian and smooth water materials only
// (it approximates skin), and a single frame. The comparison itself needs Blender and is not in CI.
#include <gtest/gtest.h>

#include <variant>

#include "shot_support.hpp"

namespace lacrima {
namespace peer_shots_test {

class PeerShot : public ::testing::TestWithParam<const char*> {};

TEST_P(PeerShot, LoadsWithMaterialsCyclesMatchesExactly) {
  const Shot shot = loadShot(test::sourcePath(std::string("tools/peers/shots/") + GetParam()));
  EXPECT_EQ(shot.frameStart, shot.frameEnd);
  ASSERT_FALSE(shot.materials.empty());
  for (const Material& material : shot.materials) {
    const bool exact = std::holds_alternative<DiffuseParams>(material.params) ||
                       std::holds_alternative<SmoothDielectricParams>(material.params);
    EXPECT_TRUE(exact) << GetParam() << ": material '" << material.name << "' is one the peer only approximates";
  }
  const Frame frame = buildFrame(shot, shot.frameStart);
  EXPECT_FALSE(frame.meshes.empty() && frame.spheres.empty());
}

INSTANTIATE_TEST_SUITE_P(Shots, PeerShot,
                         ::testing::Values("sphere_in_studio.json", "tear_on_cheek.json", "rivulet_on_cheek.json"));

}  // namespace peer_shots_test
}  // namespace lacrima
