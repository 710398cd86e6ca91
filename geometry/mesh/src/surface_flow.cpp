// Steepest-descent flow paths on triangle meshes; see surface_flow.hpp.
#include "lacrima/mesh/surface_flow.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

constexpr const char* kAdjacency = "triangle adjacency";
constexpr const char* kFlowPath = "flow path";
constexpr uint32_t kNoTwin = TriangleAdjacency::kNone;

// Barycentric coordinates below this are snapped to zero: the point is on that edge (or vertex).
// About one float ulp of a weight: SurfacePoints store floats, so finer distinctions are lost anyway.
constexpr double kSnap = 1e-7;
// A triangle is degenerate (zero area within float precision) when its height over its longest
// edge is below this fraction of that edge, or below this many float ulps of its coordinates (a
// midpoint computed in float lies off its edge by about one ulp).
constexpr double kDegenerateAspect = 1e-7;
constexpr double kDegenerateUlps = 8.0;
// A direction enters a triangle across an edge when the sine of its angle to the edge exceeds this.
// Float positions tilt the normals of coplanar triangles by ~1e-7, so a descent along an edge
// would otherwise zigzag off it by that much and miss the vertices; below this it follows the edge.
constexpr double kEntering = 1e-6;

using Vec3u = Eigen::Matrix<uint32_t, 3, 1>;

int next(int corner) { return (corner + 1) % 3; }
int prev(int corner) { return (corner + 2) % 3; }
Vec3d unit(int corner) { return Vec3d::Unit(corner); }

// ---------------------------------------------------------------------------------------------
// One triangle: corners, normal and the gradients of the barycentric coordinates
// ---------------------------------------------------------------------------------------------

struct Face {
  Vec3d corner[3];
  Vec3d normal = Vec3d::Zero();
  Vec3d gradient[3];  // grad(lambda_i) = n x (edge opposite corner i) / (2 area)
  bool degenerate = true;

  Face(const TriangleMesh& mesh, uint32_t triangle) {
    for (int c = 0; c < 3; ++c)
      corner[c] = mesh.positions[mesh.indices[size_t(triangle) * 3 + size_t(c)]].cast<double>();
    const Vec3d cross = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
    const double twiceArea = cross.norm();
    double longest = 0.0, magnitude = 0.0;
    for (int c = 0; c < 3; ++c) {
      longest = std::max(longest, (corner[next(c)] - corner[c]).norm());
      magnitude = std::max(magnitude, corner[c].cwiseAbs().maxCoeff());
    }
    const double minimumHeight = std::max(kDegenerateAspect * longest,
                                          kDegenerateUlps * double(std::numeric_limits<float>::epsilon()) * magnitude);
    // Written so that NaN positions count as degenerate.
    if (!(twiceArea > minimumHeight * longest) || !std::isfinite(twiceArea)) return;
    degenerate = false;
    normal = cross / twiceArea;
    for (int c = 0; c < 3; ++c) gradient[c] = normal.cross(corner[prev(c)] - corner[next(c)]) / twiceArea;
  }

  Vec3d position(const Vec3d& barycentric) const {
    return barycentric[0] * corner[0] + barycentric[1] * corner[1] + barycentric[2] * corner[2];
  }
  // Rates of change of the barycentric coordinates per unit length along the unit direction u.
  Vec3d rates(const Vec3d& u) const { return Vec3d(gradient[0].dot(u), gradient[1].dot(u), gradient[2].dot(u)); }
};

// ---------------------------------------------------------------------------------------------
// Adjacency
// ---------------------------------------------------------------------------------------------

void requireIndices(const TriangleMesh& mesh, const char* what) {
  if (mesh.indices.size() % 3 != 0)
    throw InputError(fmt::format("{}: the mesh has {} indices, not a multiple of 3", what, mesh.indices.size()));
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.vertexCount())
      throw InputError(fmt::format("{}: index {} is vertex {}, out of range (the mesh has {} vertices)", what, i,
                                   mesh.indices[i], mesh.vertexCount()));
}

Vec3u weldedCorners(const TriangleMesh& mesh, const std::vector<uint32_t>& weld, size_t triangle) {
  const uint32_t* idx = &mesh.indices[triangle * 3];
  return Vec3u(weld[idx[0]], weld[idx[1]], weld[idx[2]]);
}

