// Wet skin in renders (MeshInstance::wetness, materials/wet_skin.hpp): a skin floor under a tear
// film keeps its colour under uniform light (skin's own surface already traps its diffuse light),
// by what the BSDF's albedo predicts, and its highlight of a small light at the mirror direction
// is brighter; a zero or empty film, or a film on a non-skin material, renders bitwise as dry.
#include <gtest/gtest.h>

#include <algorithm>

#include "lacrima/materials/wet_skin.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/bsdf_albedo.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace wet_skin_render_test {

using test::lookAt;
using test::smallSettings;

constexpr float kTrailFilm = 20e-6f;  // a fresh tear trail (LiquidTearParams::filmThickness)

// A skin floor (y = 0) seen from 45 degrees above, filling the view, under a uniform environment
// of radiance 1; film metres on every vertex (negative: no wetness field at all).
Frame skinFloor(float film, const MaterialParams& material = SkinParams{}) {
  Frame frame;
  frame.materials.push_back(Material{"skin", material, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  if (film >= 0.0f) frame.meshes.back().wetness.assign(4, film);
  frame.camera = lookAt(Vec3(0, 1, 1), Vec3::Zero(), 10.0f);
  frame.settings = smallSettings(16, 64, 3);
  frame.uniformBackground = Color::Ones();
  return frame;
}

Color meanColor(const Film& film) {
  Color sum = Color::Zero();
  for (size_t p = 0; p < film.rgba.size(); p += 4) sum += Color(film.rgba[p], film.rgba[p + 1], film.rgba[p + 2]);
  return sum / float(film.rgba.size() / 4);
}

float peakRed(const Film& film) {
  float peak = 0.0f;
  for (size_t p = 0; p < film.rgba.size(); p += 4) peak = std::max(peak, film.rgba[p]);
  return peak;
}

// Directional albedo of a BSDF at wo (2000x720 quadrature cells).
Color directionalAlbedo(const Bsdf& bsdf, const Vec3& wo) { return test::directionalAlbedo(bsdf, wo, 2000, 720); }

TEST(WetSkinRender, WetFloorKeepsItsColourUnderUniformLightAsTheBsdfPredicts) {
  const Color dry = meanColor(renderFrame(skinFloor(-1.0f))), wet = meanColor(renderFrame(skinFloor(kTrailFilm)));
  std::printf("[ wet ] mean under uniform light: dry %.4f %.4f %.4f, wet %.4f %.4f %.4f\n", dry.x(), dry.y(), dry.z(),
              wet.x(), wet.y(), wet.z());
  // Lekner & Dorf's film over a base meeting air would make it ~30% darker (a brownish stain);
  // over skin the diffuse stays within 1% and the film's reflection replaces the skin's.
  EXPECT_TRUE(((wet - dry).cwiseAbs() < 0.05f * dry).all()) << "wet " << wet.transpose() << " dry " << dry.transpose();
  // Under a uniform environment of radiance 1 the floor shows its directional albedo (the view
  // spans 10 degrees around 45: a 2% tolerance).
  const SkinBsdf skin{SkinParams{}};
  const Vec3 wo = Vec3(0.0f, std::sqrt(0.5f), std::sqrt(0.5f));
  const Color expectedWet = directionalAlbedo(WetSkinBsdf(skin, wetFilmCoverage(kTrailFilm)), wo);
  const Color expectedDry = directionalAlbedo(skin, wo);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(wet[c], expectedWet[c], 0.02f * expectedWet[c]) << "channel " << c;
    EXPECT_NEAR(dry[c], expectedDry[c], 0.02f * expectedDry[c]) << "channel " << c;
  }
}

TEST(WetSkinRender, HighlightOfASmallLightIsBrighterWhenWet) {
  // A small sphere light at the camera's mirror direction about the floor.
  AreaLight light;
  light.shape = AreaLight::Shape::Sphere;
  light.center = Vec3(0, 3, -3);
  light.radius = 0.05f;
  light.radiance = Color::Constant(50.0f);
  Frame dryFrame = skinFloor(-1.0f), wetFrame = skinFloor(kTrailFilm);
  for (Frame* frame : {&dryFrame, &wetFrame}) {
    frame->uniformBackground = Color::Zero();
    frame->lights = {light};
  }
  const float dryPeak = peakRed(renderFrame(dryFrame)), wetPeak = peakRed(renderFrame(wetFrame));
  std::printf("[ wet ] highlight peak: dry %.3f, wet %.3f\n", dryPeak, wetPeak);
  EXPECT_GT(wetPeak, 3.0f * dryPeak);
}

TEST(WetSkinRender, NoFilmOrNonSkinRendersBitwiseDry) {
  const Film dry = renderFrame(skinFloor(-1.0f));
  EXPECT_EQ(renderFrame(skinFloor(0.0f)).rgba, dry.rgba);
  const DiffuseParams grey{Color::Constant(0.5f)};
  EXPECT_EQ(renderFrame(skinFloor(kTrailFilm, grey)).rgba, renderFrame(skinFloor(-1.0f, grey)).rgba);
  // And a film on skin does change it (the check above can fail).
  EXPECT_NE(renderFrame(skinFloor(kTrailFilm)).rgba, dry.rgba);
}

// A closed water slab lying on the floor, its base just under it (as beads and rivulets lie on skin).
MeshInstance waterSlab(uint32_t materialId) {
  const float half = 50.0f, top = 0.01f, bottom = -2e-5f;
  MeshInstance slab;
  slab.materialId = materialId;
  for (int corner = 0; corner < 8; ++corner)
    slab.mesh.positions.emplace_back(corner & 1 ? half : -half, corner & 2 ? top : bottom, corner & 4 ? half : -half);
  // Counter-clockwise seen from outside.
  slab.mesh.indices = {0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2,
                       1, 3, 7, 1, 7, 5, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  return slab;
}

// Skin under a bead is wetted by the bead: the film of the trail under it adds nothing (its top
// surface would be a second reflection, facing air, under water).
TEST(WetSkinRender, SkinUnderWaterShadesWithoutItsFilm) {
  auto underWater = [](float film) {
    Frame frame = skinFloor(film);
    frame.materials.push_back(Material{"water", SmoothDielectricParams{1.337f}, Color::Zero()});
    frame.meshes.push_back(waterSlab(1));
    return frame;
  };
  ASSERT_EQ(findClosedMeshDefect(waterSlab(1).mesh), "");
  ASSERT_GT(signedVolume(waterSlab(1).mesh), 0.0);
  const Film dry = renderFrame(underWater(-1.0f));
  EXPECT_EQ(renderFrame(underWater(kTrailFilm)).rgba, dry.rgba);
  EXPECT_NE(dry.rgba, renderFrame(skinFloor(-1.0f)).rgba);  // the water is there
}

// Skin under water reflects against water: Fresnel's equations take the ratio of the indices, so
// a skin whose surface layer has the water's own index reflects nothing there. With a black base
// the floor then renders as a black one does under the same water (only the water's surfaces
// reflect); the old shading against air left its specular lobes with F(0) = 2 %.
TEST(WetSkinRender, SkinUnderWaterOfTheWatersIndexReflectsNothing) {
  SkinParams blackSkin;
  blackSkin.albedo = Color::Zero();
  blackSkin.ior = kWaterIor;
  auto underWater = [](const MaterialParams& floor) {
    Frame frame = skinFloor(-1.0f, floor);
    frame.materials.push_back(Material{"water", SmoothDielectricParams{kWaterIor}, Color::Zero()});
    frame.meshes.push_back(waterSlab(1));
    return frame;
  };
  const Color skin = meanColor(renderFrame(underWater(blackSkin)));
  const Color black = meanColor(renderFrame(underWater(DiffuseParams{Color::Zero()})));
  const Color skinInAir = meanColor(renderFrame(skinFloor(-1.0f, blackSkin)));
  std::printf("[ wet ] black floor under water: skin of the water's index %.6f, black %.6f; the skin in air %.6f\n",
              skin.x(), black.x(), skinInAir.x());
  EXPECT_GT(skinInAir.x(), 0.01f);  // in air the same skin does reflect
  EXPECT_TRUE(((skin - black).cwiseAbs() < 1e-6f).all()) << "skin " << skin.transpose() << " black " << black.transpose();
}

TEST(WetSkinRender, WetnessOfTheWrongSizeIsRejected) {
  Frame frame = skinFloor(kTrailFilm);
  frame.meshes.back().wetness.push_back(0.0f);
  EXPECT_THROW(renderFrame(frame), std::invalid_argument);
}

}  // namespace wet_skin_render_test
}  // namespace lacrima
