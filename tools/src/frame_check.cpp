#include "frame_check.hpp"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <system_error>
#include <vector>

namespace lacrima::cli {

namespace {

std::string checkChannels(const OIIO::ImageSpec& spec, const RenderSettings& s) {
  // The further layers this run writes (their first channel; light groups: the environment's).
  std::vector<std::string> layers;
  if (s.cryptomatte.objects) layers.push_back("CryptoObject00.R");
  if (s.cryptomatte.materials) layers.push_back("CryptoMaterial00.R");
  if (s.lightGroups) layers.push_back("lightgroup_environment.R");
  for (const LightPath pass : allLightPaths())
    if (s.lightPaths.has(pass)) layers.push_back(lightPathName(pass) + ".R");
  for (const std::string& name : layers)
    if (std::find(spec.channelnames.begin(), spec.channelnames.end(), name) == spec.channelnames.end())
      return fmt::format("it has no '{}' channel, which this run writes", name);
  const OIIO::TypeDesc beauty = s.floatOutput ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF;
  for (const char* name : {"R", "G", "B", "A"}) {
    const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
    if (it == spec.channelnames.end()) return fmt::format("it has no '{}' channel", name);
    const OIIO::TypeDesc format = spec.channelformat(int(it - spec.channelnames.begin()));
    if (format != beauty)
      return fmt::format("its beauty is {}, this run writes {}", format.c_str(), beauty.c_str());
  }
  return "";
}

std::string checkMetadata(const OIIO::ImageSpec& spec, const RenderSettings& s) {
  const int frame = spec.get_int_attribute("lacrima:frame", INT_MIN);
  if (frame != s.frameNumber) return fmt::format("its lacrima:frame is {}, not {}", frame, s.frameNumber);
  const int spp = spec.get_int_attribute("lacrima:spp", INT_MIN);
  if (spp != s.samplesPerPixel) return fmt::format("its lacrima:spp is {}, not {}", spp, s.samplesPerPixel);
  const std::string seed = spec.get_string_attribute("lacrima:seed", "(none)");
  if (seed != std::to_string(s.seed)) return fmt::format("its lacrima:seed is {}, not {}", seed, s.seed);
  // Older frames may lack some; each one present must match too (it changes the pixels).
  for (const auto& [name, value] : pixelSettingsMetadata(s)) {
    const std::string onDisk = spec.get_string_attribute(name, "");
    if (!onDisk.empty() && onDisk != value) return fmt::format("its {} is {}, not {}", name, onDisk, value);
  }
  return "";
}

// The data window inside the frame: the region rendered (the whole frame without one).
std::string checkRegion(const OIIO::ImageSpec& spec, const RenderSettings& s) {
  const PixelRegion r = s.region.empty() ? PixelRegion{0, 0, s.width, s.height} : s.region;
  const int x = spec.x - spec.full_x, y = spec.y - spec.full_y;
  if (x == r.x && y == r.y && spec.width == r.width && spec.height == r.height) return "";
  return fmt::format("it holds the region {}x{} at ({}, {}), this run renders {}x{} at ({}, {})", spec.width,
                     spec.height, x, y, r.width, r.height, r.x, r.y);
}

}  // namespace

std::map<std::string, std::string> pixelSettingsMetadata(const RenderSettings& s) {
  const BounceLimits& b = s.bounces;
  return {
      {"lacrima:maxDepth", std::to_string(s.maxDepth)},
      {"lacrima:sampler", s.sampler == SamplerKind::Sobol ? "sobol" : "independent"},
      {"lacrima:filter", fmt::format("{} {} px", filterTypeName(s.filter.type), s.filter.width)},
      {"lacrima:bounces", fmt::format("diffuse {} glossy {} transmission {}", b.diffuse, b.glossy, b.transmission)},
      {"lacrima:caustics", causticsName(s.caustics)},
      {"lacrima:denoise", s.denoise ? "on" : "off"},
      {"lacrima:adaptive", s.adaptive.enabled ? fmt::format("threshold {} min {} spp", s.adaptive.threshold,
                                                             s.adaptive.minSamples)
                                              : "off"},
  };
}

std::string whyFrameMustBeRendered(const std::filesystem::path& exr, const RenderSettings& expected) {
  std::error_code ec;
  if (!std::filesystem::exists(exr, ec)) return "not rendered yet";
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) return fmt::format("it cannot be opened as an image: {}", OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.deep || spec.full_width != expected.width || spec.full_height != expected.height)
    return fmt::format("it is {}x{}, this run renders {}x{}", spec.full_width, spec.full_height, expected.width,
                       expected.height);
  if (std::string why = checkRegion(spec, expected); !why.empty()) return why;
  if (std::string why = checkChannels(spec, expected); !why.empty()) return why;
  if (std::string why = checkMetadata(spec, expected); !why.empty()) return why;
  // A truncated or damaged file often has an intact header: only reading every pixel tells.
  std::vector<float> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    return fmt::format("its pixels cannot be read (truncated or corrupt?): {}", in->geterror());
  return "";
}

}  // namespace lacrima::cli
