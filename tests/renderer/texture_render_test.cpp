// Textured materials in renders (MaterialTextures, renderer/src/surface_textures.hpp): a checker
// albedo map shows its two albedos, an sRGB 8-bit map renders like its linear float twin, uvs are
// interpolated linearly (read back through the albedo AOV), a tangent-space normal map tilts the
// shading as a rotated normal would (OpenGL +Y convention), and textured frames stay independent
// of the thread count.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <chrono>
#include <functional>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_directory.hpp"
#include "support/test_scenes.hpp"
#include "lacrima/face/eye.hpp"
#include "lacrima/materials/iris_pattern.hpp"
#include "lacrima/materials/texture_values.hpp"

namespace lacrima {
namespace texture_render_test {

using test::lookAt;
using test::smallSettings;

constexpr int kTextureSize = 64;
constexpr int kImageSize = 32;
const Color kAlbedoA(0.2f, 0.5f, 0.8f);
const Color kAlbedoB(0.7f, 0.3f, 0.1f);

// Writes a kTextureSize^2 RGB image whose texel (column i, row j) is texel(i, j), as FLOAT
// (EXR) or as UINT8 (PNG, values quantised by OIIO).
std::filesystem::path writeTexture(const std::string& name, const std::function<Color(int, int)>& texel,
                                   OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT) {
  const std::filesystem::path path = test::testDirectory("textures") / name;
  std::vector<float> pixels(size_t(kTextureSize) * kTextureSize * 3);
  for (int j = 0; j < kTextureSize; ++j)
    for (int i = 0; i < kTextureSize; ++i)
      for (int c = 0; c < 3; ++c) pixels[3 * (size_t(j) * kTextureSize + i) + c] = texel(i, j)[c];
  auto out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out) << OIIO::geterror();
  const OIIO::ImageSpec spec(kTextureSize, kTextureSize, 3, format);
  EXPECT_TRUE(out->open(path.string(), spec)) << out->geterror();
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  out->close();
  return path;
}

// Texels of the left half of the top rows and the right half of the bottom rows are A, the rest B.
Color checker(int i, int j) { return (i < kTextureSize / 2) == (j < kTextureSize / 2) ? kAlbedoA : kAlbedoB; }

float srgbEncode(float linear) {
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// The 8-bit code the PNG stores for a linear value, and the linear value that code decodes to.
float quantisedSrgb(float linear) { return std::round(srgbEncode(linear) * 255.0f) / 255.0f; }
float decodedSrgb(float linear) { return srgbToLinear(quantisedSrgb(linear)); }

// A 2 x 2 quad in z = 0 facing the camera 3 m away (+z), uv (0,0) at its lower left, uv (1,1) at
// its upper right (makeRectangle); the view spans x, y in [-halfSpan, halfSpan]. Under a uniform
// background of radiance 1 a diffuse surface shows exactly its albedo, without noise (the
// background is not light-sampled and every BSDF sample carries weight albedo).
Frame texturedQuad(const MaterialTextures& textures, float halfSpan = 0.9f) {
  Frame frame;
  Material material("quad", DiffuseParams{Color::Ones()});
  material.textures = textures;
  frame.materials.push_back(material);
  frame.meshes.emplace_back(makeRectangle(Vec3::Zero(), Vec3(2, 0, 0), Vec3(0, 2, 0)), 0);
  frame.camera = lookAt(Vec3(0, 0, 3), Vec3::Zero(), 40.0f);
  frame.camera.verticalFovRadians = 2.0f * std::atan(halfSpan / 3.0f);
  frame.settings = smallSettings(kImageSize, 4, 1);
  frame.uniformBackground = Color::Ones();
  return frame;
}

MaterialTextures albedoMap(const std::filesystem::path& file, TextureEncoding encoding = TextureEncoding::Auto) {
  MaterialTextures textures;
  textures.albedo = TextureMap{file, encoding};
  return textures;
}

Color pixel(const Film& film, int x, int y) {
  const size_t p = film.pixelIndex(x, y);
  return Color(film.rgba[4 * p], film.rgba[4 * p + 1], film.rgba[4 * p + 2]);
}

// Mean colour of the image quadrant (qx, qy) (0 = left / top), a 3-pixel margin off the seams.
Color quadrantMean(const Film& film, int qx, int qy) {
  const int half = kImageSize / 2, margin = 3;
  Color sum = Color::Zero();
  int count = 0;
  for (int y = qy * half + margin; y < (qy + 1) * half - margin; ++y)
    for (int x = qx * half + margin; x < (qx + 1) * half - margin; ++x, ++count) sum += pixel(film, x, y);
  return sum / float(count);
}

void expectColorNear(const Color& actual, const Color& expected, float tolerance, const std::string& what) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(actual[c], expected[c], tolerance) << what << " channel " << c << ": " << actual.transpose()
                                                   << " vs " << expected.transpose();
}

TEST(TextureRender, CheckerAlbedoShowsBothAlbedosInTheirSquares) {
  const Film film = renderFrame(texturedQuad(albedoMap(writeTexture("checker.exr", checker))));
  // Image top = v near 1 = texture rows j >= 32; image left = u < 0.5 = columns i < 32.
  expectColorNear(quadrantMean(film, 0, 0), kAlbedoB, 1e-4f, "top left");
  expectColorNear(quadrantMean(film, 1, 0), kAlbedoA, 1e-4f, "top right");
  expectColorNear(quadrantMean(film, 0, 1), kAlbedoA, 1e-4f, "bottom left");
  expectColorNear(quadrantMean(film, 1, 1), kAlbedoB, 1e-4f, "bottom right");
}

TEST(TextureRender, SrgbEightBitMapRendersLikeItsLinearFloatTwin) {
  const auto png = writeTexture("checker_srgb.png",
                                [](int i, int j) { return checker(i, j).unaryExpr(&srgbEncode).eval(); },
                                OIIO::TypeDesc::UINT8);
  const auto exr = writeTexture("checker_linear.exr",
                                [](int i, int j) { return checker(i, j).unaryExpr(&decodedSrgb).eval(); });
  const Film fromPng = renderFrame(texturedQuad(albedoMap(png)));
  const Film fromExr = renderFrame(texturedQuad(albedoMap(exr)));
  for (int q = 0; q < 4; ++q)
    expectColorNear(quadrantMean(fromPng, q % 2, q / 2), quadrantMean(fromExr, q % 2, q / 2), 1e-5f,
                    "quadrant " + std::to_string(q));
  expectColorNear(quadrantMean(fromPng, 1, 0), kAlbedoA, 3e-3f, "sRGB decoded to linear");
  // Read as linear (colorSpace override), the encoded values are visibly brighter.
  const Film asLinear = renderFrame(texturedQuad(albedoMap(png, TextureEncoding::Linear)));
  expectColorNear(quadrantMean(asLinear, 1, 0), kAlbedoA.unaryExpr(&quantisedSrgb).eval(), 1e-5f, "override");
}

TEST(TextureRender, UvsAreInterpolatedLinearlyAcrossTheQuad) {
  // Texel centres hold their own uv, so bilinear lookups return uv itself between them.
  const auto gradient = writeTexture("uv_gradient.exr", [](int i, int j) {
    return Color((float(i) + 0.5f) / kTextureSize, (float(j) + 0.5f) / kTextureSize, 0.0f);
  });
  const float halfSpan = 0.8f;
  Frame frame = texturedQuad(albedoMap(gradient), halfSpan);
  frame.settings.samplesPerPixel = 64;  // the pixel's mean uv is its centre's, up to the jitter's mean
  const Film film = renderFrame(frame);
  float worst = 0.0f;
  for (int y = 0; y < kImageSize; ++y)
    for (int x = 0; x < kImageSize; ++x) {
      const float worldX = (2.0f * (float(x) + 0.5f) / kImageSize - 1.0f) * halfSpan;
      const float worldY = (1.0f - 2.0f * (float(y) + 0.5f) / kImageSize) * halfSpan;
      const size_t p = film.pixelIndex(x, y);
      worst = std::max({worst, std::abs(film.albedo[3 * p] - 0.5f * (worldX + 1.0f)),
                        std::abs(film.albedo[3 * p + 1] - 0.5f * (worldY + 1.0f))});
    }
  std::printf("[ uv ] largest |albedo AOV - uv| over the image: %.5f\n", worst);
  EXPECT_LT(worst, 0.005f);
}

// A checker of single texels, about 3.6 texels to a pixel: the lookups filter over the pixel's
// footprint (MIP levels built on the fly), so every pixel shows the checker's mean instead of a
// few point samples of it (finest-level lookups left pixels up to 0.17 off the mean here).
TEST(TextureRender, TexelsFinerThanAPixelAreFilteredToTheirMean) {
  const auto fine = writeTexture("fine_checker.exr", [](int i, int j) { return (i + j) % 2 == 0 ? kAlbedoA : kAlbedoB; });
  Frame frame = texturedQuad(albedoMap(fine), 0.9f);
  frame.settings.width = frame.settings.height = 16;
  const Film film = renderFrame(frame);
  const Color mean = 0.5f * (kAlbedoA + kAlbedoB);
  float worst = 0.0f;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) worst = std::max(worst, (pixel(film, x, y) - mean).cwiseAbs().maxCoeff());
  std::printf("[ mip ] largest pixel deviation from the checker's mean: %.5f\n", worst);
  EXPECT_LT(worst, 0.01f);
}

