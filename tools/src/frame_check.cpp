#include "frame_check.hpp"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <climits>
#include <system_error>
#include <vector>

namespace lacrima::cli {

namespace {

std::string checkChannels(const OIIO::ImageSpec& spec, bool floatBeauty) {
  const OIIO::TypeDesc beauty = floatBeauty ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF;
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
  // Older frames may lack it; when present it must match too (it changes the pixels).
  const std::string maxDepth = spec.get_string_attribute("lacrima:maxDepth", "");
  if (!maxDepth.empty() && maxDepth != std::to_string(s.maxDepth))
    return fmt::format("its lacrima:maxDepth is {}, not {}", maxDepth, s.maxDepth);
  return "";
}

}  // namespace

std::string whyFrameMustBeRendered(const std::filesystem::path& exr, const RenderSettings& expected) {
  std::error_code ec;
  if (!std::filesystem::exists(exr, ec)) return "not rendered yet";
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) return fmt::format("it cannot be opened as an image: {}", OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.deep || spec.width != expected.width || spec.height != expected.height)
    return fmt::format("it is {}x{}, this run renders {}x{}", spec.width, spec.height, expected.width,
                       expected.height);
  if (std::string why = checkChannels(spec, expected.floatOutput); !why.empty()) return why;
  if (std::string why = checkMetadata(spec, expected); !why.empty()) return why;
  // A truncated or damaged file often has an intact header: only reading every pixel tells.
  std::vector<float> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    return fmt::format("its pixels cannot be read (truncated or corrupt?): {}", in->geterror());
  return "";
}

}  // namespace lacrima::cli
