// Random-walk subsurface scattering end to end (lacrima/materials/subsurface.hpp,
// renderer/src/subsurface_walk.hpp): energy conservation in a furnace, the diffuse reflectance of
// a semi-infinite medium against Chandrasekhar's H-function, determinism. Tolerances are
// statistical (5 standard errors of the pixel mean, test_scenes.hpp) plus a stated floor.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/materials/diffusion_profile.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/subsurface.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/chandrasekhar_h.hpp"
#include "support/bsdf_albedo.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace subsurface_test {

using test::lookAt;
using test::smallSettings;

// Index-matched skin (ior 1: no Fresnel, so no specular reflection and no entry/exit loss) whose
// base is a random walk with these mean free paths.
SkinParams indexMatchedSubsurfaceSkin(const Color& albedo, const Color& meanFreePath) {
  SkinParams skin;
  skin.albedo = albedo;
  skin.ior = 1.0f;
  skin.subsurface = SubsurfaceParams{meanFreePath};
  return skin;
}

// Furnace: zero absorption (albedo 1 gives single-scattering albedo 1) in a closed sphere under a
// uniform environment of radiance 1: every walk leaves again and every exit sees the
// environment, so the camera sees exactly 1. Per-channel mean free paths differ, so the channel
// MIS weights are exercised; the sphere is 4-10 mean free paths across, far from the step cap.
TEST(Subsurface, FurnaceSphereWithoutAbsorptionReturnsTheEnvironment) {
  Frame frame;
  frame.materials.push_back(
      Material{"skin", indexMatchedSubsurfaceSkin(Color::Ones(), Color(0.25f, 0.15f, 0.1f)), Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 0});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 0, 3), Vec3::Zero(), 15.0f);  // every pixel sees the sphere
  frame.settings = smallSettings(32, 256, 10);
  const Film film = renderFrame(frame);
  const test::MeanEstimate e = test::channelMean(film, 0);
  std::printf("[subsurface] furnace: %.5f +- %.5f (exact 1)\n", e.mean, e.standardError);
  test::expectMean(film, 1.0, 1e-4);
}

// A water drop half sunk into the furnace sphere: the walk crosses the drop's surfaces below the
// skin as if absent, and a walk between skin under the drop and skin in air carries the radiance
// ratio (n_entry / n_exit)^2. Water and walk are lossless, so the camera still sees exactly 1
// (without the ratio it saw 0.785 here: the skin under a drop went grey). The skin has the
// water's index: under the drop, where it meets water, it is index-matched (no Fresnel at all);
// in air its Fresnel is that of water, whose specular lobe and entry loss add up to 1 within the
// GGX margin of skin.hpp (an index-1 skin under water would meet a relative index of 0.75, with
// total internal reflection that a single-scattering GGX lobe does not conserve).
TEST(Subsurface, FurnaceSphereWithASunkenWaterDropReturnsTheEnvironment) {
  SkinParams skin = indexMatchedSubsurfaceSkin(Color::Ones(), Color::Constant(0.1f));
  skin.ior = SmoothDielectricParams{}.ior;
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{}, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 0});
  frame.spheres.push_back(Sphere{Vec3(0, 0, 0.45f), 0.2f, 1});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 0, 3), Vec3(0, 0, 0.45f), 7.0f);  // the drop and the skin around it
  frame.settings = smallSettings(24, 128, 100);
  const Film film = renderFrame(frame);
  const test::MeanEstimate e = test::channelMean(film, 0);
  std::printf("[subsurface] furnace with drop: %.5f +- %.5f (exact 1)\n", e.mean, e.standardError);
  test::expectMean(film, 1.0, 1e-3);
}

// The same sphere with absorption (albedo 0.5) must come out darker: the furnace can fail.
TEST(Subsurface, FurnaceSphereWithAbsorptionIsDarker) {
  Frame frame;
  frame.materials.push_back(
      Material{"skin", indexMatchedSubsurfaceSkin(Color::Constant(0.5f), Color::Constant(0.1f)), Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 0});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 0, 3), Vec3::Zero(), 15.0f);
  frame.settings = smallSettings(16, 32, 10);
  const test::MeanEstimate e = test::channelMean(renderFrame(frame), 0);
  EXPECT_LT(e.mean + 5.0 * e.standardError, 0.9);
}