// The procedural iris (iris_pattern.hpp) in place of an albedo map: no file, and the quad shows the
// albedo times the pattern at each pixel's uv (their correlation over the iris's disc; a pattern
// looked up at the wrong uv, flipped or not at all, correlates near 0).
TEST(TextureRender, AnIrisPatternShowsItsLayersWhereItsUvsPutThem) {
  constexpr int kSize = 96;
  constexpr float kAlbedo = 0.3f;
  Frame frame = texturedQuad({});
  frame.materials[0].params = DiffuseParams{Color::Constant(kAlbedo)};
  frame.materials[0].textures.irisPattern = IrisPatternParams{3};
  frame.settings = smallSettings(kSize, 16, 1);
  const Film film = renderFrame(frame);
  const IrisPattern pattern(3);
  double sumR = 0, sumE = 0, sumRR = 0, sumEE = 0, sumRE = 0;
  int count = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      // Image x, y to the quad's uv: (0, 0) at its lower left, the view spanning [-0.9, 0.9].
      const Vec2 uv(0.5f * (1.0f - 0.9f + 1.8f * (float(x) + 0.5f) / kSize),
                    0.5f * (1.0f + 0.9f - 1.8f * (float(y) + 0.5f) / kSize));
      const float radius = 2.0f * (uv - Vec2(0.5f, 0.5f)).norm();
      if (radius < kIrisUvPupilRadius || radius > 0.9f) continue;
      const double rendered = pixel(film, x, y).mean(), expected = kAlbedo * pattern.factorAt(uv).mean();
      sumR += rendered, sumE += expected, sumRR += rendered * rendered, sumEE += expected * expected;
      sumRE += rendered * expected, ++count;
    }
  const double meanR = sumR / count, meanE = sumE / count;
  const double correlation = (sumRE / count - meanR * meanE) /
                             std::sqrt((sumRR / count - meanR * meanR) * (sumEE / count - meanE * meanE));
  std::printf("[ info     ] iris quad: mean %.4f (pattern %.4f), correlation %.3f over %d pixels\n", meanR, meanE,
              correlation, count);
  EXPECT_NEAR(meanR, meanE, 0.03 * meanE);
  EXPECT_GT(correlation, 0.8);
}

