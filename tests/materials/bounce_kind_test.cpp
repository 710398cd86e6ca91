// BsdfSample::glossy, the kind of bounce the per-type bounce limits count (RenderSettings::bounces):
// set by the specular and glossy reflection lobes, never by a diffuse one.
#include <gtest/gtest.h>

#include "lacrima/materials/diffuse.hpp"
#include "lacrima/materials/rough_dielectric.hpp"
#include "lacrima/materials/skin.hpp"
#include "lacrima/materials/smooth_dielectric.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace bounce_kind_test {

const Vec3 kWo = Vec3(0.3f, 0.2f, 0.9f).normalized();

TEST(BounceKind, DiffuseSamplesAreNotGlossy) {
  const DiffuseBsdf diffuse(DiffuseParams{Color::Constant(0.5f)});
  test::TestRng rng(1);
  for (int k = 0; k < 1000; ++k) {
    const auto s = diffuse.sample(kWo, rng.uniform(), Vec2(rng.uniform(), rng.uniform()));
    ASSERT_TRUE(s);
    EXPECT_FALSE(s->glossy);
  }
}

// Skin picks its specular lobes for uLobe below specularProbability(wo), the Lambertian base above.
TEST(BounceKind, SkinIsGlossyExactlyWhenItsSpecularLobesDrewTheDirection) {
  SkinParams params;
  params.lobeMix = 0.3f;
  const SkinBsdf skin(params);
  const float pSpec = skin.specularProbability(kWo);
  ASSERT_GT(pSpec, 0.01f);
  ASSERT_LT(pSpec, 0.99f);
  test::TestRng rng(2);
  int glossy = 0, drawn = 0;
  for (int k = 0; k < 4000; ++k) {
    const float uLobe = rng.uniform();
    const auto s = skin.sample(kWo, uLobe, Vec2(rng.uniform(), rng.uniform()));
    if (!s) continue;  // masked below the horizon
    ++drawn;
    glossy += s->glossy ? 1 : 0;
    EXPECT_EQ(s->glossy, uLobe < pSpec) << "uLobe " << uLobe;
  }
  EXPECT_GT(glossy, 0);
  EXPECT_LT(glossy, drawn);
}

// Under a full water film the coat's reflection is glossy and the film's diffuse part is not;
// under no film the skin's own kinds pass through.
TEST(BounceKind, WetSkinTellsCoatAndBaseApart) {
  const SkinBsdf skin(SkinParams{});
  test::TestRng rng(3);
  for (const float coverage : {0.0f, 0.6f, 1.0f}) {
    SCOPED_TRACE(coverage);
    const WetSkinBsdf wet(skin, coverage);
    int glossy = 0, diffuse = 0;
    for (int k = 0; k < 4000; ++k) {
      const auto s = wet.sample(kWo, rng.uniform(), Vec2(rng.uniform(), rng.uniform()));
      if (s) (s->glossy ? glossy : diffuse) += 1;
    }
    EXPECT_GT(glossy, 0);
    EXPECT_GT(diffuse, 0);
  }
}

TEST(BounceKind, DielectricReflectionsAreGlossyTransmissionsAreTransmitted) {
  const SmoothDielectricBsdf smooth(SmoothDielectricParams{1.5f});
  RoughDielectricParams roughParams;
  roughParams.ior = 1.5f;
  roughParams.roughness = 0.3f;
  const RoughDielectricBsdf rough(roughParams);
  test::TestRng rng(4);
  for (const Bsdf* bsdf : {static_cast<const Bsdf*>(&smooth), static_cast<const Bsdf*>(&rough)}) {
    int reflected = 0, transmitted = 0;
    for (int k = 0; k < 4000; ++k) {
      const auto s = bsdf->sample(kWo, rng.uniform(), Vec2(rng.uniform(), rng.uniform()));
      if (!s) continue;
      EXPECT_NE(s->glossy, s->transmitted);  // one or the other, never both
      (s->transmitted ? transmitted : reflected) += 1;
    }
    EXPECT_GT(reflected, 0);
    EXPECT_GT(transmitted, 0);
  }
}

}  // namespace bounce_kind_test
}  // namespace lacrima