// A triangle using one (welded) vertex twice, or of zero area, has no well-defined edges or
// direction: it takes no part (so a sliver on an edge does not make that edge non-manifold).
bool takesPart(const TriangleMesh& mesh, const Vec3u& v, size_t triangle) {
  return v[0] != v[1] && v[1] != v[2] && v[0] != v[2] && !Face(mesh, uint32_t(triangle)).degenerate;
}

// Pairs the half-edges of each edge shared by exactly two triangles.
void linkTwins(const TriangleMesh& mesh, TriangleAdjacency& adjacency) {
  std::vector<std::pair<uint64_t, uint32_t>> edges;  // (key of the vertex pair, half-edge)
  edges.reserve(mesh.indices.size());
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3u v = weldedCorners(mesh, adjacency.weld, t);
    if (!takesPart(mesh, v, t)) continue;
    for (int e = 0; e < 3; ++e) {
      const uint64_t lo = std::min(v[e], v[next(e)]), hi = std::max(v[e], v[next(e)]);
      edges.emplace_back((lo << 32) | hi, uint32_t(3 * t + size_t(e)));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t begin = 0; begin < edges.size();) {
    size_t end = begin + 1;
    while (end < edges.size() && edges[end].first == edges[begin].first) ++end;
    if (end - begin == 2) {
      adjacency.twin[edges[begin].second] = edges[begin + 1].second;
      adjacency.twin[edges[begin + 1].second] = edges[begin].second;
    }
    begin = end;
  }
}

// Lists the corners of the usable triangles around each representative vertex (a CSR table).
void collectStars(const TriangleMesh& mesh, TriangleAdjacency& adjacency) {
  const size_t vertices = mesh.vertexCount();
  adjacency.starOffsets.assign(vertices + 1, 0);
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3u v = weldedCorners(mesh, adjacency.weld, t);
    if (takesPart(mesh, v, t))
      for (int c = 0; c < 3; ++c) ++adjacency.starOffsets[v[c] + 1];
  }
  for (size_t i = 0; i < vertices; ++i) adjacency.starOffsets[i + 1] += adjacency.starOffsets[i];
  adjacency.starCorners.assign(adjacency.starOffsets.back(), 0);
  std::vector<uint32_t> fill(adjacency.starOffsets.begin(), adjacency.starOffsets.end() - 1);
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3u v = weldedCorners(mesh, adjacency.weld, t);
    if (takesPart(mesh, v, t))
      for (int c = 0; c < 3; ++c) adjacency.starCorners[fill[v[c]]++] = uint32_t(3 * t + size_t(c));
  }
}

TriangleAdjacency buildFromWeld(const TriangleMesh& mesh, std::vector<uint32_t> weld) {
  TriangleAdjacency adjacency;
  adjacency.weld = std::move(weld);
  adjacency.twin.assign(mesh.indices.size(), kNoTwin);
  linkTwins(mesh, adjacency);
  collectStars(mesh, adjacency);
  return adjacency;
}

// ---------------------------------------------------------------------------------------------
// Tracing
// ---------------------------------------------------------------------------------------------

// A straight piece to walk: from `barycentric` in `triangle`, the coordinates change at `rates`
// per unit length; `slope` is the descent per unit length (g.u for the unit direction u).
struct Move {
  uint32_t triangle = 0;
  Vec3d barycentric = Vec3d::Zero();
  Vec3d rates = Vec3d::Zero();
  double slope = 0.0;
  bool leavesMesh = false;  // along a boundary edge: the water would leave the mesh here
};

// The steepest admissible direction at a point, and what was seen while looking for it.
struct Choice {
  bool found = false;
  Move best;
  bool steepFace = false;  // some triangle at the point is not flat
  bool onBoundary = false;

  void consider(const Move& move) {
    if (!found || move.slope > best.slope) {
      best = move;
      found = true;
    }
  }
};

Vec3d snapped(Vec3d b) {
  for (int c = 0; c < 3; ++c)
    if (!(b[c] >= kSnap)) b[c] = 0.0;
  return b / b.sum();
}

int zeroCount(const Vec3d& b) { return int(b[0] == 0.0) + int(b[1] == 0.0) + int(b[2] == 0.0); }

class FlowTracer {
 public:
  FlowTracer(const TriangleMesh& mesh, const TriangleAdjacency& adjacency, const Vec3d& down,
             const FlowPathOptions& options)
      : mesh_(mesh), adjacency_(adjacency), down_(down), options_(options) {}

