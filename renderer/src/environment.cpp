// Equirectangular environment map: lookup, importance sampling and its solid-angle density.
//
// Direction convention (world space, +Y up, right-handed):
//   theta = angle from +Y (0 at the zenith, pi at the nadir); v = theta / pi, so image row 0 (the
//   top of the file) is the sky above and the last row is the ground below.
//   phi   = atan2(-x, z) in [0, 2 pi); u = phi / (2 pi):
//     u = 0.5  -> -Z (the image centre is what a default camera looking down -Z sees),
//     u = 0.75 -> +X, u = 0.25 -> -X, u = 0 and 1 -> +Z (the seam is behind that camera).
//   The map is therefore seen unmirrored from the inside: going right in the image turns right.
//   Unit direction of (u, v): (-sin(theta) sin(phi), cos(theta), sin(theta) cos(phi)).
// Rotation r (radians) turns the whole environment about +Y by the right-hand rule (seen from
// above, +X goes towards -Z): whatever the unrotated map shows in direction d, the rotated map
// shows in direction R_y(r) d. In (u, v) this is phi_world = phi_map - r, a shift of u.
//
// Lookup is bilinear between the four nearest texel centres (texel (i, j) has its centre at
// u = (i + 1/2) / width, v = (j + 1/2) / height), wrapping around in longitude and clamping in
// latitude (above the first row's centres and below the last row's, the row itself).
// Nearest-texel lookup shows a map's texels as blocks wherever it is magnified (the mirror image
// of the map in a smooth drop, a blurry low-resolution sky behind the face).
//
// Importance sampling (pbrt-v3 13.6.7, "infinite area lights"): a piecewise-constant 2D
// distribution, a marginal over rows and one conditional per row, over the *cells between texel
// centres*: cell (c, r) spans u in [(c + 1/2) / w, (c + 3/2) / w) (wrapping past u = 1) and v
// between the centres of rows r - 1 and r; rows 0 and h are the half-height caps at the poles,
// from the pole to the first (last) row of centres. Inside a cell the bilinear radiance blends
// exactly its four corner texels (clamped rows at the caps), so its integral over the cell in
// (u, v) is the mean of the corners times the cell's area. A cell's weight is that mean luminance
// times the cell's solid angle (2 pi / w) (cos(theta_top) - cos(theta_bottom)), exact in theta
// (unlike sin at the cell's centre, it never vanishes). So the density follows the bilinear
// radiance as closely as a piecewise-constant one can, and the pdf is > 0 wherever the radiance
// is: a positive radiance needs a positive corner, which makes its cell's weight positive (a
// distribution over the texels themselves would need each texel's 3x3 neighbourhood for that,
// and would spread the sun's samples over twice its width). Sampling picks (u, v) with density
// p_uv, constant per cell, and maps it to a direction; with d(omega) = 2 pi^2 sin(theta) du dv
// the solid-angle density is p_uv / (2 pi^2 sin(theta)), where theta is the direction's own polar
// angle (0 returned at the poles, where it is unbounded).
//
// Zero-weight cells get no floor: they are never sampled and pdf() returns 0 there. This is
// consistent for multiple importance sampling, because pdf(dir) is defined from the same stored
// CDFs that sample() inverts (bin probability = difference of adjacent CDF entries), so pdf(dir)
// is the density of sample() for every direction, zero included. A cell with pdf 0 has radiance
// 0 (all four corners black: luminance weights are positive and texels are clamped to >= 0),
// except for cells whose weight is below float resolution of their row's CDF; such directions are
// left to BSDF sampling, whose MIS weight is then 1, so the estimate stays unbiased. Callers must
// skip light samples with pdf == 0 (possible only exactly at a pole). An entirely black map gives
// each cell the probability of its solid angle (close to uniform on the sphere; still exactly
// matched by pdf()).
//
// Texels that are NaN, infinite or negative (in any channel) become 0 and are counted
// (clampedTexelCount()); the caller decides how to report them.
#include "lacrima/renderer/environment.hpp"

