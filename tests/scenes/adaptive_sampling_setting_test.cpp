// The `render.adaptive` key (docs/shot-format.md, "Adaptive sampling").
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace adaptive_sampling_setting_test {

using test::expectSingleError;
using test::shotWithRender;
using test::writeShot;

AdaptiveSampling adaptiveOf(const std::string& name, const std::string& renderExtra) {
  return loadShot(writeShot(name, shotWithRender(renderExtra))).render.adaptive;
}

TEST(AdaptiveSamplingSetting, OffByDefaultOnWithDefaultsOrWithGivenValues) {
  EXPECT_FALSE(adaptiveOf("adaptive_default.json", "").enabled);
  EXPECT_FALSE(adaptiveOf("adaptive_false.json", R"(, "adaptive": false)").enabled);
  // The helper's shot has spp 1: the default minimum (16) comes down to the maximum.
  EXPECT_EQ(adaptiveOf("adaptive_true.json", R"(, "adaptive": true)"), (AdaptiveSampling{true, 0.01f, 1}));
  EXPECT_EQ(adaptiveOf("adaptive_object.json", R"(, "adaptive": {"threshold": 0.05})"),
            (AdaptiveSampling{true, 0.05f, 1}));
  EXPECT_EQ(adaptiveOf("adaptive_min.json", R"(, "adaptive": {"minSpp": 1})"), (AdaptiveSampling{true, 0.01f, 1}));
}

TEST(AdaptiveSamplingSetting, BadValuesAreReportedAtTheirPath) {
  expectSingleError("adaptive_zero.json", shotWithRender(R"(, "adaptive": {"threshold": 0})"),
                    "/render/adaptive/threshold: expected a number in (0, 1], found 0");
  expectSingleError("adaptive_min_over.json", shotWithRender(R"(, "adaptive": {"minSpp": 4})"),
                    "/render/adaptive/minSpp: minSpp 4 is more than spp 1, each pixel's maximum under adaptive "
                    "sampling");
  expectSingleError("adaptive_min_negative.json", shotWithRender(R"(, "adaptive": {"minSpp": -2})"),
                    "/render/adaptive/minSpp: expected an integer >= 1, found -2");
  expectSingleError("adaptive_typo.json", shotWithRender(R"(, "adaptive": {"treshold": 0.1})"),
                    "/render/adaptive/treshold: unknown key 'treshold'; did you mean 'threshold'?");
  expectSingleError("adaptive_type.json", shotWithRender(R"(, "adaptive": 0.01)"),
                    "/render/adaptive: expected an object, found 0.01");
}

}  // namespace adaptive_sampling_setting_test
}  // namespace lacrima