  FlowPath trace(const SurfacePoint& start) {
    uint32_t triangle = start.triangle;
    Vec3d b = snapped(start.barycentric.cast<double>().cwiseMax(0.0));
    append(triangle, b, b, 0.0);
    if (startsInsideDegenerate(triangle, b)) return finish(FlowStop::Degenerate);
    if (down_.isZero()) return finish(FlowStop::Flat);
    for (int step = 0;; ++step) {
      if (arc_ >= double(options_.maxLength)) return finish(FlowStop::MaxLength);
      if (step >= options_.maxSteps) return finish(FlowStop::MaxSteps);
      Move move;
      if (const auto stop = chooseMove(triangle, b, move)) return finish(*stop);
      if (!walk(move, triangle, b)) return finish(FlowStop::Flat);
    }
  }

 private:
  const TriangleMesh& mesh_;
  const TriangleAdjacency& adjacency_;
  Vec3d down_;  // unit gravity (or zero)
  FlowPathOptions options_;
  FlowPath path_;
  double arc_ = 0.0;

  uint32_t vertexOf(uint32_t triangle, int corner) const {
    return adjacency_.weld[mesh_.indices[size_t(triangle) * 3 + size_t(corner)]];
  }

  bool startsInsideDegenerate(uint32_t triangle, const Vec3d& b) const {
    if (zeroCount(b) == 2) return false;  // at a vertex: its star decides
    if (!Face(mesh_, triangle).degenerate) return false;
    // On an edge of a zero-area triangle, a proper neighbour across that edge can take over.
    return zeroCount(b) == 0 || adjacency_.twin[size_t(triangle) * 3 + size_t(next(zeroIndex(b)))] == kNoTwin;
  }

  static int zeroIndex(const Vec3d& b) {
    for (int c = 0; c < 3; ++c)
      if (b[c] == 0.0) return c;
    return -1;
  }

  // Appends a point; its surface point is in `triangle` until the next piece re-expresses it.
  void append(uint32_t triangle, const Vec3d& barycentric, const Vec3d& arrival, double arc) {
    path_.points.push_back(SurfacePoint{triangle, barycentric.cast<float>()});
    path_.arrival.push_back(arrival.cast<float>());
    path_.positions.push_back(Face(mesh_, triangle).position(barycentric).cast<float>());
    path_.arcLength.push_back(float(arc));
  }

  FlowPath finish(FlowStop stop) {
    path_.stop = stop;
    return std::move(path_);
  }

  // Slope and barycentric rates of the projected gravity in `triangle`, when it leads into the
  // triangle from b (every zero coordinate must grow).
  void considerFace(uint32_t triangle, const Vec3d& b, Choice& choice) const {
    const Face face(mesh_, triangle);
    if (face.degenerate) return;
    const Vec3d d = down_ - down_.dot(face.normal) * face.normal;
    const double slope = d.norm();
    if (!(slope > double(options_.flatTolerance))) return;
    choice.steepFace = true;
    const Vec3d rates = face.rates(d / slope);
    for (int c = 0; c < 3; ++c)
      if (b[c] == 0.0 && !(rates[c] > kEntering * face.gradient[c].norm())) return;
    choice.consider(Move{triangle, b, rates, slope, false});
  }

  // The edge of `triangle` from corner `from` towards corner `to`, walked from b (on that edge).
  void considerEdge(uint32_t triangle, int from, int to, const Vec3d& b, bool boundary, Choice& choice) const {
    const Face face(mesh_, triangle);
    const Vec3d edge = face.corner[to] - face.corner[from];
    const double length = edge.norm();
    if (!(length > 0.0)) return;
    const double slope = down_.dot(edge) / length;
    if (!(slope > double(options_.flatTolerance))) return;
    choice.consider(Move{triangle, b, (unit(to) - unit(from)) / length, slope, boundary});
  }

  // b (on edge e of `triangle`) expressed in the neighbour across that edge.
  bool acrossEdge(uint32_t triangle, int e, const Vec3d& b, uint32_t& other, Vec3d& otherB) const {
    const uint32_t twin = adjacency_.twin[size_t(triangle) * 3 + size_t(e)];
    if (twin == kNoTwin) return false;
    other = twin / 3;
    otherB = Vec3d::Zero();
    for (int c : {e, next(e)})
      for (int k = 0; k < 3; ++k)
        if (vertexOf(other, k) == vertexOf(triangle, c)) otherB[k] = b[c];
    return otherB.sum() > 0.5;  // both ends matched (a mesh of another topology would not)
  }