TEST(TextureRender, MeshWithoutUvsShadesWithTheConstants) {
  Frame frame = texturedQuad(albedoMap(writeTexture("checker_no_uv.exr", checker)));
  frame.meshes[0].mesh.uvs.clear();
  std::get<DiffuseParams>(frame.materials[0].params).albedo = Color::Constant(0.4f);
  const Film film = renderFrame(frame);
  expectColorNear(quadrantMean(film, 0, 0), Color::Constant(0.4f), 1e-5f, "no uvs");
}

// Radiance of the quad lit by a small distant sphere light in direction `toLight`, with a
// constant tangent-space normal map `tangentNormal` (none: no map).
Color litQuad(const Vec3& toLight, const std::optional<Vec3>& tangentNormal) {
  MaterialTextures textures;
  if (tangentNormal) {
    const Color encoded = 0.5f * (tangentNormal->normalized().array() + 1.0f);
    textures.normal = TextureMap{writeTexture(tangentNormal->x() != 0.0f ? "tilt_x.exr" : "tilt_y.exr",
                                              [&](int, int) { return encoded; }),
                                 TextureEncoding::Auto};
  }
  Frame frame = texturedQuad(textures);
  frame.uniformBackground = Color::Zero();
  AreaLight light;
  light.shape = AreaLight::Shape::Sphere;
  light.center = 100.0f * toLight.normalized();
  light.radius = 2.0f;
  light.radiance = Color::Constant(50.0f);
  frame.lights.push_back(light);
  frame.settings.samplesPerPixel = 16;
  const Film film = renderFrame(frame);
  Color sum = Color::Zero();
  for (int q = 0; q < 4; ++q) sum += quadrantMean(film, q % 2, q / 2);
  return sum / 4.0f;
}

