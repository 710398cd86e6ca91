#pragma once
// Which way to walk around rectangular obstacles: the first corner of the shortest path from a point
// to a goal that keeps `margin` clear of every obstacle (a visibility graph over the corners of the
// obstacles grown by the margin, searched by Dijkstra's algorithm). BioCrowds' markers steer an
// agent towards its goal's direction only (biocrowds.hpp, eq. 3), so a wall across that direction
// is a dead end: the markers either side of the agent pull it sideways equally. Walking towards the
// path's next corner instead (the role of the navigation mesh that BioCrowds' implementations steer
// by) takes it round.
#include <vector>

#include "lacrima/crowd/biocrowds.hpp"

namespace lacrima::crowd {

class GroundNavigation {
 public:
  GroundNavigation(std::vector<GroundRect> obstacles, double margin);
  // The point to walk towards now: `goal` itself when nothing is in the way, else the next corner
  // of the shortest path around the grown obstacles. `goal` when no path exists.
  Vec2d nextWaypoint(const Vec2d& from, const Vec2d& goal) const;
  // Whether the straight segment a-b stays clear of every obstacle grown by `clearance`.
  bool clear(const Vec2d& a, const Vec2d& b, double clearance) const;

 private:
  std::vector<GroundRect> obstacles_;
  double margin_;
  std::vector<Vec2d> corners_;  // of the obstacles grown by the margin
};

}  // namespace lacrima::crowd