// van de Hulst's white-sky albedo of a semi-infinite isotropic medium, A = (1 - s)(1 - 0.139 s) /
// (1 + 1.17 s), s = sqrt(1 - a): the skin albedo that singleScatteringAlbedoFor maps back to a.
float skinAlbedoForSingleScatteringAlbedo(double a) {
  const double s = std::sqrt(1.0 - a);
  return float((1.0 - s) * (1.0 - 0.139 * s) / (1.0 + 1.17 * s));
}

// A closed box: top face at y = 0, `half` wide each way, `depth` deep, six rectangles.
void addBox(Frame& frame, float half, float depth, uint32_t materialId) {
  const float y = -0.5f * depth;
  const Vec3 x(2 * half, 0, 0), z(0, 0, 2 * half), h(0, depth, 0);
  for (const auto& [center, u, v] :
       {std::tuple{Vec3(0, 0, 0), x, z}, std::tuple{Vec3(0, -depth, 0), x, z}, std::tuple{Vec3(half, y, 0), h, z},
        std::tuple{Vec3(-half, y, 0), h, z}, std::tuple{Vec3(0, y, half), x, h}, std::tuple{Vec3(0, y, -half), x, h}})
    frame.meshes.push_back(MeshInstance{makeRectangle(center, u, v), materialId});
}

// Semi-infinite slab: a box thousands of mean free paths wide and deep, index-matched, under a
// uniform environment of radiance 1. The walk enters in a cosine-distributed direction (which is
// how light from a uniform sky enters) and leaves through a cosine lobe, so the radiance seen
// from anywhere above is the white-sky (spherical) albedo
//   A_diffuse(a) = 1 - 2 sqrt(1 - a) integral_0^1 H(mu) mu dmu
// computed from the H-function (support/chandrasekhar_h.hpp). R, G, B carry single-scattering
// albedos 0.5, 0.9, 0.99 and different mean free paths in one render (channel MIS). Floor: 1%
// of the reference, for the step cap's bias at a = 0.99 and the finite box.
TEST(Subsurface, SemiInfiniteSlabReflectsTheChandrasekharWhiteSkyAlbedo) {
  const double singleScattering[3] = {0.5, 0.9, 0.99};
  Color albedo;
  for (int c = 0; c < 3; ++c) albedo[c] = skinAlbedoForSingleScatteringAlbedo(singleScattering[c]);
  const SkinParams skin = indexMatchedSubsurfaceSkin(albedo, Color(0.02f, 0.01f, 0.005f));
  for (int c = 0; c < 3; ++c)
    ASSERT_NEAR(subsurfaceMedium(skin, *skin.subsurface).singleScatteringAlbedo[c], singleScattering[c], 1e-4);
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  addBox(frame, 50.0f, 50.0f, 0);
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 2, 1), Vec3::Zero(), 10.0f);
  frame.settings = smallSettings(24, 64, 10);
  const Film film = renderFrame(frame);
  for (int c = 0; c < 3; ++c) {
    const double reference = test::semiInfiniteWhiteSkyAlbedo(singleScattering[c]);
    const test::MeanEstimate e = test::channelMean(film, c);
    std::printf("[subsurface] a = %.2f: rendered %.4f +- %.4f, H-function white-sky albedo %.4f\n",
                singleScattering[c], e.mean, e.standardError, reference);
    EXPECT_NEAR(e.mean, reference, 5.0 * e.standardError + 0.01 * reference) << "channel " << c;
  }
}

// Directional albedo of a BSDF at wo (1000x360 quadrature cells).
Color directionalAlbedo(const Bsdf& bsdf, const Vec3& wo) { return test::directionalAlbedo(bsdf, wo, 1000, 360); }