#include <numbers>
#include <fmt/core.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <system_error>

#include "distribution.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {


}  // namespace

EnvironmentMap::EnvironmentMap(int width, int height, std::vector<float> rgb, float intensity,
                               float rotationRadians)
    : width_(width), height_(height), rgb_(std::move(rgb)), intensity_(intensity), rotation_(rotationRadians) {
  if (width_ < 1 || height_ < 1 || rgb_.size() != std::size_t(width_) * std::size_t(height_) * 3) {
    throw std::invalid_argument(fmt::format("EnvironmentMap: {} floats do not make a {}x{} RGB image",
                                            rgb_.size(), width_, height_));
  }
  if (!std::isfinite(intensity_) || intensity_ < 0.0f) {
    throw InputError(fmt::format("environment map: intensity must be finite and >= 0, got {}", intensity_));
  }
  if (!std::isfinite(rotation_)) {
    throw InputError(fmt::format("environment map: rotation must be finite, got {}", rotation_));
  }

  // Clamp invalid texels to black, counting texels rather than channels.
  for (std::size_t t = 0; t < rgb_.size(); t += 3) {
    bool bad = false;
    for (int c = 0; c < 3; ++c) {
      float& x = rgb_[t + c];
      if (!std::isfinite(x) || x < 0.0f) {
        x = 0.0f;
        bad = true;
      }
    }
    clampedTexels_ += bad ? 1 : 0;
  }

  buildDistribution();
}

float EnvironmentMap::texelLuminance(int i, int j) const {
  const float* p = &rgb_[(std::size_t(j) * width_ + i) * 3];
  return std::max(0.0f, luminance(Color(p[0], p[1], p[2])));
}

// See the header comment: cells between texel centres, weighted by the mean luminance of their
// four corners times their solid angle.
void EnvironmentMap::buildDistribution() {
  const int rows = height_ + 1;
  const std::size_t rowStride = std::size_t(width_) + 1;
  conditionalCdf_.assign(std::size_t(rows) * rowStride, 0.0f);
  std::vector<double> weights(static_cast<std::size_t>(width_));
  std::vector<double> rowWeights(static_cast<std::size_t>(rows));
  const double cellWidth = 2.0 * std::numbers::pi / width_;
  double total = 0.0;
  for (int r = 0; r < rows; ++r) {
    const int top = std::max(r - 1, 0), bottom = std::min(r, height_ - 1);
    for (int c = 0; c < width_; ++c) {
      const int next = (c + 1) % width_;
      weights[c] = 0.25 * (double(texelLuminance(c, top)) + texelLuminance(next, top) + texelLuminance(c, bottom) +
                           texelLuminance(next, bottom));
    }
    const double rowMeanSum =
        detail::buildCdf(weights, std::span<float>(conditionalCdf_).subspan(std::size_t(r) * rowStride, rowStride));
    rowWeights[r] = rowMeanSum * cellWidth * cellRowSolidAngleFactor(r);
    total += rowWeights[r];
  }
  if (!(total > 0.0)) {
    // Black map: rows by solid angle with uniform conditionals, each cell by its solid angle.
    for (int r = 0; r < rows; ++r) rowWeights[r] = cellRowSolidAngleFactor(r);
  }
  marginalCdf_.assign(std::size_t(rows) + 1, 0.0f);
  detail::buildCdf(rowWeights, marginalCdf_);
  // Guide tables as wide as their CDFs: about one CDF entry per guide cell.
  marginalGuide_.assign(marginalCdf_.size(), 0);
  detail::buildGuide(marginalCdf_, marginalGuide_);
  conditionalGuide_.assign(conditionalCdf_.size(), 0);
  for (int r = 0; r < rows; ++r)
    detail::buildGuide(std::span<const float>(conditionalCdf_).subspan(std::size_t(r) * rowStride, rowStride),
                       std::span<int>(conditionalGuide_).subspan(std::size_t(r) * rowStride, rowStride));
}