  std::optional<FlowStop> chooseMove(uint32_t triangle, const Vec3d& b, Move& move) const {
    Choice choice;
    switch (zeroCount(b)) {
      case 0: considerFace(triangle, b, choice); break;
      case 1: chooseOnEdge(triangle, b, choice); break;
      default: chooseAtVertex(triangle, b, choice); break;
    }
    if (choice.found && !choice.best.leavesMesh) {
      move = choice.best;
      return std::nullopt;
    }
    if (choice.found || (choice.onBoundary && choice.steepFace)) return FlowStop::Boundary;
    return choice.steepFace ? FlowStop::Pit : FlowStop::Flat;
  }

  // On an edge: the triangle on either side, or along the edge either way (a crease).
  void chooseOnEdge(uint32_t triangle, const Vec3d& b, Choice& choice) const {
    const int e = next(zeroIndex(b));
    considerFace(triangle, b, choice);
    uint32_t other;
    Vec3d otherB;
    if (!acrossEdge(triangle, e, b, other, otherB)) {
      choice.onBoundary = true;
      return;
    }
    considerFace(other, otherB, choice);
    considerEdge(triangle, e, next(e), b, false, choice);
    considerEdge(triangle, next(e), e, b, false, choice);
  }

  // At a vertex: every triangle around it and every edge leaving it.
  void chooseAtVertex(uint32_t triangle, const Vec3d& b, Choice& choice) const {
    int corner = 0;
    for (int c = 0; c < 3; ++c)
      if (b[c] != 0.0) corner = c;
    const uint32_t vertex = vertexOf(triangle, corner);
    for (uint32_t i = adjacency_.starOffsets[vertex]; i < adjacency_.starOffsets[vertex + 1]; ++i) {
      const uint32_t t = adjacency_.starCorners[i] / 3;
      const int c = int(adjacency_.starCorners[i] % 3);
      considerFace(t, unit(c), choice);
    }
    for (uint32_t i = adjacency_.starOffsets[vertex]; i < adjacency_.starOffsets[vertex + 1]; ++i) {
      const uint32_t t = adjacency_.starCorners[i] / 3;
      const int c = int(adjacency_.starCorners[i] % 3);
      const bool nextIsBoundary = adjacency_.twin[size_t(t) * 3 + size_t(c)] == kNoTwin;
      const bool prevIsBoundary = adjacency_.twin[size_t(t) * 3 + size_t(prev(c))] == kNoTwin;
      considerEdge(t, c, next(c), unit(c), nextIsBoundary, choice);
      considerEdge(t, c, prev(c), unit(c), prevIsBoundary, choice);
      choice.onBoundary = choice.onBoundary || nextIsBoundary || prevIsBoundary;
    }
  }

  // Walks the piece to the first edge it meets (or to maxLength) and appends the end point.
  // False (nothing appended) for a direction that never leaves the triangle, which a unit
  // direction in the triangle's plane cannot do (its rates sum to zero); kept as a guard.
  bool walk(const Move& move, uint32_t& triangle, Vec3d& b) {
    double exit = std::numeric_limits<double>::infinity();
    int leaving = -1;
    for (int c = 0; c < 3; ++c)
      if (move.rates[c] < 0.0 && move.barycentric[c] / -move.rates[c] < exit) {
        exit = move.barycentric[c] / -move.rates[c];
        leaving = c;
      }
    const double remaining = double(options_.maxLength) - arc_;
    const bool reachesMaxLength = !(exit < remaining);
    if (leaving < 0 && !std::isfinite(remaining)) return false;
    const double t = reachesMaxLength ? remaining : exit;
    Vec3d end = move.barycentric + t * move.rates;
    if (!reachesMaxLength) end[leaving] = 0.0;
    end = snapped(end.cwiseMax(0.0));
    arc_ = reachesMaxLength ? double(options_.maxLength) : arc_ + t;
    // The piece starts at the previous point, re-expressed in the piece's triangle.
    path_.points.back() = SurfacePoint{move.triangle, move.barycentric.cast<float>()};
    append(move.triangle, end, end, arc_);
    triangle = move.triangle;
    b = end;
    return true;
  }
};

void requireOptions(const FlowPathOptions& options) {
  if (!(options.maxLength >= 0.0f))
    throw InputError(fmt::format("{}: maxLength must be >= 0, got {}", kFlowPath, options.maxLength));
  if (options.maxSteps < 1)
    throw InputError(fmt::format("{}: maxSteps must be >= 1, got {}", kFlowPath, options.maxSteps));
  if (!(options.flatTolerance >= 0.0f && options.flatTolerance < 1.0f))
    throw InputError(fmt::format("{}: flatTolerance must be in [0, 1), got {}", kFlowPath, options.flatTolerance));
}

}  // namespace