// Under a tear film of coverage c (wet_skin.hpp, "Subsurface skin") the walk serves the base of
// the wet fraction too: the slab reflects c E_coat(wo) + [(1 - c) + c (1 - Fw(cos_o))] A_diffuse(a),
// E_coat the film's coat alone (the wet layer has no Lambertian base on subsurface skin), Fw the
// water's Fresnel (the index-matched skin has none of its own). With the old Lambertian base under
// the film the slab rendered 0.237 here. Floor 1%: E_coat and Fw vary over the 10-degree view.
TEST(Subsurface, WetSlabScattersBelowTheFilmAsBelowDrySkin) {
  const double singleScattering = 0.9;
  const Color albedo = Color::Constant(skinAlbedoForSingleScatteringAlbedo(singleScattering));
  const SkinParams skin = indexMatchedSubsurfaceSkin(albedo, Color::Constant(0.01f));
  const float film = 1.5e-6f, coverage = wetFilmCoverage(film);
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  addBox(frame, 50.0f, 50.0f, 0);
  frame.meshes.front().wetness.assign(frame.meshes.front().mesh.positions.size(), film);  // the top face
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 2, 1), Vec3::Zero(), 10.0f);
  frame.settings = smallSettings(24, 64, 10);
  const Film rendered = renderFrame(frame);
  const Vec3 wo = Vec3(0, 2, 1).normalized();  // local: the top face's normal is +y
  const Vec3 woLocal(0, wo.z(), wo.y());
  const WetSkinBsdf allWet(SkinBsdf(skin), 1.0f);
  const Color coat = directionalAlbedo(allWet, woLocal);
  ASSERT_TRUE((allWet.evalLobes(woLocal, Vec3(0, 0, 1)).diffuse == 0.0f).all());  // no base above the walk
  const double entering = (1.0 - coverage) + coverage * (1.0 - fresnelDielectric(woLocal.z(), kWaterIor));
  const double expected = coverage * coat[0] + entering * test::semiInfiniteWhiteSkyAlbedo(singleScattering);
  const test::MeanEstimate e = test::channelMean(rendered, 0);
  std::printf("[subsurface] wet slab, coverage %.3f: rendered %.4f +- %.4f, expected %.4f\n", coverage, e.mean,
              e.standardError, expected);
  EXPECT_NEAR(e.mean, expected, 5.0 * e.standardError + 0.01 * expected);
}

// A subsurface sphere under the determinism scenes' light (test_scenes.hpp).
Frame litSubsurfaceSphere(SubsurfaceMethod method) {
  Frame frame;
  SkinParams skin;
  skin.subsurface = SubsurfaceParams{Color(0.05f, 0.03f, 0.02f), method};
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 0});
  test::addTopLightAndView(frame);
  return frame;
}

TEST(Subsurface, OneAndTwoThreadsGiveBitwiseEqualFilms) {
  test::expectThreadCountIndependent(litSubsurfaceSphere(SubsurfaceMethod::RandomWalk));
}

// The diffusion-profile method (diffusion_profile.hpp, renderer/src/subsurface_probe.hpp).
SkinParams withDiffusion(SkinParams skin) {
  skin.subsurface->method = SubsurfaceMethod::Diffusion;
  return skin;
}

// The slab of SemiInfiniteSlabReflectsTheChandrasekharWhiteSkyAlbedo under a uniform sky,
// rendered with `skin`; returns the film.
Film renderSlab(const SkinParams& skin, int spp) {
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  addBox(frame, 50.0f, 50.0f, 0);
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 2, 1), Vec3::Zero(), 10.0f);
  frame.settings = smallSettings(24, spp, 10);
  return renderFrame(frame);
}

