#include "fuzz_inputs.hpp"

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "fuzz_support.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/io/performance_track.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::fuzz {

namespace {

// What a shot does with a loaded asset, on every primitive, animation and skin.
void exerciseAsset(const GltfAsset& asset) {
  (void)describeGltfAsset(asset);
  const std::vector<float> allOn(asset.targetNames.size(), 1.0f);
  for (const GltfPrimitive& primitive : asset.primitives) (void)applyMorphTargets(primitive, allOn);
  for (const GltfAnimation& animation : asset.animations)
    for (double seconds : {0.0, 0.4, 1e3}) {
      const GltfAnimationSample sample = sampleGltfAnimation(asset, animation, seconds);
      for (const GltfPrimitive& primitive : asset.primitives) {
        if (primitive.skin < 0 || sample.skinJointMatrices[size_t(primitive.skin)].empty()) continue;
        TriangleMesh mesh = applyMorphTargets(primitive, {});
        applyGltfSkin(asset, primitive, sample.skinJointMatrices[size_t(primitive.skin)], mesh);
      }
    }
}

// A file's identity for the asset cache: where it is, how big, when last written.
struct FileStamp {
  std::string path;
  std::uintmax_t size = 0;
  std::filesystem::file_time_type modified;
  bool operator==(const FileStamp&) const = default;
};

// The shot seeds name the same glTF files in nearly every input (tiny.glb next to them; the ICT
// face, 10.7 MB, in the face regression shots), and loading the face took ~4 s of a face shot's
// ~5 s under ASan: the shot fuzzer ran ~10 inputs/s. Each file is loaded once per process and
// shared while it is unchanged (same size and modification time, so a file rewritten per input
// is loaded again); a load that throws is not kept, so it throws again each time. What is left
// per input is the shot's own work: parsing, validation, the load-time resolution of tears, eyes
// and details, buildFrame. The glTF loader itself is fuzzed by gltf_fuzzer.
std::shared_ptr<const GltfAsset> loadGltfAssetOnce(const std::filesystem::path& path) {
  std::error_code canonicalError, sizeError, timeError;
  FileStamp stamp{std::filesystem::weakly_canonical(path, canonicalError).string(),
                  std::filesystem::file_size(path, sizeError), std::filesystem::last_write_time(path, timeError)};
  if (canonicalError || sizeError || timeError)  // let the loader report it
    return std::make_shared<const GltfAsset>(loadGltfAsset(path));
  static std::vector<std::pair<FileStamp, std::shared_ptr<const GltfAsset>>> cache;
  for (const auto& [cached, asset] : cache)
    if (cached == stamp) return asset;
  auto asset = std::make_shared<const GltfAsset>(loadGltfAsset(path));
  // A bound on what fuzzed shots naming other files on disk can pin in memory.
  if (cache.size() >= 8) cache.clear();
  cache.emplace_back(std::move(stamp), asset);
  return asset;
}

}  // namespace

void loadShotInput(const uint8_t* data, size_t size) {
  const std::filesystem::path path = writeInput(data, size, "shot.json");
  try {
    Shot shot = loadShot(path, loadGltfAssetOnce);
    // SPH liquids are loaded and checked but not simulated: the regression drop (4,200 particles
    // over three frames, 3 s in Release) took 15 minutes under ASan with the fuzzer's coverage,
    // against a 10 s limit per input. The solver and its shot code run under the sanitizers in
    // lacrima_sph_tests and the SphShot tests of lacrima_scenes_tests; the bound on a liquid's particle
    // count is checked at load, which runs here.
    shot.sph.clear();
    FrameBuilder builder(shot);
    (void)builder.build(shot.frameStart);
    // A frame reads nothing but the shot and the frame number: the same frame again adds nothing.
    if (shot.frameEnd != shot.frameStart) (void)builder.build(shot.frameEnd);
  } catch (const InputError&) {
    // A clear message for bad input is the expected outcome.
  }
}

void loadGltfInput(const uint8_t* data, size_t size) {
  const std::filesystem::path path = writeInput(data, size, looksLikeJson(data, size) ? "asset.gltf" : "asset.glb");
  try {
    exerciseAsset(loadGltfAsset(path));
  } catch (const InputError&) {
  }
}

void loadPerformanceTrackInput(const uint8_t* data, size_t size) {
  const bool json = looksLikeJson(data, size);
  const std::filesystem::path path = writeInput(data, size, json ? "input.json" : "input.csv");
  PerformanceCsvOptions options;
  options.nameMap["mouthSmile"] = "smile";
  try {
    const PerformanceTrack track = readPerformanceTrack(path, {"jawOpen", "smile", "browInnerUp_L"}, options);
    (void)adaptiveTemporalFilter(resampleTrack(track, 24.0f).frames);
  } catch (const InputError&) {
  }
}

}  // namespace lacrima::fuzz
