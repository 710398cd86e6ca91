// Cryptomatte (lacrima/renderer/cryptomatte.hpp): the hash is MurmurHash3_x86_32 and the IDs are
// the specification's (its own examples); the ranking filter orders IDs by coverage; a render
// writes, per pixel, coverages that sum to the pixel's coverage (1 where every sample hit), the
// expected name's ID at a known pixel, a manifest naming every object and material, the same
// layers whatever the thread count, and the same beauty as without them; the EXR carries them.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <nlohmann/json.hpp>

#include "lacrima/base/hash.hpp"
#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/cryptomatte.hpp"
#include "lacrima/renderer/image_output.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_directory.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace cryptomatte_test {

TEST(Cryptomatte, TheHashIsMurmurHash3AndTheIdsAreTheSpecifications) {
  // MurmurHash3_x86_32's reference values (seed 0).
  EXPECT_EQ(murmurHash3_32(""), 0u);
  EXPECT_EQ(murmurHash3_32("hello"), 0x248bfa47u);
  EXPECT_EQ(murmurHash3_32("The quick brown fox jumps over the lazy dog"), 0x2e4ff723u);
  EXPECT_EQ(murmurHash3_32("", 1), 0x514e28b7u);
  // The specification's manifest example: {"bunny": "13851a76", "default": "42c9679f"}.
  EXPECT_EQ(cryptomatteHex(cryptomatteIdOf("bunny")), "13851a76");
  EXPECT_EQ(cryptomatteHex(cryptomatteIdOf("default")), "42c9679f");
  EXPECT_EQ(cryptomatteKey("CryptoObject").size(), 7u);
}

TEST(Cryptomatte, EveryIdIsAFiniteNormalNonZeroFloat) {
  // The exponent is clamped to [1, 254]: hashes whose bits would be 0, a denormal, inf or NaN.
  for (uint32_t hash : {0x00000000u, 0x00000001u, 0x807fffffu, 0x7f800000u, 0xffffffffu, 0x7fc00000u}) {
    const float id = cryptomatteIdOf(hash);
    EXPECT_TRUE(std::isnormal(id)) << std::hex << hash;
    EXPECT_EQ(std::bit_cast<uint32_t>(id) & 0x807fffffu, hash & 0x807fffffu) << "sign and mantissa kept";
  }
  int normal = 0;
  for (uint64_t i = 0; i < 100000; ++i) normal += std::isnormal(cryptomatteIdOf(uint32_t(hashCombine(11, i)))) ? 1 : 0;
  EXPECT_EQ(normal, 100000);
}

TEST(Cryptomatte, TheRankingFilterOrdersIdsByCoverage) {
  IdCoverage coverage;
  coverage.add(3.0f, 0.2f);
  coverage.add(7.0f, 0.5f);
  coverage.add(3.0f, 0.2f);
  coverage.add(5.0f, 0.4f);  // ties with 3.0: the smaller ID first
  const std::vector<float> ranked = coverage.ranked(4, 2.0f);
  const std::vector<float> expected = {7.0f, 0.25f, 3.0f, 0.2f, 5.0f, 0.2f, 0.0f, 0.0f};
  EXPECT_EQ(ranked, expected);
  EXPECT_EQ(coverage.ranked(1, 2.0f), (std::vector<float>{7.0f, 0.25f}));
}

// A porcelain ball in front of a wall that fills the view, lit from above.
Frame ballBeforeAWall() {
  Frame frame;
  frame.materials.push_back(Material{"plaster", DiffuseParams{Color(0.7f, 0.7f, 0.7f)}, Color::Zero()});
  frame.materials.push_back(Material{"porcelain", SkinParams{}, Color::Zero()});
  MeshInstance wall{makeRectangle(Vec3(0, 0, -1), Vec3(20, 0, 0), Vec3(0, 20, 0)), 0};
  wall.mesh.name = "wall";
  frame.meshes.push_back(wall);
  frame.spheres.push_back(Sphere{Vec3(0.023f, 0.011f, 0), 0.3f, 1});  // its edges off the pixels' edges
  test::addTopLightAndView(frame);
  frame.camera = test::lookAt(Vec3(0, 0, 3), Vec3(0, 0, 0), 30.0f);
  frame.settings.samplesPerPixel = 8;
  frame.settings.cryptomatte.objects = true;
  frame.settings.cryptomatte.materials = true;
  return frame;
}

