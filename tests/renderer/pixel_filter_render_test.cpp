// The pixel filter in whole renders: a constant radiance stays exactly that constant with every
// filter and sample count (the weights normalize, negative lobes included), the filter spreads a
// sharp edge by the amount its profile says (so the offsets are centred on the pixel centre),
// and filtered renders stay bitwise independent of the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace pixel_filter_render_test {

const PixelFilter kFilters[] = {{FilterType::Box, 1.0f},
                                {FilterType::Gaussian, 3.0f},
                                {FilterType::BlackmanHarris, 1.5f},
                                {FilterType::Mitchell, 4.0f},
                                {FilterType::Mitchell, 2.0f}};

std::string nameOf(const PixelFilter& f) { return std::string(filterTypeName(f.type)) + " " + std::to_string(f.width); }

// Nothing but a uniform background, seen by the default camera (looking down -Z).
Frame emptyFrame(const Color& background, const PixelFilter& filter, int spp) {
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color(0.5f, 0.5f, 0.5f)}, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3(0, 0, 10), 0.1f, 0});  // behind the camera, never seen
  frame.uniformBackground = background;
  frame.settings.width = 24;
  frame.settings.height = 16;
  frame.settings.samplesPerPixel = spp;
  frame.settings.filter = filter;
  return frame;
}

TEST(PixelFilterRender, ConstantRadianceStaysThatConstantWithEveryFilter) {
  const Color background(0.3f, 0.6f, 0.9f);
  for (const PixelFilter& filter : kFilters) {
    // 2 and 3 samples: with Mitchell, weights of opposite signs can cancel in the denominator.
    for (int spp : {1, 2, 3, 7, 16}) {
      const Film film = renderFrame(emptyFrame(background, filter, spp));
      for (size_t p = 0; p < size_t(film.width) * film.height; ++p) {
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(film.rgba[4 * p + c], background[c], 1e-6f * background[c])
              << nameOf(filter) << ", " << spp << " spp, pixel " << p << " channel " << c;
        ASSERT_EQ(film.rgba[4 * p + 3], 0.0f) << nameOf(filter);
      }
    }
  }
}

// The left half of the view is an emitter of radiance 1 ending exactly on the pixel boundary
// at the image's middle column; the right half is black. A dark pixel whose centre is d pixels
// from the edge receives the part of the filter's mass beyond d: integral from d to r of f1.
TEST(PixelFilterRender, AnEdgeSpreadsAsTheFilterProfileSays) {
  Frame frame;
  frame.materials.push_back(Material{"emitter", DiffuseParams{Color::Zero()}, Color(1, 1, 1)});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(-5, 0, -1), Vec3(10, 0, 0), Vec3(0, 10, 0)), 0});
  frame.settings.width = 16;
  frame.settings.height = 8;
  frame.settings.samplesPerPixel = 256;
  frame.settings.maxDepth = 1;
  for (const PixelFilter filter : {PixelFilter{FilterType::Gaussian, 3.0f},
                                   PixelFilter{FilterType::BlackmanHarris, 1.5f}, PixelFilter{FilterType::Box, 1.0f}}) {
    frame.settings.filter = filter;
    const Film film = renderFrame(frame);
    const double r = 0.5 * filter.width;
    for (int column = 8; column < 11; ++column) {
      const double d = column - 8 + 0.5;  // pixel centre to the edge
      double expected = 0.0;               // integral of f1 over [d, r], midpoint rule
      constexpr int n = 20000;
      for (int k = 0; k < n && d < r; ++k) expected += filterProfile(filter, d + (r - d) * (k + 0.5) / n) * (r - d) / n;
      double mean = 0.0;
      for (int y = 0; y < film.height; ++y) mean += film.rgba[4 * film.pixelIndex(column, y)] / film.height;
      const int samples = film.height * 256;  // each sample lands on the emitter or not: weights are 1
      const double sd = std::sqrt(std::max(expected * (1.0 - expected), 1e-4) / samples);
      EXPECT_NEAR(mean, expected, 5.0 * sd + 1e-4) << nameOf(filter) << ", column " << column;
      // The lit side mirrors it.
      double lit = 0.0;
      for (int y = 0; y < film.height; ++y) lit += film.rgba[4 * film.pixelIndex(15 - column, y)] / film.height;
      EXPECT_NEAR(lit, 1.0 - expected, 5.0 * sd + 1e-4) << nameOf(filter) << ", column " << 15 - column;
    }
  }
}

TEST(PixelFilterRender, NegativeLobesStayBitwiseDeterministicAcrossThreadCounts) {
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color(0.6f, 0.5f, 0.4f)}, Color::Zero()});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 0, -4)), 0});
  frame.spheres.push_back(Sphere{Vec3(0, 0.35f, 0), 0.35f, 0});
  test::addTopLightAndView(frame);
  frame.settings.filter = PixelFilter{FilterType::Mitchell, 4.0f};
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  EXPECT_TRUE(test::bitwiseEqual(one.rgba, two.rgba));
}

}  // namespace pixel_filter_render_test
}  // namespace lacrima