// v at the top of cell row r (0 <= r <= height + 1): the pole, then the rows of texel centres.
double EnvironmentMap::cellRowTop(int r) const { return std::clamp((r - 0.5) / height_, 0.0, 1.0); }

// The solid angle of cell row r divided by 2 pi / width: cos(theta_top) - cos(theta_bottom).
double EnvironmentMap::cellRowSolidAngleFactor(int r) const {
  return std::cos(std::numbers::pi * cellRowTop(r)) - std::cos(std::numbers::pi * cellRowTop(r + 1));
}

EnvironmentMap EnvironmentMap::load(const std::filesystem::path& path, float intensity, float rotationRadians) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(fmt::format("environment map '{}': file not found (or not a regular file)", name));
  }
  auto in = OIIO::ImageInput::open(name);
  if (!in) {
    throw InputError(fmt::format("environment map '{}': cannot read the image: {}", name, OIIO::geterror()));
  }
  const OIIO::ImageSpec spec = in->spec();
  const int w = spec.width, h = spec.height, nch = spec.nchannels;
  if (spec.deep || w < 1 || h < 1 || nch < 1 || spec.depth > 1) {
    throw InputError(fmt::format("environment map '{}': not a flat 2D image ({}x{}, {} channels)", name, w, h, nch));
  }
  std::vector<float> all(std::size_t(w) * h * nch);
  if (!in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, all.data())) {
    throw InputError(fmt::format("environment map '{}': cannot read the pixels: {}", name, in->geterror()));
  }
  in->close();

  // R, G, B by name when present, else the first three channels; one or two channels are grey.
  int src[3] = {0, nch >= 3 ? 1 : 0, nch >= 3 ? 2 : 0};
  const auto find = [&](const char* channel) {
    const auto it = std::find(spec.channelnames.begin(), spec.channelnames.end(), channel);
    return it == spec.channelnames.end() ? -1 : int(it - spec.channelnames.begin());
  };
  if (find("R") >= 0 && find("G") >= 0 && find("B") >= 0) {
    src[0] = find("R");
    src[1] = find("G");
    src[2] = find("B");
  }
  std::vector<float> rgb(std::size_t(w) * h * 3);
  for (std::size_t p = 0; p < std::size_t(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) rgb[p * 3 + c] = all[p * nch + src[c]];
  }
  return EnvironmentMap(w, h, std::move(rgb), intensity, rotationRadians);
}

Vec2 EnvironmentMap::directionToUv(const Vec3& d) const {
  const float theta = std::atan2(std::hypot(d.x(), d.z()), d.y());  // [0, pi], any length
  float u = (std::atan2(-d.x(), d.z()) + rotation_) * kInv2Pi;      // map phi = world phi + r
  u -= std::floor(u);
  return Vec2(u, theta * kInvPi);
}

Vec3 EnvironmentMap::uvToDirection(const Vec2& uv) const {
  const float theta = uv.y() * kPi;
  const float phi = uv.x() * (2.0f * kPi) - rotation_;  // world phi = map phi - r
  const float sinTheta = std::sin(theta);
  return Vec3(-sinTheta * std::sin(phi), std::cos(theta), sinTheta * std::cos(phi));
}

EnvironmentMap::Cell EnvironmentMap::cellAt(const Vec2& uv) const {
  // uv is in [0, 1] or NaN (a NaN direction); NaN goes to u = v = 0 without UB.
  const float u = uv.x() >= 0.0f ? uv.x() : 0.0f, v = uv.y() >= 0.0f ? std::min(uv.y(), 1.0f) : 0.0f;
  const float x = u * float(width_) - 0.5f, y = v * float(height_) - 0.5f;  // texel-centre coordinates
  const float x0 = std::floor(x), y0 = std::floor(y);
  Cell cell;
  cell.column = (int(x0) + width_) % width_;               // x0 in [-1, width - 1]
  cell.row = std::clamp(int(y0) + 1, 0, height_);          // y0 in [-1, height - 1]
  cell.fx = std::clamp(x - x0, 0.0f, 1.0f);
  cell.fy = std::clamp(y - y0, 0.0f, 1.0f);
  return cell;
}

