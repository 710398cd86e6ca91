// Shortest paths around rectangular obstacles; see ground_navigation.hpp.
#include "lacrima/crowd/ground_navigation.hpp"

#include <algorithm>
#include <limits>

namespace lacrima::crowd {

namespace {

GroundRect grown(const GroundRect& r, double by) { return {r.min - Vec2d::Constant(by), r.max + Vec2d::Constant(by)}; }

// Whether segment a-b passes through the open rectangle r (Liang & Barsky 1984's clipping).
bool segmentCrosses(const Vec2d& a, const Vec2d& b, const GroundRect& r) {
  const Vec2d d = b - a;
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] <= r.min[axis] || a[axis] >= r.max[axis]) return false;
      continue;
    }
    double t0 = (r.min[axis] - a[axis]) / d[axis], t1 = (r.max[axis] - a[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter >= leave) return false;
  }
  return true;
}

}  // namespace

GroundNavigation::GroundNavigation(std::vector<GroundRect> obstacles, double margin)
    : obstacles_(std::move(obstacles)), margin_(margin) {
  for (const GroundRect& o : obstacles_) {
    const GroundRect g = grown(o, margin_);
    corners_.insert(corners_.end(), {g.min, Vec2d(g.max.x(), g.min.y()), g.max, Vec2d(g.min.x(), g.max.y())});
  }
}

bool GroundNavigation::clear(const Vec2d& a, const Vec2d& b, double clearance) const {
  return std::none_of(obstacles_.begin(), obstacles_.end(),
                      [&](const GroundRect& o) { return segmentCrosses(a, b, grown(o, clearance)); });
}

Vec2d GroundNavigation::nextWaypoint(const Vec2d& from, const Vec2d& goal) const {
  // Segments between grown corners run along the grown faces: test them against obstacles grown
  // a little less, so that they count as clear. An agent already inside the margin (pushed there)
  // tests its first leg against the bare obstacles.
  const double clearance = 0.99 * margin_;
  if (obstacles_.empty() || (clear(from, goal, 0.0) && clear(from, goal, clearance))) return goal;
  // Nodes: 0 = from, 1 = goal, then the corners. Dijkstra over the visibility graph (a handful of
  // obstacles: a dense O(n^2) search is enough).
  std::vector<Vec2d> nodes{from, goal};
  nodes.insert(nodes.end(), corners_.begin(), corners_.end());
  const size_t n = nodes.size();
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  std::vector<int> previous(n, -1);
  std::vector<bool> done(n, false);
  distance[0] = 0.0;
  for (size_t round = 0; round < n; ++round) {
    size_t u = n;
    for (size_t i = 0; i < n; ++i)
      if (!done[i] && (u == n || distance[i] < distance[u])) u = i;
    if (u == n || distance[u] == std::numeric_limits<double>::infinity()) break;
    done[u] = true;
    if (u == 1) break;
    for (size_t v = 1; v < n; ++v) {
      if (done[v]) continue;
      if (!clear(nodes[u], nodes[v], u == 0 ? 0.0 : clearance)) continue;
      const double through = distance[u] + (nodes[v] - nodes[u]).norm();
      if (through < distance[v]) distance[v] = through, previous[v] = int(u);
    }
  }
  if (previous[1] < 0) return goal;
  int step = 1;
  while (previous[size_t(step)] != 0) step = previous[size_t(step)];
  return nodes[size_t(step)];
}

}  // namespace lacrima::crowd
