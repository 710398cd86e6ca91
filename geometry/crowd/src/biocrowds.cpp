// BioCrowds agents competing for markers; see biocrowds.hpp.
#include "lacrima/crowd/biocrowds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lacrima/crowd/ground_navigation.hpp"
#include "lacrima/base/hash.hpp"

namespace lacrima::crowd {

namespace {

bool insideAny(const std::vector<GroundRect>& rects, const Vec2d& p) {
  return std::any_of(rects.begin(), rects.end(), [&](const GroundRect& r) { return r.contains(p); });
}

// f(x, y) = (1 + cos theta) / (1 + |y|) (eq. 3), theta the angle between x and y.
double markerAttraction(const Vec2d& towardsGoal, const Vec2d& towardsMarker) {
  const double goalLength = towardsGoal.norm(), markerLength = towardsMarker.norm();
  const double cosine = goalLength > 0.0 && markerLength > 0.0 ? towardsGoal.dot(towardsMarker) / (goalLength * markerLength) : 0.0;
  return (1.0 + cosine) / (1.0 + markerLength);
}

}  // namespace

std::vector<Vec2d> scatterMarkers(const GroundRect& ground, const std::vector<GroundRect>& obstacles,
                                  const CrowdParams& params) {
  if (!(params.markerDensity > 0.0)) throw std::invalid_argument("scatterMarkers: the marker density must be positive");
  const double spacing = 1.0 / std::sqrt(params.markerDensity);
  const Vec2d size = ground.max - ground.min;
  const long columns = long(std::ceil(size.x() / spacing)), rows = long(std::ceil(size.y() / spacing));
  std::vector<Vec2d> markers;
  markers.reserve(size_t(std::max(0L, columns * rows)));
  for (long j = 0; j < rows; ++j)
    for (long i = 0; i < columns; ++i) {
      const uint64_t key = hashCombine(hashCombine(params.seed, uint64_t(i)), uint64_t(j));
      const Vec2d jitter(uint64ToUnitFloat(mix64(key)), uint64ToUnitFloat(mix64(key ^ 0x5bd1e995ULL)));
      const Vec2d p = ground.min + spacing * (Vec2d(double(i), double(j)) + jitter);
      if (ground.contains(p) && !insideAny(obstacles, p)) markers.push_back(p);
    }
  return markers;
}

double freeMotionLength(double personalSpace) {
  const double R = personalSpace, logTerm = std::log1p(R);
  const double second = 0.5 * R * R - R + logTerm;  // int_0^R rho^2 / (1 + rho)
  const double first = R - logTerm;                 // int_0^R rho / (1 + rho)
  return 0.5 * second / first;
}

BioCrowds::BioCrowds(const CrowdParams& params, const GroundRect& ground, const std::vector<GroundRect>& obstacles,
                     std::vector<Agent> agents)
    : params_(params),
      ground_(ground),
      obstacles_(obstacles),
      agents_(std::move(agents)),
      markers_(scatterMarkers(ground, obstacles, params)),
      freeMotion_(freeMotionLength(params.personalSpace)),
      navigation_(std::make_unique<GroundNavigation>(obstacles, params.obstacleMargin)) {
  if (!(params.personalSpace > 0.0)) throw std::invalid_argument("BioCrowds: the personal space must be positive");
  // Markers sorted into square cells of side R: an agent's markers lie in the 3 x 3 cells around it.
  cellSize_ = params.personalSpace;
  columns_ = std::max(1L, long(std::ceil((ground.max.x() - ground.min.x()) / cellSize_)));
  rows_ = std::max(1L, long(std::ceil((ground.max.y() - ground.min.y()) / cellSize_)));
  std::vector<std::vector<uint32_t>> cells(size_t(columns_ * rows_));
  for (uint32_t k = 0; k < markers_.size(); ++k) cells[size_t(cellOf(markers_[k]))].push_back(k);
  cellStart_.assign(cells.size() + 1, 0);
  for (size_t c = 0; c < cells.size(); ++c) {
    cellStart_[c + 1] = cellStart_[c] + uint32_t(cells[c].size());
    cellMarkers_.insert(cellMarkers_.end(), cells[c].begin(), cells[c].end());
  }
}

BioCrowds::~BioCrowds() = default;
BioCrowds::BioCrowds(BioCrowds&&) noexcept = default;
BioCrowds& BioCrowds::operator=(BioCrowds&&) noexcept = default;

long BioCrowds::cellOf(const Vec2d& p) const {
  const long i = std::clamp(long(std::floor((p.x() - ground_.min.x()) / cellSize_)), 0L, columns_ - 1);
  const long j = std::clamp(long(std::floor((p.y() - ground_.min.y()) / cellSize_)), 0L, rows_ - 1);
  return j * columns_ + i;
}

std::vector<uint32_t> BioCrowds::markersNear(const Vec2d& p) const {
  std::vector<uint32_t> near;
  const long cell = cellOf(p), ci = cell % columns_, cj = cell / columns_;
  const double radiusSquared = params_.personalSpace * params_.personalSpace;
  for (long j = std::max(0L, cj - 1); j <= std::min(rows_ - 1, cj + 1); ++j)
    for (long i = std::max(0L, ci - 1); i <= std::min(columns_ - 1, ci + 1); ++i) {
      const size_t c = size_t(j * columns_ + i);
      for (uint32_t n = cellStart_[c]; n < cellStart_[c + 1]; ++n)
        if ((markers_[cellMarkers_[n]] - p).squaredNorm() < radiusSquared) near.push_back(cellMarkers_[n]);
    }
  return near;
}

std::vector<int> BioCrowds::markerOwners() const {
  std::vector<int> owner(markers_.size(), -1);
  std::vector<double> closest(markers_.size(), std::numeric_limits<double>::infinity());
  // In agent order with a strict comparison: a marker equally close to two agents goes to the
  // first, whatever the thread count or platform.
  for (size_t a = 0; a < agents_.size(); ++a) {
    if (agents_[a].arrived) continue;
    for (uint32_t k : markersNear(agents_[a].position)) {
      const double d = (markers_[k] - agents_[a].position).squaredNorm();
      if (d < closest[k]) closest[k] = d, owner[k] = int(a);
    }
  }
  return owner;
}

std::vector<Vec2d> BioCrowds::walkingVelocities() const {
  const std::vector<int> owner = markerOwners();
  std::vector<Vec2d> heading(agents_.size(), Vec2d::Zero());
  for (size_t a = 0; a < agents_.size(); ++a)
    if (!agents_[a].arrived) heading[a] = navigation_->nextWaypoint(agents_[a].position, agents_[a].goal);
  std::vector<Vec2d> motion(agents_.size(), Vec2d::Zero());
  std::vector<double> weightSum(agents_.size(), 0.0);
  for (size_t k = 0; k < markers_.size(); ++k) {
    if (owner[k] < 0) continue;
    const Agent& agent = agents_[size_t(owner[k])];
    const Vec2d towardsMarker = markers_[k] - agent.position;
    const double w = markerAttraction(heading[size_t(owner[k])] - agent.position, towardsMarker);
    motion[size_t(owner[k])] += w * towardsMarker;
    weightSum[size_t(owner[k])] += w;
  }
  std::vector<Vec2d> velocity(agents_.size(), Vec2d::Zero());
  for (size_t a = 0; a < agents_.size(); ++a) {
    if (agents_[a].arrived || weightSum[a] <= 0.0) continue;
    const Vec2d m = motion[a] / weightSum[a];  // eqs. 1-2
    const double length = m.norm();
    if (length <= 0.0) continue;
    // Eq. 4, |m| in units of a lone agent's (biocrowds.hpp "Units").
    velocity[a] = agents_[a].maxSpeed * std::min(1.0, length / freeMotion_) * m / length;
  }
  return velocity;
}

Vec2d BioCrowds::slideAlongObstacles(const Vec2d& from, const Vec2d& displacement) const {
  if (!insideAny(obstacles_, from + displacement)) return displacement;
  // Keep the component along the obstacle's face: the larger of the two that stays outside.
  const Vec2d alongX(displacement.x(), 0.0), alongZ(0.0, displacement.y());
  const bool xFree = !insideAny(obstacles_, from + alongX), zFree = !insideAny(obstacles_, from + alongZ);
  if (xFree && (!zFree || std::abs(alongX.x()) >= std::abs(alongZ.y()))) return alongX;
  if (zFree) return alongZ;
  return Vec2d::Zero();
}

void BioCrowds::move(const std::vector<Vec2d>& velocities, double dt) {
  if (velocities.size() != agents_.size()) throw std::invalid_argument("BioCrowds::move: one velocity per agent");
  for (size_t a = 0; a < agents_.size(); ++a) {
    Agent& agent = agents_[a];
    if (agent.arrived) continue;
    const Vec2d from = agent.position, displacement = slideAlongObstacles(from, dt * velocities[a]);
    agent.position += displacement;
    // Arrived when the step passed within the goal radius (not only when it ended there).
    const double along = displacement.squaredNorm() > 0.0
                             ? std::clamp((agent.goal - from).dot(displacement) / displacement.squaredNorm(), 0.0, 1.0)
                             : 0.0;
    if ((from + along * displacement - agent.goal).norm() <= params_.goalRadius) agent.arrived = true;
  }
}

}  // namespace lacrima::crowd
