// The `render.sampler` key (docs/shot-format.md, "Sampling").
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace sampler_setting_test {

using test::expectSingleError;
using test::shotWithRender;
using test::writeShot;

SamplerKind samplerOf(const std::string& name, const std::string& renderExtra) {
  return loadShot(writeShot(name, shotWithRender(renderExtra))).render.sampler;
}

TEST(SamplerSetting, DefaultsToSobolAndReadsEachKind) {
  EXPECT_EQ(samplerOf("sampler_default.json", ""), SamplerKind::Sobol);
  EXPECT_EQ(samplerOf("sampler_sobol.json", R"(, "sampler": "sobol")"), SamplerKind::Sobol);
  EXPECT_EQ(samplerOf("sampler_independent.json", R"(, "sampler": "independent")"), SamplerKind::Independent);
}

TEST(SamplerSetting, BadValuesAreReportedAtTheirPath) {
  expectSingleError("sampler_typo.json", shotWithRender(R"(, "sampler": "sobel")"),
                    "/render/sampler: unknown sampler 'sobel'; did you mean 'sobol'?");
  expectSingleError("sampler_unknown.json", shotWithRender(R"(, "sampler": "halton")"),
                    "/render/sampler: unknown sampler 'halton' (expected one of 'sobol', 'independent')");
  expectSingleError("sampler_type.json", shotWithRender(R"(, "sampler": 3)"),
                    "/render/sampler: expected a non-empty string, found 3");
}

}  // namespace sampler_setting_test
}  // namespace lacrima
