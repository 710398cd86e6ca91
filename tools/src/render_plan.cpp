#include "render_plan.hpp"

#include <fmt/format.h>

#include "frame_check.hpp"
#include "frame_selection.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/renderer/image_output.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::cli {

namespace {

// --region X,Y,W,H (four integers >= 0, the command line's checks) as a region of the frame.
PixelRegion regionWithinFrame(const std::vector<int>& xywh, int frameWidth, int frameHeight) {
  const PixelRegion r{xywh.at(0), xywh.at(1), xywh.at(2), xywh.at(3)};
  if (r.empty())
    throw InputError(fmt::format("--region {},{},{},{}: the region's width and height must be at least 1", r.x, r.y,
                                 r.width, r.height));
  if (r.x + r.width > frameWidth || r.y + r.height > frameHeight)
    throw InputError(fmt::format("--region {},{},{},{}: the region does not lie within the {}x{} frame (it ends at "
                                 "pixel ({}, {}))",
                                 r.x, r.y, r.width, r.height, frameWidth, frameHeight, r.x + r.width - 1,
                                 r.y + r.height - 1));
  return r;
}

}  // namespace

void applyOverrides(const RenderOptions& o, RenderSettings& s) {
  if (o.spp) s.samplesPerPixel = *o.spp;
  if (o.width) s.width = *o.width;
  if (o.height) s.height = *o.height;
  if (o.threads) s.threads = *o.threads;
  if (o.maxDepth) s.maxDepth = *o.maxDepth;
  if (o.seed) s.seed = *o.seed;
  if (o.floatOutput) s.floatOutput = true;
  if (o.denoise) s.denoise = *o.denoise;
  for (const std::string& aov : o.aovs) enableAov(s, aov);  // names checked by the command line
  if (!o.region.empty()) s.region = regionWithinFrame(o.region, s.width, s.height);
}

std::string resolveOutputPattern(const RenderOptions& o, const Shot& shot, size_t frameCount) {
  const std::string pattern = o.outputPattern.empty() ? shot.outputPattern : o.outputPattern;
  requireFrameField(pattern, frameCount, "rendered");
  // Frames are always OpenEXR; another extension would mislead, and with --preview a '.png'
  // output would be overwritten by its own preview.
  if (lowerExtension(expandFramePattern(pattern, 1)) != ".exr")
    throw InputError(fmt::format("output '{}': frames are OpenEXR files, the name must end in .exr", pattern));
  return pattern;
}

std::filesystem::path previewPathFor(const std::filesystem::path& exrPath) {
  std::filesystem::path pngPath = exrPath;
  pngPath.replace_extension(".png");
  return pngPath;
}

std::string whyFrameIsNotComplete(const RenderOptions& o, const Shot& shot, const std::string& pattern,
                                  int frameNumber) {
  const std::filesystem::path exrPath = expandFramePattern(pattern, frameNumber);
  std::error_code ec;
  if (!std::filesystem::exists(exrPath, ec)) return "missing";
  std::string why = whyFrameMustBeRendered(exrPath, renderSettingsAt(shot, frameNumber));
  if (why.empty() && o.preview && !std::filesystem::exists(previewPathFor(exrPath), ec))
    why = "its --preview PNG is missing";
  return why;
}

}  // namespace lacrima::cli