// The (ID, coverage) pairs of pixel (x, y) in a Cryptomatte film layer.
std::vector<float> pairsAt(const Film& film, size_t layer, int x, int y) {
  const FilmLayer& l = film.layers.at(layer);
  const size_t p = film.pixelIndex(x, y), n = l.channels.size();
  return std::vector<float>(l.data.begin() + long(p * n), l.data.begin() + long((p + 1) * n));
}

TEST(Cryptomatte, ARenderRanksEachPixelsObjectsAndMaterialsAndNamesThemAll) {
  Frame frame = ballBeforeAWall();
  const Film film = renderFrame(frame);
  ASSERT_EQ(film.layers.size(), 2u);
  EXPECT_EQ(film.layers[0].channels.front(), "CryptoObject00.R");
  EXPECT_EQ(film.layers[0].channels.back(), "CryptoObject02.A");
  EXPECT_EQ(film.layers[1].channels.front(), "CryptoMaterial00.R");

  // Coverage sums to the pixel's alpha, which is 1 everywhere: the wall fills the view.
  double worst = 0.0;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x)
      for (size_t layer : {0, 1}) {
        const std::vector<float> pairs = pairsAt(film, layer, x, y);
        double sum = 0.0;
        for (size_t r = 1; r < pairs.size(); r += 2) sum += pairs[r];
        worst = std::max(worst, std::abs(sum - 1.0));
        EXPECT_GE(pairs[1], pairs[3]) << "ranked";
      }
  EXPECT_LT(worst, 1e-5);

  // The centre is the ball's, the corner the wall's; an edge pixel has both.
  const std::vector<float> centre = pairsAt(film, 0, film.width / 2, film.height / 2);
  EXPECT_EQ(centre[0], cryptomatteIdOf("sphere 0"));
  EXPECT_EQ(centre[1], 1.0f);
  EXPECT_EQ(pairsAt(film, 1, film.width / 2, film.height / 2)[0], cryptomatteIdOf("porcelain"));
  EXPECT_EQ(pairsAt(film, 0, 0, 0)[0], cryptomatteIdOf("wall"));
  int edges = 0;
  for (int x = 0; x < film.width; ++x) {
    const std::vector<float> row = pairsAt(film, 0, x, film.height / 2);
    if (row[1] < 1.0f && row[3] > 0.0f) ++edges;
  }
  EXPECT_GE(edges, 2) << "the ball's left and right edges share their pixels with the wall";

  // The manifests name every object and material, with their IDs.
  const std::string objects = film.attributes.at("cryptomatte/" + cryptomatteKey("CryptoObject") + "/manifest");
  const nlohmann::json manifest = nlohmann::json::parse(objects);
  for (const char* name : {"wall", "sphere 0", "light0"})
    EXPECT_EQ(manifest.at(name).get<std::string>(), cryptomatteHex(cryptomatteIdOf(name))) << name;
  EXPECT_EQ(manifest.size(), 3u);
  const nlohmann::json materials = nlohmann::json::parse(
      film.attributes.at("cryptomatte/" + cryptomatteKey("CryptoMaterial") + "/manifest"));
  EXPECT_TRUE(materials.contains("plaster") && materials.contains("porcelain"));
  EXPECT_EQ(film.attributes.at("cryptomatte/" + cryptomatteKey("CryptoObject") + "/hash"), "MurmurHash3_32");
  EXPECT_EQ(film.attributes.at("cryptomatte/" + cryptomatteKey("CryptoObject") + "/conversion"), "uint32_to_float32");
}

