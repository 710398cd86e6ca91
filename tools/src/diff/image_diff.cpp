// Image comparison for `lacrima diff` and `lacrima test-suite`; see image_diff.hpp.
#include "diff/image_diff.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "diff/flip.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima::diff {

namespace {

bool isBeautyChannel(const std::string& name) { return name == "R" || name == "G" || name == "B" || name == "A"; }

// |a - b|, with equal infinities and two NaNs counting as equal and a NaN against a number as an
// infinite difference, so that broken pixels always fail.
double channelDifference(float a, float b) {
  if (a == b || (std::isnan(a) && std::isnan(b))) return 0.0;
  const double d = std::abs(double(a) - double(b));
  return std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::vector<ChannelGroup> selectedGroups(const Image& a, const Image& b, const CompareOptions& options) {
  const std::vector<ChannelGroup> all = channelGroups(a.channels);
  std::vector<ChannelGroup> selected;
  if (options.groups.empty()) {
    selected = all;
    for (const std::string& c : b.channels)
      if (a.channelIndex(c) < 0) throw InputError(fmt::format("{}: no channel '{}' ({} has it)", a.path, c, b.path));
  } else {
    std::vector<std::string> names;
    for (const ChannelGroup& g : all) names.push_back(g.name);
    for (const std::string& wanted : options.groups) {
      const auto it = std::find_if(all.begin(), all.end(), [&](const ChannelGroup& g) { return g.name == wanted; });
      if (it == all.end())
        throw InputError(fmt::format("{}: no channel group '{}' (it has {})", a.path, wanted, joined(names)));
      selected.push_back(*it);
    }
  }
  for (const ChannelGroup& g : selected)
    for (const std::string& c : g.channels)
      if (b.channelIndex(c) < 0) throw InputError(fmt::format("{}: no channel '{}' ({} has it)", b.path, c, a.path));
  return selected;
}

std::string percentText(double p) { return fmt::format("{:.3g}%", p); }

void judge(GroupMetrics& m, const Thresholds& t) {
  if (m.failPercent > t.failPercent) {
    m.verdict = Verdict::Fail;
    m.reasons.push_back(fmt::format("{}: {} pixels ({}) differ by more than {} (allowed {})", m.name, m.failPixels,
                                    percentText(m.failPercent), t.fail, percentText(t.failPercent)));
  }
  if (t.maxMeanError && !(m.meanError <= *t.maxMeanError)) {
    m.verdict = Verdict::Fail;
    m.reasons.push_back(fmt::format("{}: mean error {:.6g} exceeds {}", m.name, m.meanError, *t.maxMeanError));
  }
  if (m.verdict == Verdict::Pass && m.warnPercent > t.warnPercent) {
    m.verdict = Verdict::Warn;
    m.reasons.push_back(fmt::format("{}: {} pixels ({}) differ by more than the warning threshold {} (allowed {})",
                                    m.name, m.warnPixels, percentText(m.warnPercent), t.warn,
                                    percentText(t.warnPercent)));
  }
}

GroupMetrics measureGroup(const Image& a, const Image& b, const ChannelGroup& group, const Thresholds& t) {
  GroupMetrics m;
  m.name = group.name;
  m.channels = group.channels;
  std::vector<int> ia, ib;
  for (const std::string& c : group.channels) {
    ia.push_back(a.channelIndex(c));
    ib.push_back(b.channelIndex(c));
  }
  double sum = 0, sumSquares = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double pixelMax = 0;
      for (size_t c = 0; c < ia.size(); ++c) {
        const double d = channelDifference(a.at(x, y, ia[c]), b.at(x, y, ib[c]));
        sum += d;
        sumSquares += d * d;
        pixelMax = std::max(pixelMax, d);
        if (d > m.maxError) {
          m.maxError = d;
          m.maxX = x;
          m.maxY = y;
          m.maxChannel = group.channels[c];
        }
      }
      if (pixelMax > t.fail) ++m.failPixels;
      if (pixelMax > t.warn) ++m.warnPixels;
    }
  const double pixels = double(a.width) * double(a.height);
  const double values = pixels * double(ia.size());
  m.meanError = values > 0 ? sum / values : 0.0;
  const double mse = values > 0 ? sumSquares / values : 0.0;
  m.rmsError = std::sqrt(mse);
  // PSNR with a peak of 1.0: display white for scene-linear HDR data, full scale for 8-bit data.
  m.psnr = mse > 0 ? 10.0 * std::log10(1.0 / mse) : std::numeric_limits<double>::infinity();
  m.failPercent = pixels > 0 ? 100.0 * double(m.failPixels) / pixels : 0.0;
  m.warnPercent = pixels > 0 ? 100.0 * double(m.warnPixels) / pixels : 0.0;
  judge(m, t);
  return m;
}

// ACEScg (AP1 primaries, D60) to linear Rec. 709 (D65) with the Bradford adaptation, as in the
// ACES/OCIO "ACEScg to lin_srgb" conversion: FLIP expects Rec. 709 primaries.
Color acesCgToRec709(const Color& c) {
  return {1.70505 * c[0] - 0.62179 * c[1] - 0.08326 * c[2], -0.13026 * c[0] + 1.14080 * c[1] - 0.01055 * c[2],
          -0.02400 * c[0] - 0.12897 * c[1] + 1.15297 * c[2]};
}

RgbImage beautyRgb(const Image& image) {
  const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  RgbImage out(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      Color c = {image.at(x, y, r), image.at(x, y, g), image.at(x, y, b)};
      if (image.colorSpace == "ACEScg") c = acesCgToRec709(c);
      out.at(x, y) = c;
    }
  return out;
}

FlipResult measureFlip(const Image& reference, const Image& test, double ppd) {
  FlipResult f;
  f.ppd = ppd > 0 ? ppd : defaultPixelsPerDegree();
  f.highDynamicRange = reference.highDynamicRange || test.highDynamicRange;
  const RgbImage a = beautyRgb(reference), b = beautyRgb(test);
  if (f.highDynamicRange) {
    const ExposureRange range = hdrExposureRange(a);
    f.startExposure = range.start;
    f.stopExposure = range.stop;
    f.exposures = range.count;
    f.errorMap = hdrFlip(a, b, f.ppd, range);
  } else {
    f.errorMap = ldrFlip(a, b, f.ppd);
  }
  double sum = 0;
  for (size_t i = 0; i < f.errorMap.size(); ++i) {
    sum += f.errorMap[i];
    if (f.errorMap[i] > f.max) {
      f.max = f.errorMap[i];
      f.maxX = int(i % size_t(reference.width));
      f.maxY = int(i / size_t(reference.width));
    }
  }
  f.mean = f.errorMap.empty() ? 0.0 : sum / double(f.errorMap.size());
  return f;
}

bool hasRgb(const Image& image) {
  return image.channelIndex("R") >= 0 && image.channelIndex("G") >= 0 && image.channelIndex("B") >= 0;
}

// OIIO picks the format from the extension, so the temporary name keeps it: "x.tmp-<pid>.exr".
void writeAtomically(const std::string& path, const OIIO::ImageBuf& buffer, OIIO::TypeDesc type, const char* what) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
  fs::path temporary = target;
  temporary.replace_extension(fmt::format(".tmp-{}{}", getpid(), target.extension().string()));
  if (!buffer.write(temporary.string(), type)) {
    fs::remove(temporary, ec);
    throw InputError(fmt::format("cannot write {} '{}': {}", what, path, buffer.geterror()));
  }
  fs::rename(temporary, target, ec);
  if (ec) {
    fs::remove(temporary, ec);
    throw InputError(fmt::format("cannot write {} '{}': {}", what, path, ec.message()));
  }
}

}  // namespace

