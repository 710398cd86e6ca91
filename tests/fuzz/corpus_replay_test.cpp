// Replays the fuzz seed corpora and every saved fuzzer finding (tests/fuzz/regressions) through
// the fuzzed input paths, so that a fixed finding stays fixed in the normal test run (and under
// ASan/UBSan in tools/hardening.sh). Also checks that the valid seeds really load: a seed that
// fails early only fuzzes the error path.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <vector>

#include "fuzz_inputs.hpp"
#include "fuzz_support.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/io/performance_track.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::fuzz {
namespace corpus_replay_test {

const std::filesystem::path kFuzzDir = LACRIMA_SOURCE_DIR "/tests/fuzz";
const std::filesystem::path kDataDir = LACRIMA_SOURCE_DIR "/tests/data";

std::vector<uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every regular file of the folders (a missing folder has none), sorted for a stable order.
std::vector<std::filesystem::path> filesIn(const std::vector<std::filesystem::path>& folders) {
  std::vector<std::filesystem::path> files;
  for (const auto& folder : folders) {
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The hand-written seeds of a corpus folder: the inputs a fuzz campaign merged in
// (tools/hardening.sh fuzz-campaign) are named by their SHA-1, without an extension, and need
// not load.
std::vector<std::filesystem::path> handWrittenSeedsIn(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> seeds = filesIn({folder});
  std::erase_if(seeds, [](const std::filesystem::path& file) { return !file.has_extension(); });
  return seeds;
}

void replayFiles(const std::vector<std::filesystem::path>& files,
                 const std::function<void(const uint8_t*, size_t)>& input) {
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    SCOPED_TRACE(file.string());
    const std::vector<uint8_t> bytes = readBytes(file);
    EXPECT_NO_THROW(input(bytes.data(), bytes.size()));
  }
}

void replay(const std::vector<std::filesystem::path>& folders,
            const std::function<void(const uint8_t*, size_t)>& input) {
  replayFiles(filesIn(folders), input);
}

// Every other input a fuzz campaign merged into the shot corpus (named by SHA-1, no extension),
// from the first-th: two tests, so that gtest shards (tools/hardening.sh) and ctest -j replay the
// halves side by side (~1,100 shots, ~250 of them on the ICT face: ~50 s under ASan in one test).
std::vector<std::filesystem::path> halfOfTheShotCampaignInputs(size_t first) {
  std::vector<std::filesystem::path> half;
  size_t index = 0;
  for (const auto& file : filesIn({kFuzzDir / "corpus/shot"}))
    if (!file.has_extension() && index++ % 2 == first) half.push_back(file);
  return half;
}

TEST(FuzzCorpusReplay, ShotSeedsAndFindingsLoadOrThrowInputError) {
  std::vector<std::filesystem::path> files = handWrittenSeedsIn(kFuzzDir / "corpus/shot");
  for (const auto& file : filesIn({kDataDir / "bad_shots", kDataDir / "regression", kFuzzDir / "regressions/shot"}))
    files.push_back(file);
  replayFiles(files, loadShotInput);
}

TEST(FuzzCorpusReplay, ShotCampaignInputsFirstHalfLoadOrThrowInputError) {
  replayFiles(halfOfTheShotCampaignInputs(0), loadShotInput);
}

TEST(FuzzCorpusReplay, ShotCampaignInputsSecondHalfLoadOrThrowInputError) {
  replayFiles(halfOfTheShotCampaignInputs(1), loadShotInput);
}

TEST(FuzzCorpusReplay, GltfSeedsAndFindingsLoadOrThrowInputError) {
  replay({kFuzzDir / "corpus/gltf", kFuzzDir / "regressions/gltf"}, loadGltfInput);
}

TEST(FuzzCorpusReplay, TrackSeedsAndFindingsLoadOrThrowInputError) {
  replay({kFuzzDir / "corpus/track", kFuzzDir / "regressions/track"}, loadPerformanceTrackInput);
}

// The seed shots are copied next to the seed assets, as the shot fuzzer sees them.
TEST(FuzzSeeds, ValidSeedShotsLoadAndBuildEveryFrame) {
  const auto shots = handWrittenSeedsIn(kFuzzDir / "corpus/shot");
  ASSERT_GE(shots.size(), 6u);
  for (const auto& file : shots) {
    SCOPED_TRACE(file.string());
    const std::filesystem::path copy = workDirectory() / file.filename();
    std::filesystem::copy_file(file, copy, std::filesystem::copy_options::overwrite_existing);
    const Shot shot = loadShot(copy);
    FrameBuilder builder(shot);
    for (int frame = shot.frameStart; frame <= shot.frameEnd; ++frame)
      EXPECT_FALSE(builder.build(frame).meshes.empty()) << "frame " << frame;
  }
}

TEST(FuzzSeeds, TinyGlbHasTargetsAnimationAndSkin) {
  const GltfAsset asset = loadGltfAsset(kFuzzDir / "seed_assets/tiny.glb");
  EXPECT_EQ(asset.targetNames, (std::vector<std::string>{"jawOpen", "smile"}));
  EXPECT_EQ(asset.animations.size(), 1u);
  EXPECT_EQ(asset.skins.size(), 1u);
  EXPECT_TRUE(asset.warnings.empty());
}

TEST(FuzzSeeds, SeedTracksLoadTheirChannels) {
  for (const auto& file : handWrittenSeedsIn(kFuzzDir / "corpus/track")) {
    SCOPED_TRACE(file.string());
    PerformanceCsvOptions options;
    options.nameMap["mouthSmile"] = "smile";
    const PerformanceTrack track = readPerformanceTrack(file, {"jawOpen", "smile", "browInnerUp_L"}, options);
    EXPECT_GE(track.names.size(), 2u);
    EXPECT_GE(track.times.size(), 3u);
  }
}

}  // namespace corpus_replay_test
}  // namespace lacrima::fuzz
