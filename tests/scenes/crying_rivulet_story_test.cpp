// The story of the example shot scenes/shots/crying_rivulet.json (README, docs/frames.md): while
// the sob has the eye welling at 11 uL/s the tear runs from the inner corner down the cheek as one
// rivulet (frame 20), and after the crying has eased it has broken into a chain of beads down the
// cheek (frame 60), its last stretch still draining to the jaw. A change to the rivulet model or the shot's keys that moves the story out of those frames
// fails here, and the pictures are to be rendered again. The shot is loaded once (about 10 s):
// labelled slow.
#include <gtest/gtest.h>

#include <cstdio>

#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace crying_rivulet_story_test {

TEST(CryingRivuletStory, ASobRunsARivuletDownTheCheekThatBreaksIntoBeadsAsTheCryingEases) {
  const Shot shot = loadShot(test::sourcePath("scenes/shots/crying_rivulet.json"));
  FrameBuilder builder(shot);
  const LiquidTearState running = builder.liquidTearStateAt(0, 20);
  ASSERT_EQ(running.rivulets.size(), 1u);
  const RivuletView& rivulet = running.rivulets[0];
  std::printf("[ story ] frame 20: rivulet %.1f-%.1f mm down the path, %.2f uL; frame 60: ", rivulet.begin * 1e3,
              rivulet.end * 1e3, rivulet.volume / kMicrolitre);
  EXPECT_EQ(rivulet.begin, 0.0);  // from the lid
  EXPECT_GT(rivulet.end, 0.06);   // down the cheek
  const LiquidTearState eased = builder.liquidTearStateAt(0, 60);
  size_t beads = 0;
  for (const BeadView& bead : eased.beads) beads += bead.phase != BeadPhase::Hanging;
  std::printf("%zu rivulets, %zu beads on the cheek\n", eased.rivulets.size(), beads);
  for (const RivuletView& r : eased.rivulets)
    std::printf("[ story ] left: %.1f-%.1f mm, %.4f uL, %zu stations, widest %.3f mm\n", r.begin * 1e3, r.end * 1e3,
                r.volume / kMicrolitre, r.stations.size(), r.stations.front().halfWidth * 1e3);
  // Drained from the top: what still runs is its last stretch above the jaw.
  for (const RivuletView& r : eased.rivulets) EXPECT_GT(r.begin, 0.09);
  EXPECT_GE(beads, 5u);
}

}  // namespace crying_rivulet_story_test
}  // namespace lacrima