// On a flat semi-infinite slab the profile integrates to the skin's albedo A, and the probe's
// weight (R over the density of all axes and channels) must keep that exactly. Skin-like albedos
// and mean free paths of the default skin's ratios.
TEST(SubsurfaceDiffusion, SemiInfiniteSlabReflectsTheAlbedo) {
  const Color albedo(0.56f, 0.37f, 0.29f);
  const Film film = renderSlab(withDiffusion(indexMatchedSubsurfaceSkin(albedo, Color(0.013f, 0.0095f, 0.0067f))), 64);
  for (int c = 0; c < 3; ++c) {
    const test::MeanEstimate e = test::channelMean(film, c);
    std::printf("[subsurface diffusion] slab channel %d: rendered %.4f +- %.4f, albedo %.4f\n", c, e.mean,
                e.standardError, albedo[c]);
    EXPECT_NEAR(e.mean, albedo[c], 5.0 * e.standardError + 0.003) << "channel " << c;
  }
}

// On the same slab under a uniform sky every probe that meets the skin weighs the same sum of
// channels (only its colour varies); what varies the sum from sample to sample is whether the
// probe took the normal or a tangent axis (tangent probes find nothing on a flat slab) and the
// light. The probe's choices read the sample's stratified numbers, so a pixel's 16 samples take
// the axes in close to their proportions. With the choices drawn independently the binomial
// share of misses alone spreads the pixels' sums by sqrt(0.2 * 0.8 / 16) / 0.8 = 0.125 of the
// mean (measured 0.141 then, with the light's share); stratified, 0.090.
TEST(SubsurfaceDiffusion, ProbeChoicesAreStratifiedOverAPixelsSamples) {
  const Color albedo(0.56f, 0.37f, 0.29f);
  const Film film = renderSlab(withDiffusion(indexMatchedSubsurfaceSkin(albedo, Color(0.013f, 0.0095f, 0.0067f))), 16);
  const size_t pixels = size_t(film.width) * film.height;
  double sum = 0.0, sumOfSquares = 0.0;
  for (size_t p = 0; p < pixels; ++p) {
    const double channelSum = double(film.rgba[4 * p]) + film.rgba[4 * p + 1] + film.rgba[4 * p + 2];
    sum += channelSum;
    sumOfSquares += channelSum * channelSum;
  }
  const double mean = sum / double(pixels);
  const double relativeSpread = std::sqrt(std::max(0.0, sumOfSquares / double(pixels) - mean * mean)) / mean;
  std::printf("[subsurface diffusion] slab at 16 spp: the pixels' channel sums spread %.4f of their mean\n",
              relativeSpread);
  EXPECT_LT(relativeSpread, 0.11);
}

// The two methods agree on the slab: the random walk reaches van de Hulst's white-sky albedo
// (singleScatteringAlbedoFor inverts it; the H-function agrees within 0.002), the profile its
// integral. Within 5 standard errors of the difference plus 1 % of the albedo.
TEST(SubsurfaceDiffusion, SlabMatchesTheRandomWalk) {
  const SkinParams walk = indexMatchedSubsurfaceSkin(Color(0.8f, 0.5f, 0.2f), Color(0.02f, 0.01f, 0.005f));
  const Film walked = renderSlab(walk, 48);
  const Film probed = renderSlab(withDiffusion(walk), 48);
  for (int c = 0; c < 3; ++c) {
    const test::MeanEstimate w = test::channelMean(walked, c), p = test::channelMean(probed, c);
    const double error = std::hypot(w.standardError, p.standardError);
    std::printf("[subsurface diffusion] slab channel %d: walk %.4f +- %.4f, diffusion %.4f +- %.4f\n", c, w.mean,
                w.standardError, p.mean, p.standardError);
    EXPECT_NEAR(p.mean, w.mean, 5.0 * error + 0.01 * walk.albedo[c]) << "channel " << c;
  }
}

