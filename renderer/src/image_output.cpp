// Writing frames: the multi-channel EXR (through OpenImageIO) and the sRGB PNG preview (through
// OpenColorIO). Both are written atomically: to "<path>.tmp-<pid>" next to the final file, then
// renamed over it (rename(2) is atomic within one filesystem), so a reader or a crashed farm job
// never leaves a half-written file under the final name. (Two threads of one process must not
// write the same path at once: they would share the temporary name.)
//
// EXR layout (single part, zip): R,G,B,A (half, or float with floatBeauty), albedo.R/G/B,
// N.X/Y/Z, Z (float), under adaptive sampling "samples" (float: the pixel's camera samples),
// when denoising denoised.R/G/B (the beauty's format), then the film's further layers (float:
// Cryptomatte's <Type>00.R ...), with the film's attributes in the header.
// Metadata: lacrima:version, lacrima:shot, lacrima:frame (int),
// lacrima:seed (string: EXR has no 64-bit integer attribute and OIIO drops one),
// lacrima:spp (int), lacrima:renderSeconds (float), lacrima:colorSpace ("ACEScg") with the
// standard "chromaticities" of ACEScg (AP1, D60 white), and the standard worldToCamera and
// worldToNDC (m44f). EXR/Imath matrices multiply row vectors (p' = p M, translation in the last
// row), i.e. they are the transpose of our column-vector Eigen matrices; the transpose stored row
// by row is Eigen's column-major storage, so the Eigen data is written as is.
//
// PNG preview: OpenColorIO is used directly rather than through OIIO's ociodisplay: the processor
// is built once from an explicit config (no global $OCIO / OIIO colour state), config errors come
// back as OCIO exceptions that we turn into InputError naming the config, and the CPU processor
// (thread-safe) is applied in row chunks in parallel with TBB straight from the film, without
// ImageBuf copies. It shows the denoised beauty when the film has one. The film's RGB is premultiplied by coverage, so dropping alpha shows the frame
// over black; the PNG is 8-bit RGB, no alpha.
#include "lacrima/renderer/image_output.hpp"

#include <fmt/core.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "lacrima/base/error.hpp"

#ifndef LACRIMA_VERSION
#define LACRIMA_VERSION "unknown"
#endif

namespace OCIO = OCIO_NAMESPACE;

namespace lacrima {

namespace {

namespace fs = std::filesystem;

// A sibling temporary file that becomes the final file on commit() and is removed otherwise.
class AtomicFile {
 public:
  AtomicFile(const fs::path& finalPath, const char* what) : final_(finalPath), what_(what) {
    if (finalPath.filename().empty()) {
      throw InputError(fmt::format("cannot write {} '{}': not a file name", what_, final_.string()));
    }
    temporary_ = finalPath;
    temporary_ += fmt::format(".tmp-{}", long(::getpid()));
    const fs::path parent = finalPath.parent_path();
    if (!parent.empty()) {
      std::error_code ec;
      fs::create_directories(parent, ec);
      if (ec) {
        throw InputError(fmt::format("cannot write {} '{}': cannot create directory '{}': {}", what_,
                                     final_.string(), parent.string(), ec.message()));
      }
    }
  }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile() {
    if (!committed_) {
      std::error_code ec;
      fs::remove(temporary_, ec);
    }
  }

  const fs::path& temporary() const { return temporary_; }

  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError(fmt::format("cannot write {} '{}': {}", what_, final_.string(), reason));
  }

  void commit() {
    std::error_code ec;
    fs::rename(temporary_, final_, ec);
    if (ec) fail(fmt::format("cannot rename the temporary file into place: {}", ec.message()));
    committed_ = true;
  }

 private:
  fs::path final_, temporary_;
  const char* what_;
  bool committed_ = false;
};

// Writes one image with OIIO's writer for `format` to the temporary file, then commits it.
void writeAtomically(const fs::path& path, const char* what, const char* format, const OIIO::ImageSpec& spec,
                     OIIO::TypeDesc dataType, const void* data) {
  AtomicFile file(path, what);
  auto out = OIIO::ImageOutput::create(format);
  if (!out) file.fail(fmt::format("no OpenImageIO writer for {}: {}", format, OIIO::geterror()));
  if (!out->open(file.temporary().string(), spec)) file.fail(out->geterror());
  if (!out->write_image(dataType, data)) {
    const std::string error = out->geterror();
    out->close();
    file.fail(error);
  }
  if (!out->close()) file.fail(out->geterror());
  out.reset();
  file.commit();
}

void checkFilm(const Film& film, const char* function) {
  const std::size_t n = std::size_t(std::max(film.width, 0)) * std::size_t(std::max(film.height, 0));
  const auto planeOk = [n](const std::vector<float>& plane, std::size_t channels) {
    return plane.empty() || plane.size() == n * channels;
  };
  if (film.width < 1 || film.height < 1 || film.rgba.size() != n * 4 || !planeOk(film.albedo, 3) ||
      !planeOk(film.normal, 3) || !planeOk(film.depth, 1) || !planeOk(film.sampleCount, 1) ||
      !planeOk(film.denoised, 3) ||
      std::any_of(film.layers.begin(), film.layers.end(),
                  [&](const FilmLayer& l) { return l.channels.empty() || l.data.size() != n * l.channels.size(); })) {
    throw std::invalid_argument(fmt::format("{}: inconsistent {}x{} film (rgba {}, albedo {}, normal {}, depth {})",
                                            function, film.width, film.height, film.rgba.size(),
                                            film.albedo.size(), film.normal.size(), film.depth.size()));
  }
}

constexpr int kExrChannels = 11;  // without the sample count

// A region's film is the EXR's data window inside the whole frame, its display window (OpenEXR's
// own crop window: compositors place it in the frame).
void setWindows(OIIO::ImageSpec& spec, const Film& film) {
  spec.x = film.originX;
  spec.y = film.originY;
  spec.full_x = 0;
  spec.full_y = 0;
  spec.full_width = std::max(film.frameWidth, film.originX + film.width);
  spec.full_height = std::max(film.frameHeight, film.originY + film.height);
}

}  // namespace

