#pragma once
// Writing frames: multi-channel EXR (atomic: temporary name, then rename) and a PNG preview
// through OpenColorIO.
#include <filesystem>
#include <map>
#include <string>

#include "lacrima/renderer/film.hpp"

namespace lacrima {

struct ExrMetadata {
  std::string shotFile;
  int frame = 1;
  uint64_t seed = 0;
  int samplesPerPixel = 0;
  double renderSeconds = 0.0;
  Mat4 worldToCamera = Mat4::Identity();
  Mat4 worldToNDC = Mat4::Identity();
  std::map<std::string, std::string> extra;  // further string attributes ("lacrima:..." keys)
};

// Channels: R,G,B,A (half, or float when floatBeauty), albedo.R/G/B, N.X/Y/Z, Z (float), and
// "samples" (float) when the film has sample counts (adaptive sampling), denoised.R/G/B (the
// beauty's format) when it has a denoised beauty; the preview shows the denoised one then; then
// the film's further layers (float: Cryptomatte's), and its attributes in the header.
// Writes to "<path>.tmp-<pid>" then renames over <path>; creates parent directories.
// Throws InputError (names the path) when the file cannot be written.
void writeExr(const std::filesystem::path& path, const Film& film, const ExrMetadata& metadata,
              bool floatBeauty);

// Reads the beauty (RGBA) of an EXR written by writeExr, for tests and tools.
Film readExrBeauty(const std::filesystem::path& path);

// sRGB PNG preview of the beauty through the OCIO config (working space ACEScg, view
// "ACES 1.0 - SDR Video" on display "sRGB - Display"). Atomic like writeExr.
void writePreviewPng(const std::filesystem::path& path, const Film& film,
                     const std::filesystem::path& ocioConfig);

}  // namespace lacrima