// A Lambertian surface under a small light reflects in proportion to the cosine between the
// shading normal and the light: a uniform tilt of beta about an axis scales the flat quad's
// radiance by cos(gamma -+ beta) / cos(gamma). Red tilts towards +u (+x here), green towards up
// the image, decreasing v: world -y here, since v grows with world y on this quad.
TEST(TextureRender, UniformNormalMapTiltsTheShadingLikeARotatedNormal) {
  const float beta = degreesToRadians(30.0f), gamma = degreesToRadians(40.0f);
  const Vec3 lightX(std::sin(gamma), 0.0f, std::cos(gamma)), lightY(0.0f, std::sin(gamma), std::cos(gamma));
  const Color flatX = litQuad(lightX, std::nullopt), flatY = litQuad(lightY, std::nullopt);
  const Color tiltX = litQuad(lightX, Vec3(std::sin(beta), 0.0f, std::cos(beta)));
  const Color tiltY = litQuad(lightY, Vec3(0.0f, std::sin(beta), std::cos(beta)));
  const float expectedX = std::cos(gamma - beta) / std::cos(gamma);  // towards the light: brighter
  const float expectedY = std::cos(gamma + beta) / std::cos(gamma);  // away from it: darker
  std::printf("[ normal map ] ratio x %.4f (expected %.4f), y %.4f (expected %.4f)\n", tiltX.x() / flatX.x(),
              expectedX, tiltY.x() / flatY.x(), expectedY);
  EXPECT_NEAR(tiltX.x() / flatX.x(), expectedX, 0.02f);
  EXPECT_NEAR(tiltY.x() / flatY.x(), expectedY, 0.02f);
}