void writeExr(const fs::path& path, const Film& film, const ExrMetadata& metadata, bool floatBeauty) {
  checkFilm(film, "writeExr");
  const int w = film.width, h = film.height;
  const std::size_t n = std::size_t(w) * h;

  const bool withSamples = !film.sampleCount.empty(), withDenoised = !film.denoised.empty();
  const int samplesChannel = kExrChannels, denoisedChannel = kExrChannels + (withSamples ? 1 : 0);
  const int layersChannel = denoisedChannel + (withDenoised ? 3 : 0);
  int channels = layersChannel;
  for (const FilmLayer& layer : film.layers) channels += int(layer.channels.size());
  OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z"};
  if (withSamples) spec.channelnames.push_back("samples");
  if (withDenoised) spec.channelnames.insert(spec.channelnames.end(), {"denoised.R", "denoised.G", "denoised.B"});
  for (const FilmLayer& layer : film.layers)
    spec.channelnames.insert(spec.channelnames.end(), layer.channels.begin(), layer.channels.end());
  const OIIO::TypeDesc beauty = floatBeauty ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::HALF;
  spec.channelformats.assign(channels, OIIO::TypeDesc::FLOAT);
  if (withDenoised) std::fill_n(spec.channelformats.begin() + denoisedChannel, 3, beauty);
  std::fill_n(spec.channelformats.begin(), 4, beauty);
  spec.alpha_channel = 3;
  spec.z_channel = 10;
  setWindows(spec, film);
  spec.attribute("compression", "zip");

  // Attributes we own; `extra` may not override them.
  static const std::set<std::string> reserved = {
      "lacrima:version", "lacrima:shot", "lacrima:frame", "lacrima:seed", "lacrima:spp", "lacrima:renderSeconds",
      "lacrima:colorSpace", "worldToCamera", "worldToNDC", "chromaticities", "compression"};
  for (const auto* attributes : {&metadata.extra, &film.attributes})
    for (const auto& [key, value] : *attributes) {
      if (reserved.count(key) != 0) {
        throw std::invalid_argument(fmt::format("writeExr: extra attribute '{}' would replace a standard one", key));
      }
      spec.attribute(key, value);
    }
  spec.attribute("lacrima:version", LACRIMA_VERSION);
  spec.attribute("Software", "lacrima " LACRIMA_VERSION);
  spec.attribute("lacrima:shot", metadata.shotFile);
  spec.attribute("lacrima:frame", metadata.frame);
  spec.attribute("lacrima:seed", fmt::format("{}", metadata.seed));
  spec.attribute("lacrima:spp", metadata.samplesPerPixel);
  spec.attribute("lacrima:renderSeconds", float(metadata.renderSeconds));
  spec.attribute("lacrima:colorSpace", "ACEScg");
  // ACEScg = ACES AP1 primaries, ACES white (about D60): R, G, B, white as CIE xy.
  static const float ap1[8] = {0.713f, 0.293f, 0.165f, 0.830f, 0.128f, 0.044f, 0.32168f, 0.33767f};
  spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), ap1);
  spec.attribute("worldToCamera", OIIO::TypeMatrix44, metadata.worldToCamera.data());
  spec.attribute("worldToNDC", OIIO::TypeMatrix44, metadata.worldToNDC.data());

  // Interleave the planes; OIIO converts each channel to its own format while writing.
  std::vector<float> pixels(n * channels);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t p = r.begin(); p != r.end(); ++p) {
      float* out = &pixels[p * channels];
      std::copy_n(&film.rgba[p * 4], 4, out);
      if (!film.albedo.empty()) std::copy_n(&film.albedo[p * 3], 3, out + 4); else std::fill_n(out + 4, 3, 0.0f);
      if (!film.normal.empty()) std::copy_n(&film.normal[p * 3], 3, out + 7); else std::fill_n(out + 7, 3, 0.0f);
      out[10] = film.depth.empty() ? 0.0f : film.depth[p];
      if (withSamples) out[samplesChannel] = film.sampleCount[p];
      if (withDenoised) std::copy_n(&film.denoised[p * 3], 3, out + denoisedChannel);
      float* layerOut = out + layersChannel;
      for (const FilmLayer& layer : film.layers) {
        const size_t count = layer.channels.size();
        std::copy_n(&layer.data[p * count], count, layerOut);
        layerOut += count;
      }
    }
  });
  writeAtomically(path, "EXR", "openexr", spec, OIIO::TypeDesc::FLOAT, pixels.data());
}