Color EnvironmentMap::texel(int i, int j) const {
  const float* p = &rgb_[(std::size_t(j) * width_ + i) * 3];
  return Color(p[0], p[1], p[2]);
}

// Bilinear blend of the cell's four corners (rows clamped at the poles, columns wrapped).
Color EnvironmentMap::radiance(const Vec3& direction) const { return radianceIn(cellAt(directionToUv(direction))); }

Color EnvironmentMap::radianceIn(const Cell& cell) const {
  const int left = cell.column, right = (cell.column + 1) % width_;
  const int top = std::max(cell.row - 1, 0), bottom = std::min(cell.row, height_ - 1);
  const Color upper = (1.0f - cell.fx) * texel(left, top) + cell.fx * texel(right, top);
  const Color lower = (1.0f - cell.fx) * texel(left, bottom) + cell.fx * texel(right, bottom);
  return ((1.0f - cell.fy) * upper + cell.fy * lower) * intensity_;
}

float EnvironmentMap::sinPolarAngle(const Vec3& direction) {
  return std::hypot(direction.x(), direction.z()) / direction.norm();
}

float EnvironmentMap::pdf(const Vec3& direction) const {
  const float sinTheta = sinPolarAngle(direction);
  if (!(sinTheta > 0.0f)) return 0.0f;  // a pole, zero or NaN direction
  return pdfIn(cellAt(directionToUv(direction)), sinTheta);
}

EnvironmentSample EnvironmentMap::lookup(const Vec3& direction) const {
  const Cell cell = cellAt(directionToUv(direction));
  const float sinTheta = sinPolarAngle(direction);
  EnvironmentSample s;
  s.direction = direction;
  s.radiance = radianceIn(cell);
  s.pdf = sinTheta > 0.0f ? pdfIn(cell, sinTheta) : 0.0f;  // 0 at a pole, zero or NaN direction
  return s;
}

// The density of sample() in the direction of polar angle sine sinTheta (> 0) that falls in cell.
float EnvironmentMap::pdfIn(const Cell& cell, float sinTheta) const {
  const std::span<const float> row(&conditionalCdf_[std::size_t(cell.row) * (std::size_t(width_) + 1)],
                                   std::size_t(width_) + 1);
  const double cellHeight = cellRowTop(cell.row + 1) - cellRowTop(cell.row);
  const float pdfUv = float(detail::binProbability(marginalCdf_, cell.row) / cellHeight) *
                      detail::binProbability(row, cell.column) * float(width_);
  return pdfUv / (2.0f * kPi * kPi * sinTheta);
}

EnvironmentSample EnvironmentMap::sample(const Vec2& u) const {
  const detail::CdfSample rowSample = detail::sampleCdf(marginalCdf_, marginalGuide_, u.y());
  const std::size_t rowStart = std::size_t(rowSample.index) * (std::size_t(width_) + 1);
  const std::span<const float> row(&conditionalCdf_[rowStart], std::size_t(width_) + 1);
  const std::span<const int> rowGuide(&conditionalGuide_[rowStart], std::size_t(width_) + 1);
  const detail::CdfSample columnSample = detail::sampleCdf(row, rowGuide, u.x());
  const double top = cellRowTop(rowSample.index), bottom = cellRowTop(rowSample.index + 1);
  float su = (float(columnSample.index) + 0.5f + columnSample.offset) / float(width_);
  if (su >= 1.0f) su -= 1.0f;  // the cell across the seam
  const Vec2 uv(su, float(top + rowSample.offset * (bottom - top)));
  // Evaluate through the same direction -> cell lookup as radiance()/pdf(), so the returned
  // values are exactly what a BSDF-sampled ray in this direction would see.
  return lookup(uvToDirection(uv));
}

}  // namespace lacrima
