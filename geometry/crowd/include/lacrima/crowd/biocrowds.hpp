#pragma once
// BioCrowds (de Lima Bicho et al. 2012, "Simulating crowds based on a space colonization
// algorithm", Computers & Graphics 36(2); as summarised by Schaffer et al. 2020, section 2.1):
// markers scattered over the walkable ground; each step every marker within an agent's personal
// space R goes to the closest agent only, and each agent walks towards the weighted mean of its
// markers:
//   m = sum_k w_k (a_k - X)                                  (eq. 1)
//   w_k = f(g - X, a_k - X) / sum_l f(g - X, a_l - X)         (eq. 2)
//   f(x, y) = (1 + cos theta) / (1 + |y|), theta = angle(x, y) (eq. 3)
//   v = min(|m|, S_max) m / |m|                               (eq. 4)
// Because a marker belongs to one agent, an agent's markers lie in its own Voronoi cell and the
// mean of them too: agents do not walk through each other (collision-free by construction), and
// they slow down where markers are scarce (a dense crowd).
//
// Units. Eq. 4 compares |m|, a length, with a speed. lacrima reads it as |m| scaled so that an
// agent alone on open ground (all markers of its disc its own) walks at S_max: speed =
// S_max min(1, |m| / m_free), with m_free the expected |m| of that lone agent for the given R
// (freeMotionLength). Crowding still slows agents exactly as eq. 4 does; S_max keeps its meaning
// of the desired speed (1.3 m/s in Schaffer et al.'s experiments).
//
// The ground is the plane y = 0 of lacrima's Y-up world: agents and markers are (x, z) points.
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

namespace lacrima::crowd {

using Vec2d = Eigen::Vector2d;
class GroundNavigation;

// An axis-aligned rectangle of the ground (x, z).
struct GroundRect {
  Vec2d min = Vec2d::Zero(), max = Vec2d::Zero();
  bool contains(const Vec2d& p) const {
    return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
  }
};

struct CrowdParams {
  double markerDensity = 4.0;     // markers per square metre (one per cell of a jittered grid)
  double personalSpace = 1.5;     // R, metres: an agent sees the markers this close
  double obstacleMargin = 0.75;   // metres: how wide a berth agents steer around obstacles (ground_navigation.hpp)
  double goalRadius = 1.0;        // metres: an agent this close to its goal has arrived (and leaves)
  uint64_t seed = 1;              // the markers' jitter
};

struct Agent {
  Vec2d position = Vec2d::Zero();
  Vec2d goal = Vec2d::Zero();
  double maxSpeed = 1.3;  // S_max, m/s
  bool arrived = false;   // reached its goal: it takes no markers and stands still
};

// Markers: one per cell of a square grid of spacing 1 / sqrt(density), jittered within its cell
// by a hash of (seed, cell), none inside an obstacle.
std::vector<Vec2d> scatterMarkers(const GroundRect& ground, const std::vector<GroundRect>& obstacles,
                                  const CrowdParams& params);

// The expected |m| of an agent alone among uniformly scattered markers within R:
// (1/2) int_0^R rho^2 / (1 + rho) drho / int_0^R rho / (1 + rho) drho (eqs. 1-3 in polar form).
double freeMotionLength(double personalSpace);

class BioCrowds {
 public:
  BioCrowds(const CrowdParams& params, const GroundRect& ground, const std::vector<GroundRect>& obstacles,
            std::vector<Agent> agents);
  ~BioCrowds();
  BioCrowds(BioCrowds&&) noexcept;
  BioCrowds& operator=(BioCrowds&&) noexcept;

  // Each agent's walking velocity (eq. 4, m/s) from the markers it holds now; zero for an agent
  // that has arrived or holds none. Agents are not moved. The goal of eqs. 2-3 is the next corner
  // of the agent's way round the obstacles (ground_navigation.hpp), its own goal when none is in
  // the way.
  std::vector<Vec2d> walkingVelocities() const;
  // Moves every agent that has not arrived by its velocity for dt seconds (sliding along an
  // obstacle it would enter), and marks those whose step passed within the goal radius of their
  // goal as arrived. `velocities` are the walking velocities or
  // others (the coupling to a liquid, fluid_coupling.hpp).
  void move(const std::vector<Vec2d>& velocities, double dt);
  // walkingVelocities then move.
  void step(double dt) { move(walkingVelocities(), dt); }

  const std::vector<Agent>& agents() const { return agents_; }
  std::vector<Agent>& agents() { return agents_; }
  const std::vector<Vec2d>& markers() const { return markers_; }
  const CrowdParams& params() const { return params_; }
  // For each marker, the agent holding it now (-1: none), as walkingVelocities assigns them.
  std::vector<int> markerOwners() const;

 private:
  // The displacement with what would end inside an obstacle taken out: the agent slides along the
  // obstacle's face (or stops in a corner). Markers alone do not keep agents out: the weighted
  // mean of markers on two faces of a corner can lie inside it.
  Vec2d slideAlongObstacles(const Vec2d& from, const Vec2d& displacement) const;
  long cellOf(const Vec2d& p) const;                 // the marker cell holding p (clamped to the ground)
  std::vector<uint32_t> markersNear(const Vec2d& p) const;  // markers within R of p, ascending

  CrowdParams params_;
  GroundRect ground_;
  std::vector<GroundRect> obstacles_;
  std::vector<Agent> agents_;
  std::vector<Vec2d> markers_;
  double freeMotion_;
  std::unique_ptr<GroundNavigation> navigation_;
  // Markers sorted into square cells of side R over the ground: cell c holds
  // cellMarkers_[cellStart_[c], cellStart_[c + 1]).
  double cellSize_ = 1.0;
  long columns_ = 1, rows_ = 1;
  std::vector<uint32_t> cellStart_, cellMarkers_;
};

}  // namespace lacrima::crowd
