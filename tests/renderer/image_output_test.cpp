// EXR and PNG output: channels, formats, metadata, round trips, atomic writes and errors.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lacrima/base/error.hpp"
#include "lacrima/renderer/image_output.hpp"

namespace lacrima {
namespace image_output_test {

namespace fs = std::filesystem;

const fs::path kOcioConfig = fs::path(LACRIMA_SOURCE_DIR) / "scenes/ocio/config.ocio";

// A fresh, empty directory per test under the test output directory.
fs::path freshDirectory(const std::string& name) {
  const fs::path dir = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "image_output" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> directoryListing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

Film testFilm(int w, int h) {
  Film film(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t p = film.pixelIndex(x, y);
      film.rgba[p * 4 + 0] = 0.01f * float(x) + 0.5f;
      film.rgba[p * 4 + 1] = 3.0f * float(y) / float(h);  // beyond 1: an HDR value
      film.rgba[p * 4 + 2] = std::sin(float(x + y)) * 0.25f + 0.25f;
      film.rgba[p * 4 + 3] = (x + y) % 3 == 0 ? 0.0f : 1.0f;
      for (int c = 0; c < 3; ++c) {
        film.albedo[p * 3 + c] = 0.1f * float(c + 1) + 0.001f * float(x);
        film.normal[p * 3 + c] = c == 1 ? 0.6f : -0.8f * float(c) / 2.0f + 0.0001f * float(y);
      }
      film.depth[p] = (x == 0) ? INFINITY : 1.25f + 0.003f * float(x * y);
    }
  }
  return film;
}

ExrMetadata testMetadata() {
  ExrMetadata m;
  m.shotFile = "scenes/shots/tear_drop.json";
  m.frame = 42;
  m.seed = 18446744073709551557ULL;  // beyond 2^63: must survive as text
  m.samplesPerPixel = 256;
  m.renderSeconds = 12.5;
  m.worldToCamera << 1, 0, 0, 0.5f,  //
      0, 0, -1, 2.0f,                //
      0, 1, 0, -3.0f,                //
      0, 0, 0, 1;
  m.worldToNDC = m.worldToCamera;
  m.worldToNDC(3, 2) = -1.0f;
  m.worldToNDC(3, 3) = 0.0f;
  m.extra["lacrima:camera"] = "closeup";
  m.extra["lacrima:note"] = "tear test";
  return m;
}

TEST(ImageOutput, ExrHasChannelsFormatsAndMetadata) {
  const fs::path dir = freshDirectory("metadata");
  const fs::path path = dir / "frame.0042.exr";
  const Film film = testFilm(13, 7);
  const ExrMetadata meta = testMetadata();
  writeExr(path, film, meta, false);

  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, 13);
  EXPECT_EQ(spec.height, 7);
  std::vector<std::string> names(spec.channelnames.begin(), spec.channelnames.end());
  std::vector<std::string> expectedNames = {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z"};
  std::sort(names.begin(), names.end());
  std::sort(expectedNames.begin(), expectedNames.end());
  EXPECT_EQ(names, expectedNames);
  ASSERT_EQ(spec.channelformats.size(), 11u) << "expected per-channel formats";
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = spec.channelnames[c];
    const bool beauty = name == "R" || name == "G" || name == "B" || name == "A";
    EXPECT_EQ(spec.channelformats[c], beauty ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT) << name;
  }
  ASSERT_GE(spec.alpha_channel, 0);
  EXPECT_EQ(spec.channelnames[spec.alpha_channel], "A");
  ASSERT_GE(spec.z_channel, 0);
  EXPECT_EQ(spec.channelnames[spec.z_channel], "Z");
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");

