// Chi-square goodness-of-fit tests of every non-delta BSDF's sample() against its pdf(), and of
// the GGX visible-normal sampler against its density.
#include <gtest/gtest.h>

#include <cstdio>

#include "bsdf_cases_support.hpp"
#include "chi2_support.hpp"
#include "lacrima/materials/microfacet.hpp"

namespace lacrima {
namespace bsdf_chi2_test {

struct VndfCase {
  const char* name;
  float alpha;
  float cosThetaO;
};
const VndfCase kVndfCases[] = {{"alpha01_grazing", 0.1f, 0.15f}, {"alpha06_normal", 0.6f, 0.99f}};

uint64_t nameSeed(const std::string& name) {
  uint64_t h = 1469598103934665603ULL;  // FNV-1a
  for (const char c : name) h = (h ^ uint64_t(uint8_t(c))) * 1099511628211ULL;
  return h;
}

void report(const std::string& name, const test::Chi2Result& r) {
  std::printf("[chi2] %-44s %s\n", name.c_str(), r.message.c_str());
  ::testing::Test::RecordProperty("chi2", r.message);
}

TEST(Chi2Family, CountMatchesTheSidakFamilySize) {
  EXPECT_EQ(int(test::chi2Cases().size() + std::size(kVndfCases)), test::kChi2TestCount);
}

class BsdfChi2 : public ::testing::TestWithParam<test::BsdfCase> {};

TEST_P(BsdfChi2, SampleMatchesPdf) {
  const test::BsdfCase& c = GetParam();
  const auto bsdf = test::makeCaseBsdf(c.params, c.wetCoverage);
  const Vec3 wo = test::caseWo(c);
  test::Chi2Options options;
  options.testCount = test::kChi2TestCount;
  options.seed = nameSeed(c.name);
  const auto result = test::runChi2Test(
      [&](float uLobe, const Vec2& u) -> std::optional<Vec3> {
        const auto s = bsdf->sample(wo, uLobe, u);
        if (!s) return std::nullopt;
        EXPECT_FALSE(s->specular);
        return s->wi;
      },
      [&](const Vec3& wi) { return double(bsdf->pdf(wo, wi)); }, options);
  report(c.name, result);
  EXPECT_TRUE(result.passed) << result.message;
  EXPECT_LE(result.pdfIntegral, 1.0 + 1e-3);
}

INSTANTIATE_TEST_SUITE_P(AllBsdfs, BsdfChi2, ::testing::ValuesIn(test::chi2Cases()),
                         [](const auto& info) { return info.param.name; });

TEST(VndfChi2, SampleMatchesVisibleNormalDensity) {
  for (const VndfCase& c : kVndfCases) {
    const GgxDistribution d(c.alpha);
    const Vec3 wo = test::directionFromCosPhi(c.cosThetaO, 2.0);
    test::Chi2Options options;
    options.testCount = test::kChi2TestCount;
    options.seed = nameSeed(c.name);
    const auto result = test::runChi2Test(
        [&](float, const Vec2& u) -> std::optional<Vec3> { return d.sampleVisibleNormal(wo, u); },
        [&](const Vec3& wm) { return double(d.visibleD(wo, wm)); }, options);
    report(std::string("vndf_") + c.name, result);
    EXPECT_TRUE(result.passed) << c.name << ": " << result.message;
    EXPECT_NEAR(result.pdfIntegral, 1.0, 1e-3) << c.name;
  }
}

}  // namespace bsdf_chi2_test
}  // namespace lacrima
