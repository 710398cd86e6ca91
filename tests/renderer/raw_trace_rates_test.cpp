// `lacrima bench`'s raw Embree rates: the packet rates (rtcIntersect16 / rtcOccluded16) must time
// the very rays the single-ray rates time, so both ways must find the same hits.
#include <gtest/gtest.h>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/bench.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace raw_trace_rates_test {

// A floor and an ellipsoid under a light, seen from the side: the camera rays hit and miss, and
// the bounces off the floor leave the scene or run into the ellipsoid, so neither count is trivial.
// 17 x 5 pixels at 3 samples: 255 camera rays, not a multiple of 16 (a packet with masked lanes).
Frame floorAndEllipsoid() {
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color(0.6f, 0.5f, 0.4f)}, Color::Zero()});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 0, -2)), 0});
  frame.meshes.push_back(
      MeshInstance{makeEllipsoid(Vec3(0.3f, 0.3f, 0), Mat3(Vec3(0.3f, 0.25f, 0.2f).asDiagonal()), 12, 24), 0});
  test::addTopLightAndView(frame);
  frame.settings.width = 17;
  frame.settings.height = 5;
  frame.settings.samplesPerPixel = 3;
  return frame;
}

TEST(RawTraceRates, PacketsOf16FindTheHitsSingleRaysFind) {
  const RawTraceRates rates = measureRawEmbreeThroughput(floorAndEllipsoid());
  EXPECT_EQ(rates.intersectRays, 255u + rates.occludedRays);  // the camera rays and a bounce per hit
  EXPECT_GT(rates.intersectHits, 0u);
  EXPECT_LT(rates.intersectHits, rates.intersectRays);
  EXPECT_EQ(rates.intersect16Hits, rates.intersectHits);
  EXPECT_GT(rates.occludedHits, 0u);
  EXPECT_LT(rates.occludedHits, rates.occludedRays);
  EXPECT_EQ(rates.occluded16Hits, rates.occludedHits);
  EXPECT_GT(rates.intersect16RaysPerSecond(), 0.0);
  EXPECT_GT(rates.occluded16RaysPerSecond(), 0.0);
}

}  // namespace raw_trace_rates_test
}  // namespace lacrima
