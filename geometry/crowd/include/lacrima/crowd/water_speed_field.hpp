#pragma once
// Where the water runs fast and where it is slow: the mean ground speed of a particle liquid per
// square cell of the field, averaged over every particle in the cell over every frame added. It
// shows what an obstacle does to a stream (Schaffer et al.'s section 4.3: "a protected area behind the
// obstacle") and is how tests and `lacrima flood` measure a block's shelter.
#include <vector>

#include "lacrima/crowd/biocrowds.hpp"
#include "lacrima/base/math.hpp"

namespace lacrima::crowd {

class WaterSpeedField {
 public:
  WaterSpeedField(const GroundRect& field, double cellSize);

  // One frame of the liquid: its particles' positions and velocities (ground components used).
  void add(const std::vector<Vec3d>& positions, const std::vector<Vec3d>& velocities);

  int columns() const { return columns_; }
  int rows() const { return rows_; }
  // The mean ground speed in cell (column, row) (column along x, row along z), or < 0 where no
  // particle ever was.
  double meanSpeed(int column, int row) const;
  // The mean ground speed over the particles of the cells whose centres lie in `region` (< 0 if dry).
  double meanSpeedIn(const GroundRect& region) const;
  // The ground point at the centre of a cell.
  Vec2d cellCenter(int column, int row) const;

 private:
  GroundRect field_;
  double cellSize_;
  int columns_, rows_;
  std::vector<double> speedSums_;
  std::vector<double> counts_;
};

// The lee of a block in a stream flowing towards -x: as long as the block, downstream of it,
// across its width.
GroundRect leeOf(const GroundRect& block);

// Beside the lee: the same stretch of the river beside the block's width, on the side with more
// room between the block and the bank (`riverMin`, `riverMax`: the banks' z). The open water the
// lee is compared with.
GroundRect besideLeeOf(const GroundRect& block, double riverMin, double riverMax);

}  // namespace lacrima::crowd
