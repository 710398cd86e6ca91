#include "fuzz_inputs.hpp"

#include "fuzz_support.hpp"
#include "lacrima/geometry/gltf_asset.hpp"
#include "lacrima/geometry/performance_track.hpp"
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

}  // namespace

void loadShotInput(const uint8_t* data, size_t size) {
  const std::filesystem::path path = writeInput(data, size, "shot.json");
  try {
    const Shot shot = loadShot(path);
    (void)buildFrame(shot, shot.frameStart);
    (void)buildFrame(shot, shot.frameEnd);
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
