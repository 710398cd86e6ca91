// The `render.caustics` key (docs/shot-format.md, "Caustics"), and the retired
// `render.transparentShadows`, which a shot is told to replace.
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace caustics_setting_test {

using test::expectSingleError;
using test::shotWithRender;
using test::writeShot;

Caustics modeOf(const std::string& name, const std::string& renderExtra) {
  return loadShot(writeShot(name, shotWithRender(renderExtra))).render.caustics;
}

TEST(CausticsSetting, DefaultsToMneeAndReadsEachMode) {
  EXPECT_EQ(modeOf("caustics_default.json", ""), Caustics::Mnee);
  EXPECT_EQ(modeOf("caustics_mnee.json", R"(, "caustics": "mnee")"), Caustics::Mnee);
  EXPECT_EQ(modeOf("caustics_straight.json", R"(, "caustics": "straight")"), Caustics::Straight);
  EXPECT_EQ(modeOf("caustics_off.json", R"(, "caustics": "off")"), Caustics::Off);
}

TEST(CausticsSetting, TheRetiredTransparentShadowsKeyNamesWhatReplacesIt) {
  const std::string message =
      "/render/transparentShadows: is no longer read: give \"caustics\" instead (\"off\" for false; true was the "
      "default, \"mnee\")";
  expectSingleError("caustics_ts_false.json", shotWithRender(R"(, "transparentShadows": false)"), message);
  expectSingleError("caustics_ts_true.json", shotWithRender(R"(, "transparentShadows": true, "caustics": "straight")"),
                    message);
}

TEST(CausticsSetting, BadValuesAreReportedAtTheirPath) {
  expectSingleError("caustics_typo.json", shotWithRender(R"(, "caustics": "mne")"),
                    "/render/caustics: unknown caustics mode 'mne'; did you mean 'mnee'?");
  expectSingleError("caustics_unknown.json", shotWithRender(R"(, "caustics": "photons")"),
                    "/render/caustics: unknown caustics mode 'photons' (expected one of 'mnee', 'straight', 'off')");
  expectSingleError("caustics_type.json", shotWithRender(R"(, "caustics": true)"),
                    "/render/caustics: expected a non-empty string, found true");
}

}  // namespace caustics_setting_test
}  // namespace lacrima