// A slab thinner than the profile's reach under a uniform sky: the normal probes' chords cross
// both faces, and the probe takes one of the two crossings (subsurface_probe.cpp). With any
// choice whose probability the weight divides by, the camera sees the profile's integral over
// both faces: A from the top, and from the bottom face at depth h, with rho = sqrt(r^2 + h^2),
//   integral R(rho) 2 pi r dr = A / (4 * 0.99) [(e^(-h/d) - e^(-rMax/d)) + 3 (e^(-h/3d) - e^(-rMax/3d))]
// (R of diffusion_profile.hpp, cut at rMax and scaled by 1 / 0.99). Every exit sees the sky.
TEST(SubsurfaceDiffusion, ThinSlabReturnsTheProfileOverBothFaces) {
  const Color albedo(0.8f, 0.6f, 0.4f), meanFreePath(0.013f, 0.0095f, 0.0067f);
  const float thickness = 0.02f;
  Frame frame;
  frame.materials.push_back(Material{"skin", withDiffusion(indexMatchedSubsurfaceSkin(albedo, meanFreePath)), Color::Zero()});
  // Opposite windings: the bottom face's normal points out of the slab as the top's does.
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3::Zero(), Vec3(100, 0, 0), Vec3(0, 0, 100)), 0});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, -thickness, 0), Vec3(0, 0, 100), Vec3(100, 0, 0)), 0});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 2, 1), Vec3::Zero(), 10.0f);
  frame.settings = smallSettings(24, 64, 10);
  const Film film = renderFrame(frame);
  const DiffusionProfile profile(albedo, meanFreePath);
  for (int c = 0; c < 3; ++c) {
    const double d = profile.shape()[c], rMax = profile.maxRadius(c), h = thickness;
    const double bottom = albedo[c] / (4.0 * 0.99) *
                          ((std::exp(-h / d) - std::exp(-rMax / d)) + 3.0 * (std::exp(-h / (3 * d)) - std::exp(-rMax / (3 * d))));
    const double expected = albedo[c] + bottom;
    const test::MeanEstimate e = test::channelMean(film, c);
    std::printf("[subsurface diffusion] thin slab channel %d: rendered %.4f +- %.4f, expected %.4f (bottom face %.4f)\n",
                c, e.mean, e.standardError, expected, bottom);
    EXPECT_NEAR(e.mean, expected, 5.0 * e.standardError + 0.01 * expected) << "channel " << c;
  }
}

// Without absorption (A = 1) a sphere much larger than the profile returns the environment: the
// probe's density stays a density on a curved surface (axes and channels combined). On a sphere
// the area within a distance d of a point is pi d^2, as on a plane (Archimedes), so the
// flat-surface profile integrates to 1 there too. Floor 0.3 %: a density that counted channels
// whose chords cannot reach the exit (pbrt-v3's Pdf_Sp) read 0.989 in red and fails.
TEST(SubsurfaceDiffusion, FurnaceSphereReturnsTheEnvironment) {
  Frame frame;
  frame.materials.push_back(Material{
      "skin", withDiffusion(indexMatchedSubsurfaceSkin(Color::Ones(), Color(0.004f, 0.003f, 0.002f))), Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 0});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 0, 3), Vec3::Zero(), 15.0f);
  frame.settings = smallSettings(32, 256, 10);
  const Film film = renderFrame(frame);
  for (int c = 0; c < 3; ++c) {
    const test::MeanEstimate e = test::channelMean(film, c);
    std::printf("[subsurface diffusion] furnace channel %d: %.4f +- %.4f (exact 1)\n", c, e.mean, e.standardError);
    EXPECT_NEAR(e.mean, 1.0, 5.0 * e.standardError + 0.003) << "channel " << c;
  }
}

// Absorption must show: the same sphere at albedo 0.3 is far darker (the furnace can fail).
TEST(SubsurfaceDiffusion, AbsorbingSphereIsDarker) {
  Frame frame;
  frame.materials.push_back(Material{
      "skin", withDiffusion(indexMatchedSubsurfaceSkin(Color::Constant(0.3f), Color::Constant(0.004f))), Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 0});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 0, 3), Vec3::Zero(), 15.0f);
  frame.settings = smallSettings(16, 16, 10);
  const test::MeanEstimate e = test::channelMean(renderFrame(frame), 0);
  EXPECT_NEAR(e.mean, 0.3, 5.0 * e.standardError + 0.015);
}