int Image::channelIndex(const std::string& name) const {
  const auto it = std::find(channels.begin(), channels.end(), name);
  return it == channels.end() ? -1 : int(it - channels.begin());
}

Image readImage(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(fmt::format("{}: no such file", path));
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw InputError(fmt::format("{}: cannot read image: {}", path, OIIO::geterror()));
  const OIIO::ImageSpec spec = input->spec();
  Image image;
  image.path = path;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.channelnames;
  const OIIO::TypeDesc format = spec.format;
  image.highDynamicRange = format == OIIO::TypeDesc::HALF || format == OIIO::TypeDesc::FLOAT ||
                           format == OIIO::TypeDesc::DOUBLE || spec.channelformats.size() > 0;
  image.colorSpace = spec.get_string_attribute("lacrima:colorSpace");
  image.values.resize(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.values.data())) {
    const std::string why = input->geterror();
    throw InputError(fmt::format("{}: cannot read image: {}", path, why.empty() ? "read failed" : why));
  }
  return image;
}

std::vector<ChannelGroup> channelGroups(const std::vector<std::string>& channelNames) {
  std::vector<ChannelGroup> groups;
  auto add = [&groups](const std::string& group, const std::string& channel) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const ChannelGroup& g) { return g.name == group; });
    if (it == groups.end()) it = groups.insert(groups.end(), ChannelGroup{group, {}});
    it->channels.push_back(channel);
  };
  for (const std::string& c : channelNames) {
    const size_t dot = c.rfind('.');
    if (dot != std::string::npos) add(c.substr(0, dot), c);
    else add(isBeautyChannel(c) ? "beauty" : c, c);
  }
  return groups;
}