TriangleAdjacency buildTriangleAdjacency(const TriangleMesh& mesh) {
  requireIndices(mesh, kAdjacency);
  std::vector<uint32_t> identity(mesh.vertexCount());
  for (size_t v = 0; v < identity.size(); ++v) identity[v] = uint32_t(v);
  return buildFromWeld(mesh, std::move(identity));
}

TriangleAdjacency buildTriangleAdjacency(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap) {
  requireIndices(mesh, kAdjacency);
  if (weldMap.size() != mesh.vertexCount())
    throw InputError(
        fmt::format("{}: the weld map has {} entries for {} vertices", kAdjacency, weldMap.size(), mesh.vertexCount()));
  for (size_t v = 0; v < weldMap.size(); ++v)
    if (weldMap[v] >= mesh.vertexCount())
      throw InputError(fmt::format("{}: the weld map sends vertex {} to {}, out of range", kAdjacency, v, weldMap[v]));
  return buildFromWeld(mesh, weldMap);
}

const char* flowStopName(FlowStop stop) {
  switch (stop) {
    case FlowStop::MaxLength: return "max length";
    case FlowStop::Boundary: return "boundary";
    case FlowStop::Pit: return "pit";
    case FlowStop::Flat: return "flat";
    case FlowStop::MaxSteps: return "max steps";
    case FlowStop::Degenerate: return "degenerate";
  }
  return "unknown";
}

FlowPath traceFlowPath(const TriangleMesh& mesh, const TriangleAdjacency& adjacency, const SurfacePoint& start,
                       const Vec3& gravity, const FlowPathOptions& options) {
  requireOptions(options);
  if (adjacency.triangleCount() != mesh.triangleCount() || adjacency.vertexCount() != mesh.vertexCount())
    throw InputError(fmt::format("{}: the adjacency is for {} triangles and {} vertices, the mesh has {} and {}",
                                 kFlowPath, adjacency.triangleCount(), adjacency.vertexCount(), mesh.triangleCount(),
                                 mesh.vertexCount()));
  requireIndices(mesh, kFlowPath);
  if (!gravity.allFinite())
    throw InputError(
        fmt::format("{}: gravity ({}, {}, {}) must be finite", kFlowPath, gravity.x(), gravity.y(), gravity.z()));
  surfacePosition(mesh, start);  // validates the start
  const Vec3d g = gravity.cast<double>();
  const Vec3d down = g.isZero() ? Vec3d::Zero() : Vec3d(g / g.norm());
  return FlowTracer(mesh, adjacency, down, options).trace(start);
}

std::vector<SurfacePoint> resampleFlowPath(const FlowPath& path, float spacing) {
  if (!(spacing > 0.0f) || !std::isfinite(spacing))
    throw InputError(fmt::format("{}: the resampling spacing must be finite and > 0, got {}", kFlowPath, spacing));
  std::vector<SurfacePoint> samples;
  if (path.points.empty()) return samples;
  const double length = path.length();
  const double count = std::floor(length / double(spacing));
  if (count > 1e7)
    throw InputError(
        fmt::format("{}: spacing {} gives more than 10^7 samples over a length of {}", kFlowPath, spacing, length));
  samples.reserve(size_t(count) + 2);
  size_t piece = 0;
  for (size_t k = 0; k <= size_t(count); ++k) {
    const double s = double(k) * double(spacing);
    while (piece + 2 < path.points.size() && double(path.arcLength[piece + 1]) < s) ++piece;
    if (piece + 1 >= path.points.size()) {
      samples.push_back(path.points[piece]);
      continue;
    }
    const double a = path.arcLength[piece], z = path.arcLength[piece + 1];
    const double u = z > a ? std::clamp((s - a) / (z - a), 0.0, 1.0) : 0.0;
    const Vec3d b =
        (1.0 - u) * path.points[piece].barycentric.cast<double>() + u * path.arrival[piece + 1].cast<double>();
    samples.push_back(SurfacePoint{path.points[piece].triangle, b.cast<float>()});
  }
  if (length - count * double(spacing) > 1e-3 * double(spacing)) samples.push_back(path.points.back());
  return samples;
}

}  // namespace lacrima