Film readExrBeauty(const fs::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw InputError(fmt::format("EXR '{}': file not found (or not a regular file)", name));
  }
  auto in = OIIO::ImageInput::open(name);
  if (!in) throw InputError(fmt::format("EXR '{}': cannot read the image: {}", name, OIIO::geterror()));
  const OIIO::ImageSpec spec = in->spec();
  const auto find = [&](const char* channel) {
    const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), channel);
    return it == spec.channelnames.end() ? -1 : int(it - spec.channelnames.begin());
  };
  const int src[4] = {find("R"), find("G"), find("B"), find("A")};
  if (spec.deep || spec.width < 1 || spec.height < 1 || src[0] < 0 || src[1] < 0 || src[2] < 0) {
    throw InputError(fmt::format("EXR '{}': no R, G, B channels in a flat image", name));
  }
  const int nch = spec.nchannels;
  std::vector<float> all(std::size_t(spec.width) * spec.height * nch);
  if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, all.data())) {
    throw InputError(fmt::format("EXR '{}': cannot read the pixels: {}", name, in->geterror()));
  }
  in->close();

  // Only the beauty: the AOV planes stay empty.
  Film film;
  film.width = spec.width;
  film.height = spec.height;
  film.originX = spec.x - spec.full_x;
  film.originY = spec.y - spec.full_y;
  film.frameWidth = spec.full_width;
  film.frameHeight = spec.full_height;
  film.rgba.resize(std::size_t(spec.width) * spec.height * 4);
  for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p) {
    for (int c = 0; c < 4; ++c) film.rgba[p * 4 + c] = src[c] >= 0 ? all[p * nch + src[c]] : 1.0f;
  }
  return film;
}

void writePreviewPng(const fs::path& path, const Film& film, const fs::path& ocioConfig) {
  checkFilm(film, "writePreviewPng");
  static constexpr const char* kWorkingSpace = "ACEScg";
  static constexpr const char* kDisplay = "sRGB - Display";
  static constexpr const char* kView = "ACES 1.0 - SDR Video";

  const std::string configName = ocioConfig.string();
  std::error_code ec;
  if (!fs::is_regular_file(ocioConfig, ec)) {
    throw InputError(fmt::format("OCIO config '{}': file not found (or not a regular file)", configName));
  }
  OCIO::ConstCPUProcessorRcPtr cpu;
  try {
    OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromFile(configName.c_str());
    config->validate();
    cpu = config->getProcessor(kWorkingSpace, kDisplay, kView, OCIO::TRANSFORM_DIR_FORWARD)->getDefaultCPUProcessor();
  } catch (const OCIO::Exception& e) {
    throw InputError(fmt::format("OCIO config '{}': cannot convert {} to display '{}', view '{}': {}", configName,
                                 kWorkingSpace, kDisplay, kView, e.what()));
  }

  const int w = film.width, h = film.height;
  std::vector<std::uint8_t> rgb8(std::size_t(w) * h * 3);
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& rows) {
    const std::size_t first = std::size_t(rows.begin()) * w, count = std::size_t(rows.size()) * w;
    std::vector<float> chunk(film.rgba.begin() + std::ptrdiff_t(first * 4),
                             film.rgba.begin() + std::ptrdiff_t((first + count) * 4));
    if (!film.denoised.empty())  // the preview shows the denoised beauty where there is one
      for (std::size_t p = 0; p < count; ++p) std::copy_n(&film.denoised[(first + p) * 3], 3, &chunk[p * 4]);
    for (float& x : chunk) {  // NaN would survive the transform; infinities become the largest half
      if (std::isnan(x)) x = 0.0f;
      else if (std::isinf(x)) x = x > 0.0f ? 65504.0f : 0.0f;
    }
    OCIO::PackedImageDesc desc(chunk.data(), long(w), long(rows.size()), 4);
    cpu->apply(desc);
    for (std::size_t p = 0; p < count; ++p) {
      for (int c = 0; c < 3; ++c) {
        const float v = chunk[p * 4 + c];
        rgb8[(first + p) * 3 + c] = std::uint8_t(std::lround(std::clamp(std::isnan(v) ? 0.0f : v, 0.0f, 1.0f) * 255.0f));
      }
    }
  });

  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  spec.attribute("Software", "lacrima " LACRIMA_VERSION);
  writeAtomically(path, "PNG preview", "png", spec, OIIO::TypeDesc::UINT8, rgb8.data());
}

}  // namespace lacrima