// A 3 mm slab of subsurface skin (two 100 m rectangles with uvs, the top at y = 0 facing up, the
// bottom facing down) under a uniform sky of radiance 1, seen from above. Walks leave through
// either face and see the sky, so the slab shows its reflectance plus transmittance, which falls
// as the mean free path shrinks against the fixed thickness (more absorption on the way).
Frame skinSlab(const MaterialTextures& textures) {
  Frame frame;
  SkinParams skin;
  skin.albedo = Color(0.6f, 0.45f, 0.35f);
  skin.subsurface = SubsurfaceParams{};
  Material material("skin", skin);
  material.textures = textures;
  frame.materials.push_back(material);
  frame.meshes.emplace_back(makeRectangle(Vec3::Zero(), Vec3(100, 0, 0), Vec3(0, 0, -100)), 0);
  frame.meshes.emplace_back(makeRectangle(Vec3(0, -0.003f, 0), Vec3(100, 0, 0), Vec3(0, 0, 100)), 0);
  frame.camera = lookAt(Vec3(0, 1, 1), Vec3::Zero(), 10.0f);
  frame.settings = smallSettings(16, 32, 8);
  frame.uniformBackground = Color::Ones();
  return frame;
}

// Maps of ones change nothing, bit for bit: the per-hit BSDF and subsurface medium are built from
// the same numbers as the material's own. A map halving the mean free path darkens the slab.
TEST(TextureRender, SkinMapsOfOneRenderBitwiseAsTheUntexturedSkin) {
  const auto ones = writeTexture("ones.exr", [](int, int) { return Color::Ones().eval(); });
  const auto halves = writeTexture("halves.exr", [](int, int) { return Color::Constant(0.5f).eval(); });
  MaterialTextures unit;
  unit.albedo = unit.roughness = unit.meanFreePath = TextureMap{ones, TextureEncoding::Auto};
  const Film plain = renderFrame(skinSlab({})), textured = renderFrame(skinSlab(unit));
  EXPECT_TRUE(test::bitwiseEqual(plain.rgba, textured.rgba));
  MaterialTextures shorter;
  shorter.meanFreePath = TextureMap{halves, TextureEncoding::Auto};
  const test::MeanEstimate full = test::channelMean(plain, 0);
  const test::MeanEstimate half = test::channelMean(renderFrame(skinSlab(shorter)), 0);
  std::printf("[ mean free path map ] slab red: %.4f +- %.4f, halved %.4f +- %.4f\n", full.mean, full.standardError,
              half.mean, half.standardError);
  EXPECT_LT(half.mean + 3.0 * (half.standardError + full.standardError), full.mean);
}

// The texture cache lives for the process (surface_textures.hpp): a map rewritten between two
// frames is read again, not served from the cache (its modification time is moved on by 2 s:
// OIIO compares whole seconds).
TEST(TextureRender, AMapRewrittenBetweenFramesIsReadAgain) {
  const auto map = writeTexture("rewritten.exr", checker);
  const Film before = renderFrame(texturedQuad(albedoMap(map)));
  writeTexture("rewritten.exr", [](int, int) { return kAlbedoA; });
  std::filesystem::last_write_time(map, std::filesystem::last_write_time(map) + std::chrono::seconds(2));
  const Film after = renderFrame(texturedQuad(albedoMap(map)));
  expectColorNear(quadrantMean(before, 0, 0), kAlbedoB, 1e-4f, "the checker's top left");
  expectColorNear(quadrantMean(after, 0, 0), kAlbedoA, 1e-4f, "the new map's top left");
}

TEST(TextureRender, TexturedFrameIsIndependentOfTheThreadCount) {
  Frame frame = texturedQuad(albedoMap(writeTexture("checker_threads.exr", checker)));
  frame.uniformBackground = Color(0.3f, 0.6f, 1.0f);
  frame.settings.maxDepth = 4;
  test::expectThreadCountIndependent(frame);
}

TEST(TextureRender, UnreadableTextureIsAnInputErrorNamingMaterialAndFile) {
  const auto missing = test::testDirectory("textures") / "no_such_map.exr";
  try {
    renderFrame(texturedQuad(albedoMap(missing)));
    ADD_FAILURE() << "rendered without the texture";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("material 'quad': cannot read the albedo texture '" + missing.string() + "'", 0), 0u)
        << message;
  }
}

}  // namespace texture_render_test
}  // namespace lacrima
