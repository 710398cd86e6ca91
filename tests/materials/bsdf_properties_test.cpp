// Properties every non-delta BSDF must have: sample() agrees with eval()/pdf(), reciprocity,
// energy conservation, and one-sided behaviour of the opaque models.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <tuple>

#include "bsdf_cases_support.hpp"
#include "chi2_support.hpp"
#include "lacrima/materials/diffuse.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/rough_dielectric.hpp"
#include "lacrima/materials/skin.hpp"

namespace lacrima {
namespace bsdf_properties_test {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct NamedParams {
  std::string name;
  MaterialParams params;
  bool twoSided;  // light may arrive from below (dielectrics)
  float wetCoverage = 0.0f;  // > 0: wet skin (bsdf_cases_support.hpp makeCaseBsdf)
};

std::vector<NamedParams> propertyMaterials() {
  std::vector<NamedParams> m;
  m.push_back({"diffuse", DiffuseParams{Color(0.8f, 0.5f, 0.2f)}, false});
  m.push_back({"diffuse_white", DiffuseParams{Color(1.0f, 1.0f, 1.0f)}, false});
  m.push_back({"skin", SkinParams{}, false});
  for (const float r : {0.1f, 0.35f, 0.8f}) {
    SkinParams white;
    white.albedo = Color(1.0f, 1.0f, 1.0f);
    white.roughness = r;
    m.push_back({"skin_white_r" + std::to_string(r), white, false});
  }
  // Dual-lobe skin (sharper roughness, broader roughness, weight of the broader lobe); white
  // bases test the energy bound where it is tightest.
  for (const auto& [r1, r2, mix] : {std::tuple{0.3f, 0.6f, 0.5f}, std::tuple{0.1f, 0.9f, 0.3f}, std::tuple{0.35f, 0.5f, 0.9f}}) {
    SkinParams white;
    white.albedo = Color(1.0f, 1.0f, 1.0f);
    white.roughness = r1;
    white.roughness2 = r2;
    white.lobeMix = mix;
    m.push_back({"skin_dual_white_" + std::to_string(r1) + "_" + std::to_string(r2) + "_" + std::to_string(mix), white,
                 false});
  }
  SkinParams dual;
  dual.roughness2 = 0.6f;
  dual.lobeMix = 0.15f;
  m.push_back({"skin_dual", dual, false});
  SkinParams subsurface = dual;  // the specular lobes alone (subsurface.hpp)
  subsurface.subsurface = SubsurfaceParams{};
  m.push_back({"skin_subsurface", subsurface, false});
  // Wet skin: white bases (tightest energy bound) and the default skin, half and fully covered.
  for (const float coverage : {0.5f, 1.0f}) {
    SkinParams white;
    white.albedo = Color(1.0f, 1.0f, 1.0f);
    white.roughness = 0.1f;
    m.push_back({"wet_skin_white_c" + std::to_string(coverage), white, false, coverage});
    m.push_back({"wet_skin_c" + std::to_string(coverage), SkinParams{}, false, coverage});
  }
  for (const float r : {0.2f, 0.5f, 0.9f}) {
    RoughDielectricParams p;
    p.roughness = r;
    m.push_back({"rough_dielectric_r" + std::to_string(r), p, true});
  }
  RoughDielectricParams tinted;
  tinted.roughness = 0.4f;
  tinted.tint = Color(0.9f, 0.7f, 0.5f);
  tinted.ior = 1.5f;
  m.push_back({"rough_dielectric_tinted_ior15", tinted, true});
  return m;
}

// Index of refraction on the side of w, relative to the outside (normal side).
float sideIor(const MaterialParams& params, const Vec3& w) {
  if (const auto* p = std::get_if<RoughDielectricParams>(&params)) return w.z() > 0.0f ? 1.0f : p->ior;
  return 1.0f;
}

Vec3 randomWo(test::TestRng& rng, bool twoSided) {
  Vec3 w = rng.sphere();
  if (!twoSided) w.z() = std::abs(w.z());
  return w;
}

TEST(BsdfConsistency, SampleAgreesWithEvalAndPdf) {
  for (const auto& m : propertyMaterials()) {
    const auto bsdf = test::makeCaseBsdf(m.params, m.wetCoverage);
    test::TestRng rng(1234);
    double maxErrF = 0.0;
    double maxErrPdf = 0.0;
    int checked = 0;
    for (int k = 0; k < 300; ++k) {
      const Vec3 wo = randomWo(rng, m.twoSided);
      if (std::abs(wo.z()) < 1e-3f) continue;
      for (int j = 0; j < 300; ++j) {
        const float uLobe = rng.uniform();
        const auto s = bsdf->sample(wo, uLobe, rng.uniform2());
        if (!s) continue;
        ASSERT_FALSE(s->specular) << m.name;
        ASSERT_GT(s->pdf, 0.0f) << m.name;
        ASSERT_TRUE(isFinite(s->f)) << m.name;
        ASSERT_NEAR(s->wi.norm(), 1.0f, 1e-4f) << m.name;
        EXPECT_EQ(s->transmitted, !sameHemisphere(wo, s->wi)) << m.name;
        const Color f = bsdf->eval(wo, s->wi);
        const float pdf = bsdf->pdf(wo, s->wi);
        for (int c = 0; c < 3; ++c) maxErrF = std::max(maxErrF, test::relativeError(s->f[c], f[c]));
        maxErrPdf = std::max(maxErrPdf, test::relativeError(s->pdf, pdf));
        if (s->transmitted) {
          EXPECT_NEAR(s->eta, sideIor(m.params, s->wi) / sideIor(m.params, wo), 1e-6f);
        }
        ++checked;
      }
    }
    std::printf("[consistency] %-34s %6d samples, max rel. error f %.2e, pdf %.2e\n", m.name.c_str(), checked,
                maxErrF, maxErrPdf);
    EXPECT_GT(checked, 50000) << m.name;
    EXPECT_LT(maxErrF, 1e-3) << m.name;
    EXPECT_LT(maxErrPdf, 1e-3) << m.name;
  }
}

// Numerical conditioning of a pair for the dielectric: microfacet normal of (wo, wi) (generalised
// half vector, Walter 2007 eq. 16) and how far the pair is from the places where F is steep:
// grazing a facet, or the critical angle on the inner side (F has a square-root edge there).
bool wellConditioned(const MaterialParams& params, const Vec3& wo, const Vec3& wi, float etaO, float etaI) {
  const auto* dielectric = std::get_if<RoughDielectricParams>(&params);
  if (!dielectric) return true;
  Vec3d h = (wo.cast<double>() * etaO + wi.cast<double>() * etaI).normalized();
  if (h.z() < 0.0) h = -h;
  const double cosCritical = std::sqrt(1.0 - 1.0 / (double(dielectric->ior) * dielectric->ior));
  for (const Vec3& w : {wo, wi}) {
    const double c = std::abs(h.dot(w.cast<double>()));
    if (c < 0.02 || std::abs(w.z()) < 0.02) return false;
    if (w.z() < 0.0f && std::abs(c - cosCritical) < 0.01) return false;  // inner side near TIR
  }
  return true;
}

TEST(BsdfReciprocity, ReflectionIsSymmetricAndTransmissionScalesWithEtaSquared) {
  // Reflection: f(wo, wi) = f(wi, wo). Transmission through an interface (Veach 1997 ch. 5):
  //   f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2,
  // eta_o and eta_i the refractive indices on the sides of wo and wi, for the radiance BTDF
  // (Walter's eq. 21 has n_o^2 in its numerator). Reflection is the case eta_o = eta_i.
  for (const auto& m : propertyMaterials()) {
    const auto bsdf = test::makeCaseBsdf(m.params, m.wetCoverage);
    test::TestRng rng(99);
    double maxErr = 0.0;
    int nonzero = 0;
    int checked = 0;
    int illConditionedOff = 0;
    for (int k = 0; k < 40000; ++k) {
      const Vec3 wo = randomWo(rng, m.twoSided);
      // Half the pairs from the sampler (inside the lobes), half uniform.
      Vec3 wi = randomWo(rng, m.twoSided);
      if (k % 2 == 0) {
        const auto s = bsdf->sample(wo, rng.uniform(), rng.uniform2());
        if (!s) continue;
        wi = s->wi;
      }
      const float etaO = sideIor(m.params, wo);
      const float etaI = sideIor(m.params, wi);
      const Color forward = bsdf->eval(wo, wi) / (etaO * etaO);
      const Color backward = bsdf->eval(wi, wo) / (etaI * etaI);
      if (std::max(forward.maxCoeff(), backward.maxCoeff()) <= 1e-6f) continue;
      ++nonzero;
      double err = 0.0;
      for (int c = 0; c < 3; ++c) err = std::max(err, test::relativeError(forward[c], backward[c]));
      if (wellConditioned(m.params, wo, wi, etaO, etaI)) {
        maxErr = std::max(maxErr, err);
        ++checked;
      } else if (err > 1e-2) {
        ++illConditionedOff;
      }
    }
    std::printf("[reciprocity] %-34s max rel. error %.2e over %d well-conditioned pairs; %d of %d other "
                "pairs off by > 1%%\n",
                m.name.c_str(), maxErr, checked, illConditionedOff, nonzero - checked);
    EXPECT_GT(checked, 10000) << m.name;
    EXPECT_LT(maxErr, 1e-4) << m.name;
    EXPECT_LT(illConditionedOff, nonzero / 200) << m.name;
  }
}

// Directional albedo by quadrature over the sphere: integral f(wo, wi) |cos_i| s(wi) dwi with
// s = etap^2 for transmitted directions when `physical`. The etap^2 undoes the radiance scaling of
// the BTDF, so this is the fraction of energy scattered (the importance-transport albedo), which
// must be <= 1. Integrated over the chi-square grid of cells (the lobes are resolved there).
double quadratureAlbedo(const Bsdf& bsdf, const MaterialParams& params, const Vec3& wo, bool physical) {
  const auto cells = test::integrateSphereCells(
      [&](double c, double phi) {
        const Vec3 wi = test::directionFromCosPhi(c, phi);
        double scale = std::abs(c);
        if (physical && !sameHemisphere(wo, wi)) {
          const double etap = sideIor(params, wi) / sideIor(params, wo);
          scale *= etap * etap;
        }
        return double(bsdf.eval(wo, wi).maxCoeff()) * scale;
      },
      10, 20, 8, 1e-9, 1e-6);
  double sum = 0.0;
  for (const double c : cells) sum += c;
  return sum;
}

// Monte Carlo directional albedo with the BSDF's own sampler (validated by the chi-square and
// consistency tests): mean of f |cos| / pdf, transmitted weights times etap^2 when `physical`.
struct McAlbedo {
  double mean = 0.0;
  double stdErr = 0.0;
  double maxWeight = 0.0;
};

McAlbedo monteCarloAlbedo(const Bsdf& bsdf, const Vec3& wo, bool physical, uint64_t seed, int samples = 40000) {
  test::TestRng rng(seed);
  double sum = 0.0;
  double sum2 = 0.0;
  McAlbedo r;
  for (int k = 0; k < samples; ++k) {
    const auto s = bsdf.sample(wo, rng.uniform(), rng.uniform2());
    if (!s) continue;
    double w = s->f.maxCoeff() * std::abs(s->wi.z()) / s->pdf;
    if (physical && s->transmitted) w *= double(s->eta) * s->eta;
    r.maxWeight = std::max(r.maxWeight, w);
    sum += w;
    sum2 += w * w;
  }
  r.mean = sum / samples;
  r.stdErr = std::sqrt(std::max(0.0, sum2 / samples - r.mean * r.mean) / samples);
  return r;
}

TEST(BsdfEnergy, DirectionalAlbedoAtMostOne) {
  for (const auto& m : propertyMaterials()) {
    const auto bsdf = test::makeCaseBsdf(m.params, m.wetCoverage);
    std::vector<float> cosines = {1.0f, 0.8f, 0.5f, 0.25f, 0.1f, 0.03f};
    if (m.twoSided) {
      for (int i = 0, n = int(cosines.size()); i < n; ++i) cosines.push_back(-cosines[i]);
    }
    double maxAlbedo = 0.0;
    float maxCos = 0.0f;
    for (const float cosO : cosines) {
      const Vec3 wo = test::directionFromCosPhi(cosO, 0.8);
      const McAlbedo mc = monteCarloAlbedo(*bsdf, wo, /*physical=*/true, uint64_t(1000 + 1000 * cosO));
      double albedo = mc.mean;
      if (m.twoSided) {
        // GGX dielectric with visible-normal sampling: every weight is G2/G1 <= 1 (Heitz 2018
        // eq. 19), so no direction can gain energy and the albedo is <= 1 sample by sample.
        EXPECT_LE(mc.maxWeight, 1.0 + 1e-4) << m.name << " cos_o " << cosO;
      } else {
        // Opaque models: quadrature (deterministic), cross-checked against Monte Carlo.
        albedo = quadratureAlbedo(*bsdf, m.params, wo, /*physical=*/true);
        EXPECT_NEAR(mc.mean, albedo, 5.0 * mc.stdErr + 2e-4) << m.name << " cos_o " << cosO;
      }
      EXPECT_LE(albedo, 1.0 + 1e-5) << m.name << " cos_o " << cosO;
      if (albedo > maxAlbedo) {
        maxAlbedo = albedo;
        maxCos = cosO;
      }
    }
    std::printf("[energy] %-34s max directional albedo %.5f at cos_o %.2f\n", m.name.c_str(), maxAlbedo, maxCos);
  }
}

TEST(BsdfEnergy, DielectricSamplerCoversTheWholeSupport) {
  // The Monte Carlo albedo above only sees directions the sampler can produce: check f > 0
  // implies pdf > 0 for random pairs.
  for (const auto& m : propertyMaterials()) {
    if (!m.twoSided) continue;
    const auto bsdf = test::makeCaseBsdf(m.params, m.wetCoverage);
    test::TestRng rng(17);
    for (int k = 0; k < 100000; ++k) {
      const Vec3 wo = rng.sphere();
      const Vec3 wi = rng.sphere();
      if (bsdf->eval(wo, wi).maxCoeff() > 0.0f) {
        ASSERT_GT(bsdf->pdf(wo, wi), 0.0f) << m.name;
      }
    }
  }
}

TEST(BsdfEnergy, RadianceTransmissionFromOutsideIsAlsoBelowOne) {
  // From air into water the radiance BTDF carries 1/eta^2 < 1, so even radiance weights are <= 1;
  // from inside they are not (radiance concentrates in the denser medium), see smooth_dielectric.hpp.
  RoughDielectricParams p;
  p.roughness = 0.3f;
  const auto bsdf = makeBsdf(p);
  for (const float cosO : {1.0f, 0.5f, 0.1f}) {
    const Vec3 wo = test::directionFromCosPhi(cosO, 0.1);
    const McAlbedo mc = monteCarloAlbedo(*bsdf, wo, /*physical=*/false, 77);
    EXPECT_LE(mc.maxWeight, 1.0 + 1e-4) << cosO;
    const McAlbedo inside = monteCarloAlbedo(*bsdf, -wo, /*physical=*/false, 78);
    if (cosO == 1.0f) {
      EXPECT_GT(inside.maxWeight, 1.5) << "radiance weight from inside carries eta^2";
    }
  }
}

TEST(DiffuseBsdf, AlbedoIsExactAndOneSided) {
  const DiffuseParams p{Color(0.8f, 0.5f, 0.2f)};
  const DiffuseBsdf bsdf(p);
  test::TestRng rng(5);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 wo = randomWo(rng, false);
    const auto s = bsdf.sample(wo, rng.uniform(), rng.uniform2());
    ASSERT_TRUE(s.has_value());
    const Color weight = s->f * s->wi.z() / s->pdf;
    EXPECT_LT((weight - p.albedo).abs().maxCoeff(), 1e-5f);
  }
  const Vec3 below(0.3f, 0.0f, -0.95f);
  const Vec3 above(0.0f, 0.3f, 0.95f);
  EXPECT_FALSE(bsdf.sample(below, 0.5f, Vec2(0.3f, 0.7f)).has_value());
  EXPECT_EQ(bsdf.eval(below, above).maxCoeff(), 0.0f);
  EXPECT_EQ(bsdf.eval(above, below).maxCoeff(), 0.0f);
  EXPECT_EQ(bsdf.pdf(below, above), 0.0f);
  EXPECT_EQ(bsdf.pdf(above, below), 0.0f);
}

TEST(SkinBsdf, BaseAlbedoLosesExactlyTheFresnelReflectedPart) {
  // The base lobe alone (albedo a minus albedo 0) reflects a (1 - F(cos_o)) of the light.
  SkinParams withBase;
  withBase.albedo = Color(0.6f, 0.6f, 0.6f);
  SkinParams specularOnly = withBase;
  specularOnly.albedo = Color(0.0f, 0.0f, 0.0f);
  const SkinBsdf a(withBase);
  const SkinBsdf b(specularOnly);
  for (const double cosO : {0.95, 0.6, 0.2}) {
    const Vec3 wo = test::directionFromCosPhi(cosO, 0.0);
    const double base = test::integrate2D(
        [&](double c, double phi) {
          const Vec3 wi = test::directionFromCosPhi(c, phi);
          return double(a.eval(wo, wi).x() - b.eval(wo, wi).x()) * c;
        },
        0.0, 1.0, 0.0, kTwoPi, 8);
    EXPECT_NEAR(base, 0.6 * (1.0 - fresnelDielectric(float(cosO), withBase.ior)), 2e-5) << cosO;
  }
  // The hemispherical Fresnel reflectance: about 0.0918 for n = 1.4 (integral of the exact F).
  const double fbar = test::integrate2D(
      [](double c, double) { return fresnelDielectric(float(c), 1.4f) * 2.0 * c; }, 0.0, 1.0, 0.0, 1.0, 8);
  EXPECT_NEAR(fresnelHemisphericalReflectance(1.4f), fbar, 1e-5);
}

TEST(SkinBsdf, OneSidedAndMixtureProbabilityClamped) {
  const SkinBsdf bsdf{SkinParams{}};
  const Vec3 below(0.3f, 0.0f, -0.95f);
  const Vec3 above(0.0f, 0.3f, 0.95f);
  EXPECT_FALSE(bsdf.sample(below, 0.05f, Vec2(0.3f, 0.7f)).has_value());
  EXPECT_EQ(bsdf.eval(below, above).maxCoeff(), 0.0f);
  EXPECT_EQ(bsdf.pdf(above, below), 0.0f);
  for (const float c : {1.0f, 0.5f, 0.1f, 0.01f}) {
    const float p = bsdf.specularProbability(test::directionFromCosPhi(c, 0.0));
    EXPECT_GE(p, 0.1f);
    EXPECT_LE(p, 0.9f);
  }
  // More specular sampling towards grazing, where Fresnel grows.
  EXPECT_GT(bsdf.specularProbability(test::directionFromCosPhi(0.05, 0.0)),
            bsdf.specularProbability(test::directionFromCosPhi(0.9, 0.0)));
}

}  // namespace bsdf_properties_test
}  // namespace lacrima