  EXPECT_EQ(spec.get_string_attribute("lacrima:version"), LACRIMA_VERSION);
  EXPECT_EQ(spec.get_string_attribute("lacrima:shot"), meta.shotFile);
  const OIIO::ParamValue* frame = spec.find_attribute("lacrima:frame");
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->type(), OIIO::TypeInt);
  EXPECT_EQ(frame->get_int(), 42);
  EXPECT_EQ(spec.get_string_attribute("lacrima:seed"), "18446744073709551557");
  EXPECT_EQ(spec.get_int_attribute("lacrima:spp"), 256);
  const OIIO::ParamValue* seconds = spec.find_attribute("lacrima:renderSeconds");
  ASSERT_TRUE(seconds);
  EXPECT_EQ(seconds->type(), OIIO::TypeFloat);
  EXPECT_FLOAT_EQ(seconds->get_float(), 12.5f);
  EXPECT_EQ(spec.get_string_attribute("lacrima:camera"), "closeup");
  EXPECT_EQ(spec.get_string_attribute("lacrima:note"), "tear test");
  EXPECT_EQ(spec.get_string_attribute("lacrima:colorSpace"), "ACEScg");
  EXPECT_TRUE(spec.find_attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8)));

  for (const auto& [name, matrix] : {std::pair{"worldToCamera", meta.worldToCamera}, {"worldToNDC", meta.worldToNDC}}) {
    const OIIO::ParamValue* p = spec.find_attribute(name);
    ASSERT_TRUE(p) << name;
    EXPECT_EQ(p->type(), OIIO::TypeMatrix44) << name;
    const float* m = static_cast<const float*>(p->data());
    // EXR (Imath) matrices act on row vectors, p' = p M: element [row][col] is our (col, row).
    for (int row = 0; row < 4; ++row) {
      for (int col = 0; col < 4; ++col) EXPECT_EQ(m[row * 4 + col], matrix(col, row)) << name << " " << row << col;
    }
  }
  // The translation is in the last row of the stored matrix.
  const float* w2c = static_cast<const float*>(spec.find_attribute("worldToCamera")->data());
  EXPECT_EQ(w2c[12], 0.5f);
  EXPECT_EQ(w2c[13], 2.0f);
  EXPECT_EQ(w2c[14], -3.0f);

  // AOV planes are stored exactly (float).
  std::vector<float> all(std::size_t(13) * 7 * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()));
  const auto channel = [&](const std::string& name) {
    return int(std::find(spec.channelnames.begin(), spec.channelnames.end(), name) - spec.channelnames.begin());
  };
  for (std::size_t p = 0; p < std::size_t(13) * 7; ++p) {
    EXPECT_EQ(all[p * spec.nchannels + channel("albedo.G")], film.albedo[p * 3 + 1]);
    EXPECT_EQ(all[p * spec.nchannels + channel("N.Z")], film.normal[p * 3 + 2]);
    EXPECT_EQ(all[p * spec.nchannels + channel("Z")], film.depth[p]);
  }
}

TEST(ImageOutput, BeautyRoundTripsHalfAndFloat) {
  const fs::path dir = freshDirectory("roundtrip");
  const Film film = testFilm(17, 9);
  for (const bool floatBeauty : {false, true}) {
    const fs::path path = dir / (floatBeauty ? "float.exr" : "half.exr");
    writeExr(path, film, testMetadata(), floatBeauty);
    const Film back = readExrBeauty(path);
    ASSERT_EQ(back.width, 17);
    ASSERT_EQ(back.height, 9);
    ASSERT_EQ(back.rgba.size(), film.rgba.size());
    for (std::size_t k = 0; k < film.rgba.size(); ++k) {
      if (floatBeauty) {
        ASSERT_EQ(back.rgba[k], film.rgba[k]) << k;
      } else {
        // half: 11-bit significand, relative error <= 2^-11
        ASSERT_NEAR(back.rgba[k], film.rgba[k], std::abs(film.rgba[k]) * 0x1p-11f + 1e-7f) << k;
      }
    }
    // Half really is half: 0.5 + 0.01 x is not representable exactly in half precision.
    if (!floatBeauty) {
      EXPECT_NE(back.rgba[4], film.rgba[4]);
    }
  }
  EXPECT_EQ(directoryListing(dir), (std::vector<std::string>{"float.exr", "half.exr"})) << "temporary files left";
}

