// The flood's water speed map; see flood_water_map.hpp.
#include "flood_water_map.hpp"

#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <vector>

#include "lacrima/base/error.hpp"

namespace lacrima::cli {

namespace {

// Dark blue at rest, cyan at v_F, white at 2 v_F and above.
std::array<float, 3> speedColour(double speed, double streamSpeed) {
  const float t = float(std::clamp(speed / std::max(2.0 * streamSpeed, 1e-9), 0.0, 1.0));
  if (t < 0.5f) {
    const float u = t / 0.5f;
    return {0.02f, 0.05f + 0.65f * u, 0.3f + 0.6f * u};
  }
  const float u = (t - 0.5f) / 0.5f;
  return {u, 0.7f + 0.3f * u, 0.9f + 0.1f * u};
}

}  // namespace

void writeWaterSpeedMap(const crowd::WaterSpeedField& field, const crowd::FloodParams& params,
                        const std::filesystem::path& path) {
  // Four pixels a cell (the trajectories' top view has eight a metre); the image's first row is the
  // far side (z up).
  constexpr int kPixelsPerCell = 4;
  const int width = kPixelsPerCell * field.columns(), height = kPixelsPerCell * field.rows();
  std::vector<float> rgb(size_t(width) * size_t(height) * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int column = x / kPixelsPerCell, row = field.rows() - 1 - y / kPixelsPerCell;
      const double speed = field.meanSpeed(column, row);
      std::array<float, 3> colour = speed < 0.0 ? std::array<float, 3>{0.78f, 0.76f, 0.68f} : speedColour(speed, params.river.speed);
      for (const crowd::GroundRect& o : params.river.obstacles)
        if (o.contains(field.cellCenter(column, row))) colour = {0.25f, 0.25f, 0.25f};
      std::copy(colour.begin(), colour.end(), &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3]);
    }
  writePlotPng(path, width, height, rgb, "the water map");
}

void writePlotPng(const std::filesystem::path& path, int width, int height, const std::vector<float>& rgb, const char* what) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  image.set_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path temporary = path.string() + ".tmp.png";
  if (!image.write(temporary.string(), OIIO::TypeDesc::UINT8))
    throw InputError(fmt::format("cannot write {} '{}': {}", what, path.string(), image.geterror()));
  std::filesystem::rename(temporary, path);
}

std::string shelterSummary(const crowd::WaterSpeedField& field, const crowd::FloodParams& params) {
  std::string summary;
  const double riverMin = params.river.zMin, riverMax = params.river.zMin + params.river.width;
  for (size_t k = 0; k < params.river.obstacles.size(); ++k) {
    const crowd::GroundRect& block = params.river.obstacles[k];
    summary += fmt::format("{}obstacle {}: the water in its lee {:.2f} m/s, beside the lee {:.2f} m/s",
                           summary.empty() ? "" : "; ", k, field.meanSpeedIn(crowd::leeOf(block)),
                           field.meanSpeedIn(crowd::besideLeeOf(block, riverMin, riverMax)));
  }
  return summary;
}

}  // namespace lacrima::cli
