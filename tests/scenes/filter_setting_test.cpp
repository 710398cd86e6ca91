// The `render.filter` key (docs/shot-format.md, "Pixel filter"): defaults, each type with its
// default and an explicit width, and one clear message at the JSON path for each bad value.
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace filter_setting_test {

using test::expectSingleError;
using test::shotWithRender;
using test::writeShot;

PixelFilter filterOf(const std::string& name, const std::string& renderExtra) {
  return loadShot(writeShot(name, shotWithRender(renderExtra))).render.filter;
}

void expectFilter(const PixelFilter& actual, FilterType type, float width) {
  EXPECT_EQ(actual.type, type);
  EXPECT_EQ(actual.width, width);
}

TEST(FilterSetting, DefaultsToBlackmanHarrisOfOneAndAHalfPixels) {
  expectFilter(filterOf("filter_default.json", ""), FilterType::BlackmanHarris, 1.5f);
}

TEST(FilterSetting, ReadsEachTypeWithItsDefaultOrGivenWidth) {
  expectFilter(filterOf("filter_bh.json", R"(, "filter": {"type": "blackman-harris"})"), FilterType::BlackmanHarris,
               1.5f);
  expectFilter(filterOf("filter_gauss.json", R"(, "filter": {"type": "gaussian"})"), FilterType::Gaussian, 3.0f);
  expectFilter(filterOf("filter_mitchell.json", R"(, "filter": {"type": "mitchell"})"), FilterType::Mitchell, 4.0f);
  expectFilter(filterOf("filter_box.json", R"(, "filter": {"type": "box"})"), FilterType::Box, 1.0f);
  expectFilter(filterOf("filter_gauss_w.json", R"(, "filter": {"type": "gaussian", "width": 2})"), FilterType::Gaussian,
               2.0f);
  expectFilter(filterOf("filter_bh_w.json", R"(, "filter": {"type": "blackman-harris", "width": 2.25})"),
               FilterType::BlackmanHarris, 2.25f);
  expectFilter(filterOf("filter_box_max.json", R"(, "filter": {"type": "box", "width": 16})"), FilterType::Box, 16.0f);
}

TEST(FilterSetting, BadValuesAreReportedAtTheirPath) {
  expectSingleError("filter_typo.json", shotWithRender(R"(, "filter": {"type": "gausian"})"),
                    "/render/filter/type: unknown filter type 'gausian'; did you mean 'gaussian'?");
  expectSingleError("filter_unknown.json", shotWithRender(R"(, "filter": {"type": "lanczos"})"),
                    "/render/filter/type: unknown filter type 'lanczos' (expected one of 'blackman-harris', "
                    "'gaussian', 'mitchell', 'box')");
  expectSingleError("filter_zero.json", shotWithRender(R"(, "filter": {"type": "box", "width": 0})"),
                    "/render/filter/width: expected a number in (0, 16], found 0");
  expectSingleError("filter_negative.json", shotWithRender(R"(, "filter": {"type": "mitchell", "width": -2})"),
                    "/render/filter/width: expected a number in (0, 16], found -2");
  expectSingleError("filter_absurd.json", shotWithRender(R"(, "filter": {"type": "gaussian", "width": 150})"),
                    "/render/filter/width: expected a number in (0, 16], found 150");
  expectSingleError("filter_width_string.json", shotWithRender(R"(, "filter": {"type": "box", "width": "1.5"})"),
                    "/render/filter/width: expected a number in (0, 16], found \"1.5\"");
  expectSingleError("filter_no_type.json", shotWithRender(R"(, "filter": {"width": 2})"),
                    "/render/filter: missing required key 'type' (one of 'blackman-harris', 'gaussian', 'mitchell', "
                    "'box')");
  expectSingleError("filter_string.json", shotWithRender(R"(, "filter": "gaussian")"),
                    "/render/filter: expected an object, found \"gaussian\"");
  expectSingleError("filter_unknown_key.json", shotWithRender(R"(, "filter": {"type": "box", "radius": 1})"),
                    "/render/filter/radius: unknown key 'radius' (allowed here: type, width)");
}

}  // namespace filter_setting_test
}  // namespace lacrima