const char* verdictName(Verdict v) { return v == Verdict::Pass ? "PASS" : v == Verdict::Warn ? "WARN" : "FAIL"; }

Verdict worst(Verdict a, Verdict b) { return int(a) >= int(b) ? a : b; }

Comparison compareImages(const Image& a, const Image& b, const CompareOptions& options) {
  if (a.width != b.width || a.height != b.height)
    throw InputError(
        fmt::format("{}: {} x {} pixels, but {} has {} x {}", b.path, b.width, b.height, a.path, a.width, a.height));
  Comparison result;
  result.pathA = a.path;
  result.pathB = b.path;
  result.width = a.width;
  result.height = a.height;
  bool beautyCompared = false;
  for (const ChannelGroup& g : selectedGroups(a, b, options)) {
    result.groups.push_back(measureGroup(a, b, g, options.thresholds));
    result.verdict = worst(result.verdict, result.groups.back().verdict);
    beautyCompared = beautyCompared || g.name == "beauty";
  }
  if (options.flip && beautyCompared && hasRgb(a) && hasRgb(b)) result.flip = measureFlip(a, b, options.ppd);
  return result;
}

void writeDifferenceImage(const std::string& path, const Image& a, const Image& b, const Comparison& comparison) {
  std::vector<std::string> names;
  for (const GroupMetrics& g : comparison.groups) names.insert(names.end(), g.channels.begin(), g.channels.end());
  OIIO::ImageSpec spec(a.width, a.height, int(names.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  spec.alpha_channel = -1;
  spec.z_channel = -1;
  spec.attribute("compression", "zip");
  OIIO::ImageBuf buffer(spec);
  std::vector<float> pixel(names.size());
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      for (size_t c = 0; c < names.size(); ++c)
        pixel[c] = float(channelDifference(a.at(x, y, a.channelIndex(names[c])), b.at(x, y, b.channelIndex(names[c]))));
      buffer.setpixel(x, y, pixel.data(), int(pixel.size()));
    }
  writeAtomically(path, buffer, OIIO::TypeDesc::FLOAT, "difference image");
}

void writeFlipImage(const std::string& path, const FlipResult& flip, int width, int height) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf buffer(spec);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Color c = magma(flip.errorMap[size_t(y) * size_t(width) + size_t(x)]);
      const float rgb[3] = {float(c[0]), float(c[1]), float(c[2])};
      buffer.setpixel(x, y, rgb, 3);
    }
  writeAtomically(path, buffer, OIIO::TypeDesc::UINT8, "FLIP image");
}

}  // namespace lacrima::diff
