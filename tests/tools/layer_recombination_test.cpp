// The compositing layers on the regression shots (tests/data/regression): each shot rendered by
// `lacrima render` with the light-path passes and the light groups (float beauty, 2 spp: the sums
// do not depend on the noise), and in every frame the nine passes, and the groups, add up to the
// beauty in every pixel to float rounding (docs/compositing.md).
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "support/regression_shots.hpp"
#include "support/run_command.hpp"

namespace lacrima {
namespace layer_recombination_test {

namespace fs = std::filesystem;

const fs::path& kRegressionDir = test::regressionDir();

struct ExrChannels {
  int pixels = 0;
  std::map<std::string, std::vector<float>> byName;
};

ExrChannels readChannels(const fs::path& path) {
  ExrChannels out;
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) {
    ADD_FAILURE() << "cannot read " << path;
    return out;
  }
  const OIIO::ImageSpec& spec = input->spec();
  out.pixels = spec.width * spec.height;
  std::vector<float> all(size_t(out.pixels) * size_t(spec.nchannels));
  EXPECT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()));
  for (int c = 0; c < spec.nchannels; ++c) {
    std::vector<float>& channel = out.byName[spec.channelnames[size_t(c)]];
    for (int p = 0; p < out.pixels; ++p) channel.push_back(all[size_t(p) * size_t(spec.nchannels) + size_t(c)]);
  }
  return out;
}

// The largest |sum of the layers - beauty| / max(|beauty|, 1e-3) over pixels and R, G, B.
double worstRecombination(const ExrChannels& exr, const std::vector<std::string>& layers) {
  double worst = 0.0;
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float>& beauty = exr.byName.at(c);
    for (int p = 0; p < exr.pixels; ++p) {
      double sum = 0.0;
      for (const std::string& layer : layers) sum += exr.byName.at(layer + "." + c)[size_t(p)];
      worst = std::max(worst, std::abs(sum - beauty[size_t(p)]) / std::max(1e-3, std::abs(double(beauty[size_t(p)]))));
    }
  }
  return worst;
}

std::vector<std::string> lightGroupLayers(const ExrChannels& exr) {
  std::vector<std::string> layers;
  for (const auto& [name, values] : exr.byName)
    if (name.rfind("lightgroup_", 0) == 0 && name.size() > 2 && name.substr(name.size() - 2) == ".R")
      layers.push_back(name.substr(0, name.size() - 2));
  return layers;
}

class LayerRecombination : public ::testing::TestWithParam<std::string> {};

TEST_P(LayerRecombination, ThePassesAndTheGroupsAddUpToTheBeauty) {
  const std::string name = GetParam();
  const fs::path dir = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "recombination" / name;
  fs::remove_all(dir);
  const auto run = test::runCommand(std::string(LACRIMA_BINARY) + " render " +
                                    test::shellQuote((kRegressionDir / (name + ".json")).string()) +
                                    " --spp 2 --no-denoise --float --aov lightPaths --aov lightGroups --quiet --out " +
                                    test::shellQuote((dir / "f.####.exr").string()));
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  const std::vector<std::string> passes = {"diffuse_direct",        "diffuse_indirect", "specular_direct",
                                           "specular_indirect",     "transmission_direct",
                                           "transmission_indirect", "subsurface",       "emission",
                                           "environment"};
  int frames = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".exr") continue;
    ++frames;
    const ExrChannels exr = readChannels(e.path());
    const std::vector<std::string> groups = lightGroupLayers(exr);
    EXPECT_FALSE(groups.empty()) << e.path();
    EXPECT_LT(worstRecombination(exr, passes), 1e-5) << e.path() << ": the light-path passes";
    EXPECT_LT(worstRecombination(exr, groups), 1e-5) << e.path() << ": the light groups";
  }
  EXPECT_GT(frames, 0);
}

INSTANTIATE_TEST_SUITE_P(Shots, LayerRecombination, ::testing::ValuesIn(test::regressionShots()),
                         [](const auto& info) { return info.param; });

}  // namespace layer_recombination_test
}  // namespace lacrima
