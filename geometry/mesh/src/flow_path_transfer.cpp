// Mapping arc lengths between two courses of a flow path; see flow_path_transfer.hpp.
#include "lacrima/mesh/flow_path_transfer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {

std::vector<FlowPathTransfer::Piece> FlowPathTransfer::piecesOn(const FlowPath& path, const TriangleMesh& skin) {
  if (path.points.size() < 2 || path.arrival.size() != path.points.size() || path.arcLength.size() != path.points.size())
    throw InputError(fmt::format("flow path transfer: a course needs at least 2 points with arrivals and arc lengths, "
                                 "got {}", path.points.size()));
  std::vector<Piece> pieces;
  for (size_t i = 0; i + 1 < path.points.size(); ++i) {
    // A piece is straight in its triangle, and a triangle is flat on any pose: its image is the
    // segment between its ends' positions on `skin`.
    const SurfacePoint end{path.points[i].triangle, path.arrival[i + 1]};
    pieces.push_back({double(path.arcLength[i]), double(path.arcLength[i + 1]),
                      surfacePosition(skin, path.points[i]).cast<double>(), surfacePosition(skin, end).cast<double>()});
  }
  return pieces;
}

FlowPathTransfer::FlowPathTransfer(const FlowPath& from, const FlowPath& to, const TriangleMesh& skin)
    : old_(piecesOn(from, skin)), new_(piecesOn(to, skin)) {}

Vec3d FlowPathTransfer::materialPoint(double s) const {
  // The last piece starting at or before s.
  const auto after = std::upper_bound(old_.begin(), old_.end(), s, [](double v, const Piece& p) { return v < p.s0; });
  const Piece& piece = after == old_.begin() ? old_.front() : *(after - 1);
  const double length = piece.s1 - piece.s0;
  const double f = length > 0.0 ? std::clamp((s - piece.s0) / length, 0.0, 1.0) : 0.0;
  return piece.from + f * (piece.to - piece.from);
}

double FlowPathTransfer::project(const Vec3d& p, double* distance) const {
  double best = std::numeric_limits<double>::infinity(), arc = 0.0;
  for (const Piece& piece : new_) {
    const Vec3d d = piece.to - piece.from;
    const double length2 = d.squaredNorm();
    const double f = length2 > 0.0 ? std::clamp((p - piece.from).dot(d) / length2, 0.0, 1.0) : 0.0;
    const double r2 = (p - (piece.from + f * d)).squaredNorm();
    if (r2 < best) {  // strict: the earliest piece wins a tie, so the map is deterministic
      best = r2;
      arc = piece.s0 + f * (piece.s1 - piece.s0);
    }
  }
  if (distance) *distance = std::sqrt(best);
  return arc;
}

double FlowPathTransfer::operator()(double s) const {
  if (!std::isfinite(s)) return project(materialPoint(s), nullptr);  // not remembered (NaN is no key)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (const auto known = images_.find(s); known != images_.end()) return known->second;
  }
  const double image = project(materialPoint(s), nullptr);  // a pure function of s: a race stores the same value
  std::lock_guard<std::mutex> lock(mutex_);
  images_.emplace(s, image);
  return image;
}

double FlowPathTransfer::sidewaysStep(double s) const {
  double distance = 0.0;
  project(materialPoint(s), &distance);
  return distance;
}

}  // namespace lacrima