// A mean free path far below the ray offsets (a mean-free-path map can scale it down to 1e-4):
// the exit lands next to the entry, rounding puts a candidate's radius past the cut, and that must
// not divide by a zero density (it once gave infinite pixels). The skin then looks Lambertian.
TEST(SubsurfaceDiffusion, TinyMeanFreePathStaysFiniteAndKeepsTheAlbedo) {
  Frame frame;
  frame.materials.push_back(Material{
      "skin", withDiffusion(indexMatchedSubsurfaceSkin(Color::Constant(0.5f), Color::Constant(1e-7f))), Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3(0.2f, 0.1f, 0), 0.5f, 0});
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0.2f, 0.1f, 3), Vec3(0.2f, 0.1f, 0), 15.0f);
  frame.settings = smallSettings(32, 32, 10);
  const Film film = renderFrame(frame);
  for (int c = 0; c < 3; ++c) {
    const test::MeanEstimate e = test::channelMean(film, c);
    std::printf("[subsurface diffusion] tiny mean free path, channel %d: %.4f +- %.4f (albedo 0.5)\n", c, e.mean,
                e.standardError);
    EXPECT_LT(e.standardError, 0.01) << "channel " << c << ": outliers";
    EXPECT_NEAR(e.mean, 0.5, 5.0 * e.standardError + 0.03) << "channel " << c;
  }
}

TEST(SubsurfaceDiffusion, OneAndTwoThreadsGiveBitwiseEqualFilms) {
  test::expectThreadCountIndependent(litSubsurfaceSphere(SubsurfaceMethod::Diffusion));
}

// A white diffuse sphere on a floor of subsurface skin, under a uniform sky, with the camera close
// enough that every pixel sees the sphere: the skin is met only after a diffuse bounce, where it
// shades with its Lambertian base (integrator.cpp, PathIntegrator::radiance). The film is then the
// one rendered with the same skin without subsurface, bitwise (both draw the same numbers), and not
// the one without a floor (the floor's light is in it). Seen directly, the subsurface skin differs.
Frame sphereOnSkinFloor(const SkinParams& skin, bool floor) {
  Frame frame;
  frame.materials.push_back(Material{"white", DiffuseParams{Color::Constant(0.8f)}, Color::Zero()});
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3(0, 0.5f, 0), 0.5f, 0});
  if (floor) addBox(frame, 5.0f, 1.0f, 1);
  frame.uniformBackground = Color::Ones();
  frame.camera = lookAt(Vec3(0, 0.5f, 3), Vec3(0, 0.5f, 0), 8.0f);
  frame.settings = smallSettings(12, 8, 6);
  return frame;
}

TEST(SubsurfaceDiffusion, SkinMetAfterADiffuseBounceShadesWithItsLambertianBase) {
  SkinParams subsurface = withDiffusion(indexMatchedSubsurfaceSkin(Color(0.56f, 0.37f, 0.29f), Color(0.02f, 0.01f, 0.005f)));
  subsurface.ior = 1.4f;
  SkinParams lambertian = subsurface;
  lambertian.subsurface.reset();
  const Film withSubsurface = renderFrame(sphereOnSkinFloor(subsurface, true));
  const Film withLambertian = renderFrame(sphereOnSkinFloor(lambertian, true));
  const Film withoutFloor = renderFrame(sphereOnSkinFloor(lambertian, false));
  EXPECT_EQ(withSubsurface.rgba, withLambertian.rgba);
  EXPECT_NE(withLambertian.rgba, withoutFloor.rgba) << "the floor's light must be in the film";
  // Seen directly (the camera looks down at the floor beside the sphere), the skin scatters below.
  Frame direct = sphereOnSkinFloor(subsurface, true);
  direct.camera = lookAt(Vec3(2, 2, 2), Vec3(2, 0, 1), 20.0f);
  Frame directLambertian = direct;
  directLambertian.materials[1].params = lambertian;
  EXPECT_NE(renderFrame(direct).rgba, renderFrame(directLambertian).rgba);
}