TEST(Cryptomatte, ALightIsNamedAsItsLightGroup) {
  Frame frame = ballBeforeAWall();
  frame.lights.push_back(frame.lights[0]);
  frame.lights[1].group = "key";
  const CryptomatteNames names = cryptomatteNames(frame);
  EXPECT_EQ(names.objects[names.objects.size() - 2], "light0") << "no lightGroup: its default group's name";
  EXPECT_EQ(names.objects.back(), "key");
  EXPECT_EQ(names.materialManifest.back(), "key");
}

TEST(Cryptomatte, SkinUnderATearsFilmHasAWetNameOfItsOwn) {
  Frame frame = ballBeforeAWall();
  frame.materials[0] = Material{"skin", SkinParams{}, Color::Zero()};
  const auto materialAt = [&](const Frame& f, int x, int y) { return pairsAt(renderFrame(f), 1, x, y)[0]; };
  EXPECT_EQ(materialAt(frame, 0, 0), cryptomatteIdOf("skin"));
  frame.meshes[0].wetness.assign(frame.meshes[0].mesh.positions.size(), 2e-5f);  // a 20 um film all over
  const Film wet = renderFrame(frame);
  EXPECT_EQ(pairsAt(wet, 1, 0, 0)[0], cryptomatteIdOf("skin/wet"));
  EXPECT_EQ(pairsAt(wet, 1, wet.width / 2, wet.height / 2)[0], cryptomatteIdOf("porcelain")) << "the ball is dry";
  const nlohmann::json manifest =
      nlohmann::json::parse(wet.attributes.at("cryptomatte/" + cryptomatteKey("CryptoMaterial") + "/manifest"));
  EXPECT_TRUE(manifest.contains("skin/wet"));
  EXPECT_FALSE(manifest.contains("porcelain/wet")) << "no mesh of porcelain carries a film";
  // A film on a material that does not render one (diffuse plaster) keeps the material's name.
  frame.materials[0] = Material{"plaster", DiffuseParams{Color(0.7f, 0.7f, 0.7f)}, Color::Zero()};
  EXPECT_EQ(materialAt(frame, 0, 0), cryptomatteIdOf("plaster"));
}

TEST(Cryptomatte, TheLayersDoNotDependOnTheThreadsAndLeaveTheBeautyAsItWas) {
  Frame frame = ballBeforeAWall();
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  for (size_t layer : {0, 1}) EXPECT_TRUE(test::bitwiseEqual(one.layers[layer].data, two.layers[layer].data));
  frame.settings.cryptomatte = CryptomatteSettings{};
  const Film plain = renderFrame(frame);
  EXPECT_TRUE(plain.layers.empty());
  EXPECT_TRUE(plain.attributes.empty());
  EXPECT_TRUE(test::bitwiseEqual(plain.rgba, two.rgba)) << "the matte is a by-product of the same samples";
}

TEST(Cryptomatte, TheExrCarriesTheLayersAndTheMetadata) {
  Frame frame = ballBeforeAWall();
  frame.settings.width = 16;
  frame.settings.height = 12;
  const Film film = renderFrame(frame);
  const auto path = test::testDirectory("cryptomatte") / "ball.exr";
  writeExr(path, film, ExrMetadata{}, false);
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  const std::string key = cryptomatteKey("CryptoObject");
  EXPECT_EQ(spec.get_string_attribute("cryptomatte/" + key + "/name"), "CryptoObject");
  EXPECT_EQ(spec.get_string_attribute("cryptomatte/" + key + "/manifest"),
            film.attributes.at("cryptomatte/" + key + "/manifest"));
  const int id = spec.channelindex("CryptoObject00.R"), coverage = spec.channelindex("CryptoObject00.G");
  ASSERT_GE(id, 0);
  ASSERT_GE(coverage, 0);
  EXPECT_EQ(spec.channelformat(id), OIIO::TypeDesc::FLOAT) << "IDs keep their 32 bits";
  std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
  const size_t centre = film.pixelIndex(8, 6);
  EXPECT_EQ(pixels[centre * spec.nchannels + size_t(id)], cryptomatteIdOf("sphere 0"));
  EXPECT_EQ(pixels[centre * spec.nchannels + size_t(coverage)], 1.0f);
}

}  // namespace cryptomatte_test
}  // namespace lacrima
