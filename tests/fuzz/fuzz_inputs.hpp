#pragma once
// The three fuzzed input paths, shared by the libFuzzer targets (tests/fuzz/targets) and the
// gtest that replays the seed corpora and the saved findings (corpus_replay_test.cpp).
// Contract: each returns normally for any input (it loaded, or lacrima::InputError said why);
// any other exception, crash, hang or leak is a finding.
#include <cstddef>
#include <cstdint>

namespace lacrima::fuzz {

// loadShot, then buildFrame for the first and the last frame.
void loadShotInput(const uint8_t* data, size_t size);

// loadGltfAsset (.gltf when the input starts with '{', else .glb), then describe the asset,
// morph every primitive, sample every animation and pose the skins.
void loadGltfInput(const uint8_t* data, size_t size);

// readPerformanceTrack (JSON when the input starts with '{', else CSV), resampled to 24 fps and
// filtered (Weise et al. 2011).
void loadPerformanceTrackInput(const uint8_t* data, size_t size);

}  // namespace lacrima::fuzz
