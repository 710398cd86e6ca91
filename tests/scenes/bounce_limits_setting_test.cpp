// The `render.bounces` key (docs/shot-format.md, "Bounce limits").
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace bounce_limits_setting_test {

using test::expectSingleError;
using test::shotWithRender;
using test::writeShot;

BounceLimits bouncesOf(const std::string& name, const std::string& renderExtra) {
  return loadShot(writeShot(name, shotWithRender(renderExtra))).render.bounces;
}

TEST(BounceLimitsSetting, DefaultsToNoLimitAndReadsEachKind) {
  EXPECT_EQ(bouncesOf("bounces_default.json", ""), BounceLimits{});
  EXPECT_EQ(bouncesOf("bounces_all.json", R"(, "bounces": {"diffuse": 4, "glossy": 2, "transmission": 12})"),
            (BounceLimits{4, 2, 12}));
  // A kind left out keeps no limit.
  const BounceLimits some = bouncesOf("bounces_some.json", R"(, "bounces": {"glossy": 0})");
  EXPECT_EQ(some, (BounceLimits{BounceLimits::kUnlimited, 0, BounceLimits::kUnlimited}));
}

TEST(BounceLimitsSetting, BadValuesAreReportedAtTheirPath) {
  expectSingleError("bounces_negative.json", shotWithRender(R"(, "bounces": {"diffuse": -1})"),
                    "/render/bounces/diffuse: expected an integer in [0, 1024], found -1");
  expectSingleError("bounces_fraction.json", shotWithRender(R"(, "bounces": {"glossy": 2.5})"),
                    "/render/bounces/glossy: expected an integer in [0, 1024], found 2.5");
  expectSingleError("bounces_typo.json", shotWithRender(R"(, "bounces": {"difuse": 4})"),
                    "/render/bounces/difuse: unknown key 'difuse'; did you mean 'diffuse'?");
  expectSingleError("bounces_type.json", shotWithRender(R"(, "bounces": 4)"),
                    "/render/bounces: expected an object, found 4");
}

}  // namespace bounce_limits_setting_test
}  // namespace lacrima