// A region's film is the EXR's data window inside the whole frame (its display window), and reads
// back in its place; a whole frame's windows are the same.
TEST(ImageOutput, ARegionIsTheDataWindowInsideTheFrame) {
  const fs::path dir = freshDirectory("region");
  Film film = testFilm(7, 5);
  film.frameWidth = 40;
  film.frameHeight = 30;
  film.originX = 12;
  film.originY = 20;
  writeExr(dir / "region.exr", film, testMetadata(), true);
  auto in = OIIO::ImageInput::open((dir / "region.exr").string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(std::vector<int>({spec.x, spec.y, spec.width, spec.height}), std::vector<int>({12, 20, 7, 5}));
  EXPECT_EQ(std::vector<int>({spec.full_x, spec.full_y, spec.full_width, spec.full_height}),
            std::vector<int>({0, 0, 40, 30}));
  in->close();
  const Film back = readExrBeauty(dir / "region.exr");
  EXPECT_EQ(std::vector<int>({back.originX, back.originY, back.width, back.height, back.frameWidth, back.frameHeight}),
            std::vector<int>({12, 20, 7, 5, 40, 30}));
  EXPECT_EQ(back.rgba, film.rgba);

  writeExr(dir / "whole.exr", testFilm(7, 5), testMetadata(), true);
  const Film whole = readExrBeauty(dir / "whole.exr");
  EXPECT_EQ(std::vector<int>({whole.originX, whole.originY, whole.frameWidth, whole.frameHeight}),
            std::vector<int>({0, 0, 7, 5}));
}

TEST(ImageOutput, CreatesParentDirectoriesAndReplacesAtomically) {
  const fs::path dir = freshDirectory("atomic");
  const fs::path path = dir / "a" / "b" / "frame.exr";
  writeExr(path, testFilm(4, 3), testMetadata(), false);
  Film brighter = testFilm(4, 3);
  brighter.rgba[0] = 7.0f;
  writeExr(path, brighter, testMetadata(), false);  // replaces the existing file
  EXPECT_EQ(readExrBeauty(path).rgba[0], 7.0f);
  EXPECT_EQ(directoryListing(path.parent_path()), std::vector<std::string>{"frame.exr"});
}

TEST(ImageOutput, UnwritableLocationThrowsAndLeavesNoFile) {
  const fs::path dir = freshDirectory("unwritable");
  // The parent "directory" is a regular file (permissions are no test here: tests may run as root).
  const fs::path blocker = dir / "blocker";
  std::ofstream(blocker) << "a file, not a directory";
  const fs::path underFile = blocker / "frame.exr";
  try {
    writeExr(underFile, testFilm(4, 3), testMetadata(), false);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(underFile.string()), std::string::npos) << e.what();
  }
  // The final name is an existing directory: the temporary is written, the rename fails, and the
  // temporary must be removed.
  const fs::path occupied = dir / "occupied.exr";
  fs::create_directories(occupied / "keep");
  try {
    writeExr(occupied, testFilm(4, 3), testMetadata(), false);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(occupied.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(occupied / "keep"));
  EXPECT_THROW(writePreviewPng(blocker / "preview.png", testFilm(4, 3), kOcioConfig), InputError);
  EXPECT_EQ(directoryListing(dir), (std::vector<std::string>{"blocker", "occupied.exr"}));
}

TEST(ImageOutput, ReadingAMissingOrCorruptExrThrows) {
  const fs::path dir = freshDirectory("read_errors");
  const fs::path missing = dir / "missing.exr";
  try {
    readExrBeauty(missing);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  const fs::path corrupt = dir / "corrupt.exr";
  std::ofstream(corrupt) << "not an exr";
  EXPECT_THROW(readExrBeauty(corrupt), InputError);
}

// Reads an 8-bit PNG back as bytes.
std::vector<unsigned char> readPng(const fs::path& path, int& w, int& h, int& channels) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return {};
  w = in->spec().width;
  h = in->spec().height;
  channels = in->spec().nchannels;
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> bytes(std::size_t(w) * h * channels);
  EXPECT_TRUE(in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, bytes.data()));
  return bytes;
}

TEST(ImageOutput, PreviewOfMidGreyThroughAcesSdrVideo) {
  const fs::path dir = freshDirectory("preview");
  Film film(8, 6);
  for (std::size_t p = 0; p < std::size_t(8) * 6; ++p) {
    film.rgba[p * 4 + 0] = film.rgba[p * 4 + 1] = film.rgba[p * 4 + 2] = 0.18f;
    film.rgba[p * 4 + 3] = 1.0f;
  }
  film.rgba[4 * 1 + 0] = film.rgba[4 * 1 + 1] = film.rgba[4 * 1 + 2] = 0.0f;    // black
  film.rgba[4 * 2 + 0] = film.rgba[4 * 2 + 1] = film.rgba[4 * 2 + 2] = 1000.0f; // highlight
  film.rgba[4 * 3 + 0] = std::nanf("");                                          // must not break the preview
  const fs::path path = dir / "preview.png";
  writePreviewPng(path, film, kOcioConfig);

  int w = 0, h = 0, channels = 0;
  const std::vector<unsigned char> bytes = readPng(path, w, h, channels);
  ASSERT_EQ(w, 8);
  ASSERT_EQ(h, 6);
  ASSERT_EQ(channels, 3) << "alpha is dropped";
  // Measured on OCIO 2.1 with the shipped config: ACEScg 0.18 -> 0.356 through this view.
  const int expected = int(std::lround(0.356 * 255.0));
  for (std::size_t p = 4; p < std::size_t(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(int(bytes[p * 3 + c]), expected, 2) << "pixel " << p;
  }
  EXPECT_LE(bytes[3 * 1], 2);
  EXPECT_GE(bytes[3 * 2], 250);
  EXPECT_EQ(directoryListing(dir), std::vector<std::string>{"preview.png"}) << "temporary files left";
}

TEST(ImageOutput, PreviewWithMissingOrInvalidConfigNamesIt) {
  const fs::path dir = freshDirectory("preview_errors");
  const Film film(4, 4);
  const fs::path missing = dir / "missing.ocio";
  const fs::path invalid = dir / "invalid.ocio";
  std::ofstream(invalid) << "ocio_profile_version: 2.1\nroles: [this is not\n";
  const fs::path noView = dir / "no_view.ocio";  // parses, but lacks the display and view we need
  std::ofstream(noView) << "ocio_profile_version: 2.1\n"
                           "roles: {default: raw, scene_linear: raw}\n"
                           "displays: {sRGB: [!<View> {name: Raw, colorspace: raw}]}\n"
                           "colorspaces:\n  - !<ColorSpace> {name: raw, isdata: true}\n";
  for (const fs::path& config : {missing, invalid, noView}) {
    try {
      writePreviewPng(dir / "preview.png", film, config);
      ADD_FAILURE() << "no exception for " << config;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(config.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(fs::exists(dir / "preview.png"));
}

}  // namespace image_output_test
}  // namespace lacrima
