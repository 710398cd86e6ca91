#pragma once
// Shot files (JSON, version 1): loading with strict, complete validation, and turning a shot
// into a renderer Frame through the geometry stage.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lacrima/base/error.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

// One problem found in a shot file.
struct Diagnostic {
  std::filesystem::path file;
  std::string jsonPath;  // e.g. "/materials/2/ior"  (JSON pointer) ; "" for whole-file problems
  int line = 0;          // 1-based, 0 when unknown
  int column = 0;        // 1-based, 0 when unknown
  std::string message;   // what was expected, what was found, closest valid name if any

  // "shot.json:12:7: /materials/2/ior: expected a number > 1, found \"abc\""
  std::string format() const;
};

// Thrown by loadShot with every problem found (not only the first).
class ShotError : public InputError {
 public:
  explicit ShotError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

struct Shot;  // full definition in shot_model.hpp (plain data)
struct GltfAsset;

}  // namespace lacrima

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima {

// Reads, parses and validates a shot file. Throws ShotError listing every problem.
Shot loadShot(const std::filesystem::path& path);

// How loadShot reads the glTF file of an asset (it throws for a file it cannot load).
using GltfAssetLoader = std::function<std::shared_ptr<const GltfAsset>(const std::filesystem::path&)>;

// The same, reading the assets through `loadAsset`: a process that loads many shots naming the
// same large assets (the shot fuzzer, tests/fuzz) can share one loaded copy between them.
Shot loadShot(const std::filesystem::path& path, const GltfAssetLoader& loadAsset);

// A recorded or tracked take played on one of the shot's assets instead of the animation the shot
// gives it (`lacrima render --performance`, docs/tracking.md): the asset's keyed blendshapes,
// animator controls, keyed joints and performance track are dropped, and `file` (a performance
// CSV: weights and, on an asset with a rig, joint channels such as head.rx) plays from the shot's
// first frame. Everything else (tears, flesh, eyes, details) follows the face the track poses.
struct PerformanceOverride {
  std::string asset;            // the asset's name in the shot
  std::filesystem::path file;   // absolute, or relative to the working directory
  std::optional<double> fps;    // the track's frame rate; none: the shot's
};

// loadShot with takes played on assets; an unknown asset name is a ShotError at /assets.
Shot loadShot(const std::filesystem::path& path, const std::vector<PerformanceOverride>& performances);

// The shot's render settings for one frame: shot.render with its frameNumber set (the one place
// a frame's number is given to its settings; buildFrame hands these to the renderer).
RenderSettings renderSettingsAt(const Shot& shot, int frameNumber);

// The renderer input for one frame number, built alone: FrameBuilder(shot).build(frameNumber)
// (frame_builder.hpp), so every simulation runs from its start (or a state filed on disk). A
// sequence keeps one FrameBuilder instead. Throws InputError for a frame outside the shot.
Frame buildFrame(const Shot& shot, int frameNumber);

// The face pose of `shot.assets[assetIndex]` at a (fractional) frame: its blendshape weights from
// every source (indexed like its glTF's targetNames, clamped to [0, 1]) and its rig joints, as the
// frame is built with them.
FacePose assetFacePoseAt(const Shot& shot, size_t assetIndex, double frame);

// Replaces a run of '#' (e.g. "####") with the zero-padded frame number.
std::string expandFramePattern(const std::string& pattern, int frameNumber);

}  // namespace lacrima
