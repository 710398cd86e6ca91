// The water's mean speed over the field; see water_speed_field.hpp.
#include "lacrima/crowd/water_speed_field.hpp"

#include <cmath>

namespace lacrima::crowd {

WaterSpeedField::WaterSpeedField(const GroundRect& field, double cellSize)
    : field_(field),
      cellSize_(cellSize),
      columns_(std::max(1, int(std::ceil((field.max.x() - field.min.x()) / cellSize)))),
      rows_(std::max(1, int(std::ceil((field.max.y() - field.min.y()) / cellSize)))),
      speedSums_(size_t(columns_) * size_t(rows_), 0.0),
      counts_(speedSums_.size(), 0.0) {}

void WaterSpeedField::add(const std::vector<Vec3d>& positions, const std::vector<Vec3d>& velocities) {
  for (size_t i = 0; i < positions.size() && i < velocities.size(); ++i) {
    const int column = int(std::floor((positions[i].x() - field_.min.x()) / cellSize_));
    const int row = int(std::floor((positions[i].z() - field_.min.y()) / cellSize_));
    if (column < 0 || row < 0 || column >= columns_ || row >= rows_) continue;
    const size_t cell = size_t(row) * size_t(columns_) + size_t(column);
    speedSums_[cell] += std::hypot(velocities[i].x(), velocities[i].z());
    counts_[cell] += 1.0;
  }
}

double WaterSpeedField::meanSpeed(int column, int row) const {
  const size_t cell = size_t(row) * size_t(columns_) + size_t(column);
  return counts_[cell] > 0.0 ? speedSums_[cell] / counts_[cell] : -1.0;
}

Vec2d WaterSpeedField::cellCenter(int column, int row) const {
  return field_.min + cellSize_ * Vec2d(column + 0.5, row + 0.5);
}

double WaterSpeedField::meanSpeedIn(const GroundRect& region) const {
  double sum = 0.0, count = 0.0;
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column)
      if (region.contains(cellCenter(column, row))) {
        const size_t cell = size_t(row) * size_t(columns_) + size_t(column);
        sum += speedSums_[cell], count += counts_[cell];
      }
  return count > 0.0 ? sum / count : -1.0;
}

GroundRect leeOf(const GroundRect& block) {
  const double length = block.max.x() - block.min.x();
  return GroundRect{Vec2d(block.min.x() - length, block.min.y()), Vec2d(block.min.x(), block.max.y())};
}

GroundRect besideLeeOf(const GroundRect& block, double riverMin, double riverMax) {
  const GroundRect lee = leeOf(block);
  const double width = block.max.y() - block.min.y();
  const bool below = block.min.y() - riverMin > riverMax - block.max.y();
  const double z0 = below ? std::max(riverMin, block.min.y() - width) : block.max.y();
  const double z1 = below ? block.min.y() : std::min(riverMax, block.max.y() + width);
  return GroundRect{Vec2d(lee.min.x(), z0), Vec2d(lee.max.x(), z1)};
}

}  // namespace lacrima::crowd
