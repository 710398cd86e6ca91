// The skin's second specular lobe: absent by default (the single-lobe skin, bitwise), a convex mix of two GGX
// lobes when lobeMix > 0, and the BSDF's pore hook.
#include <gtest/gtest.h>

#include "chi2_support.hpp"
#include "lacrima/materials/diffuse.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/microfacet.hpp"
#include "lacrima/materials/skin.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace skin_dual_lobe_test {

// The single-lobe skin's f, written out in the order it was evaluated before the second lobe (Walter 2007 eq. 20 plus the
// Fresnel-weighted base of skin.hpp), to compare bitwise.
Color singleLobeSkinEval(const SkinParams& p, const Vec3& wo, const Vec3& wi) {
  if (wo.z() <= 0.0f || wi.z() <= 0.0f) return Color::Zero();
  const Color albedo = p.albedo.max(0.0f).min(kMaxSkinAlbedo);
  const float diffuseNorm = kInvPi / (1.0f - fresnelHemisphericalReflectance(p.ior));
  const float transO = 1.0f - fresnelDielectric(wo.z(), p.ior);
  const float transI = 1.0f - fresnelDielectric(wi.z(), p.ior);
  const Color diffuse = albedo * (diffuseNorm * transO * transI);
  const Vec3 wm = (wo + wi).normalized();
  const GgxDistribution d(roughnessToAlpha(p.roughness));
  const float F = fresnelDielectric(wo.dot(wm), p.ior);
  return diffuse + Color::Constant(d.D(wm) * d.G(wo, wi) * F / (4.0f * wo.z() * wi.z()));
}

bool bitwiseEqual(const Color& a, const Color& b) { return (a == b).all(); }

TEST(SkinDualLobe, ZeroMixIsTheSingleLobeSkinBitwise) {
  SkinParams singleLobe;
  singleLobe.roughness = 0.3f;
  SkinParams other = singleLobe;
  other.roughness2 = 0.9f;  // ignored while lobeMix is 0
  const SkinBsdf a(singleLobe), b(other);
  test::TestRng rng(31);
  int nonzero = 0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 wo = rng.sphere();
    wo.z() = std::abs(wo.z());
    const Vec3 wi = rng.sphere();
    const Color f = a.eval(wo, wi);
    ASSERT_TRUE(bitwiseEqual(f, singleLobeSkinEval(singleLobe, wo, wi))) << k;
    ASSERT_TRUE(bitwiseEqual(f, b.eval(wo, wi))) << k;
    ASSERT_EQ(a.pdf(wo, wi), b.pdf(wo, wi)) << k;
    const float uLobe = rng.uniform();
    const Vec2 u = rng.uniform2();
    const auto sa = a.sample(wo, uLobe, u);
    const auto sb = b.sample(wo, uLobe, u);
    ASSERT_EQ(sa.has_value(), sb.has_value());
    if (sa) {
      ASSERT_TRUE(sa->wi == sb->wi && bitwiseEqual(sa->f, sb->f) && sa->pdf == sb->pdf) << k;
    }
    if (f.maxCoeff() > 0.0f) ++nonzero;
  }
  EXPECT_GT(nonzero, 5000);
}

TEST(SkinDualLobe, EvalAndPdfAreTheWeightedMixOfTheSingleLobes) {
  SkinParams dual;
  dual.roughness = 0.25f;
  dual.roughness2 = 0.7f;
  dual.lobeMix = 0.3f;
  SkinParams sharp = dual;
  sharp.lobeMix = 0.0f;
  SkinParams broad = sharp;
  broad.roughness = dual.roughness2;
  const SkinBsdf d(dual), s(sharp), b(broad);
  test::TestRng rng(32);
  double maxErrF = 0.0, maxErrPdf = 0.0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 wo = rng.sphere();
    wo.z() = std::abs(wo.z());
    Vec3 wi = rng.sphere();
    wi.z() = std::abs(wi.z());
    // The base is the same in all three, so f mixes like the specular parts: (1 - w) f1 + w f2.
    const Color expected = 0.7f * s.eval(wo, wi) + 0.3f * b.eval(wo, wi);
    for (int c = 0; c < 3; ++c) maxErrF = std::max(maxErrF, test::relativeError(d.eval(wo, wi)[c], expected[c]));
    // The lobe choice probability pSpec depends only on Fresnel and the base, so it is shared too.
    const float expectedPdf = 0.7f * s.pdf(wo, wi) + 0.3f * b.pdf(wo, wi);
    maxErrPdf = std::max(maxErrPdf, test::relativeError(d.pdf(wo, wi), expectedPdf));
  }
  EXPECT_LT(maxErrF, 1e-5);
  EXPECT_LT(maxErrPdf, 1e-5);
}

TEST(SkinDualLobe, SpecularAlbedoStaysBelowFresnelBound) {
  // Specular only (black base): the directional albedo of the mix is bounded like one lobe's,
  // E_spec <= F(cos_o) + 1e-3 (1 - F(cos_o)) (skin.hpp, Energy), by quadrature.
  SkinParams p;
  p.albedo = Color::Zero();
  p.roughness = 0.2f;
  p.roughness2 = 0.8f;
  p.lobeMix = 0.5f;
  const SkinBsdf bsdf(p);
  for (const double cosO : {0.99, 0.7, 0.4, 0.15}) {
    const Vec3 wo = test::directionFromCosPhi(cosO, 0.0);
    const auto cells = test::integrateSphereCells(
        [&](double c, double phi) { return double(bsdf.eval(wo, test::directionFromCosPhi(c, phi)).x()) * std::abs(c); },
        10, 20, 8, 1e-9, 1e-6);
    double albedo = 0.0;
    for (const double c : cells) albedo += c;
    const double F = fresnelDielectric(float(cosO), p.ior);
    EXPECT_LE(albedo, F + 1e-3 * (1.0 - F)) << cosO;
    EXPECT_GT(albedo, 0.5 * F) << cosO;  // the lobes are there (masking loses some at grazing)
  }
}

TEST(SkinDualLobe, PoreHookIsIdentityWithoutPoresAndTiltsWithThem) {
  const Vec3 ns(0.0f, 0.0f, 1.0f);
  const SkinBsdf plain{SkinParams{}};
  const DiffuseBsdf diffuse{DiffuseParams{}};
  SkinParams pored;
  pored.poreScale = 3e-4f;
  pored.poreDepth = 3e-5f;
  const SkinBsdf withPores(pored);
  test::TestRng rng(33);
  int tilted = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p(0.01f * rng.uniform(), 0.01f * rng.uniform(), 0.002f);
    ASSERT_TRUE(plain.perturbShadingNormal(p, ns, ns) == ns);
    ASSERT_TRUE(diffuse.perturbShadingNormal(p, ns, ns) == ns);
    if (withPores.perturbShadingNormal(p, ns, ns).z() < 0.9998f) ++tilted;  // > ~1 degree
  }
  EXPECT_GT(tilted, 100);
}

}  // namespace skin_dual_lobe_test
}  // namespace lacrima