// A skin slab (index 1.4) under a rectangular light placed so that the camera sees its glossy
// reflection, with light-path AOVs.
Frame skinUnderItsReflectedLight(const SkinParams& skin, uint64_t seed) {
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  addBox(frame, 2.0f, 1.0f, 0);
  AreaLight light;
  light.center = Vec3(0, 1, -1.5f);
  light.edgeU = Vec3(0.4f, 0, 0);
  light.edgeV = Vec3(0, 1.5f, 1.0f).normalized() * 0.4f;  // emits towards the slab's centre
  light.radiance = Color::Constant(4.0f);
  frame.lights.push_back(light);
  frame.uniformBackground = Color::Constant(0.05f);
  frame.camera = lookAt(Vec3(0, 1, 1.5f), Vec3::Zero(), 30.0f);
  frame.settings = smallSettings(24, 16, 6);
  frame.settings.seed = seed;
  frame.settings.lightPaths.addAll();
  return frame;
}

// The mean of the specular_direct pass over two renders (seeds 1 and 2), and its per-render noise:
// the RMS of their difference over sqrt(2).
struct PassEstimate {
  double mean = 0.0, noise = 0.0;
};
PassEstimate specularDirectOf(const SkinParams& skin) {
  const Film a = renderFrame(skinUnderItsReflectedLight(skin, 1)), b = renderFrame(skinUnderItsReflectedLight(skin, 2));
  const std::vector<float>& x = test::rgbLayer(a, lightPathName(LightPath::SpecularDirect)).data;
  const std::vector<float>& y = test::rgbLayer(b, lightPathName(LightPath::SpecularDirect)).data;
  double sum = 0.0, squares = 0.0;
  for (size_t i = 0; i < x.size(); ++i) sum += 0.5 * (x[i] + y[i]), squares += (x[i] - y[i]) * double(x[i] - y[i]);
  return {sum / double(x.size()), std::sqrt(squares / double(x.size()) / 2.0)};
}

// On subsurface skin the path goes on by the specular lobes only with their probability pSurface
// (~0.1 here), so light those lobes find by sampling counts 1 / pSurface times. Its MIS weight must
// count that probability in the BSDF technique's density (integrator.cpp, Vertex::
// bsdfSamplingProbability), or the glossy highlight is far noisier than on Lambertian skin with the
// same lobes: measured 2.2x the noise without (0.0022 against 0.0010), 1.1x with. The mean is the
// same either way (both are unbiased).
TEST(SubsurfaceDiffusion, TheSheenOnSubsurfaceSkinIsNoNoisierThanOnLambertianSkin) {
  SkinParams subsurface = withDiffusion(indexMatchedSubsurfaceSkin(Color(0.56f, 0.37f, 0.29f), Color(0.01f, 0.007f, 0.005f)));
  subsurface.ior = 1.4f;
  SkinParams lambertian = subsurface;
  lambertian.subsurface.reset();
  const PassEstimate withSubsurface = specularDirectOf(subsurface), withLambertian = specularDirectOf(lambertian);
  std::printf("[subsurface diffusion] specular direct: subsurface %.4f (noise %.4f), Lambertian %.4f (noise %.4f)\n",
              withSubsurface.mean, withSubsurface.noise, withLambertian.mean, withLambertian.noise);
  ASSERT_GT(withLambertian.mean, 0.01) << "the camera must see the light's reflection";
  const double pixels = 24.0 * 24.0 * 3.0 * 2.0;
  const double standardError = std::hypot(withSubsurface.noise, withLambertian.noise) / std::sqrt(pixels);
  EXPECT_NEAR(withSubsurface.mean, withLambertian.mean, 5.0 * standardError + 1e-3);
  EXPECT_LT(withSubsurface.noise, 1.3 * withLambertian.noise);
}

}  // namespace subsurface_test
}  // namespace lacrima
