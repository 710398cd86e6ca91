// A liquid tear's wet trail as per-vertex film thickness on the skin; see liquid_tear_film.hpp.
#include "liquid_tear_film.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>
#include <span>

#include "lacrima/geometry/gradient_noise.hpp"
#include "lacrima/geometry/surface_point.hpp"

namespace lacrima::shotfile {

namespace {

// One straight piece of the path on this frame's skin, with the film along it.
struct WetPiece {
  Vec3 from, to;       // posed positions
  Vec3 direction;      // to - from
  float length2 = 0.0f;  // its squared length
  double s0 = 0.0, s1 = 0.0;  // arc lengths at its ends
  float reach = 0.0f;  // distance beyond which the film has fallen to 0 (widest film on the piece)
  float peak = 0.0f;   // no point gets more film from this piece (the thickest cell it crosses)
};

// The pieces of the path that carry film, each with its reach; empty when the trail is dry.
std::vector<WetPiece> wetPieces(const ShotLiquidTear& tear, const FlowPath& path,
                                const TearLiquidSimulation& simulation, const TriangleMesh& skin) {
  // Cells are trailCellLength long: probing every half cell meets each cell a piece crosses.
  const double probe = 0.5 * tear.input.params.trailCellLength;
  std::vector<WetPiece> pieces;
  for (size_t i = 0; i + 1 < path.points.size(); ++i) {
    WetPiece piece;
    piece.s0 = path.arcLength[i];
    piece.s1 = path.arcLength[i + 1];
    double widest = 0.0;
    for (double s = piece.s0;; s = std::min(s + probe, piece.s1)) {
      if (simulation.filmThicknessAt(s) > 0.0) widest = std::max(widest, simulation.filmWidthAt(s));
      if (s >= piece.s1) break;
    }
    if (widest <= 0.0) continue;
    piece.from = surfacePosition(skin, path.points[i]);
    piece.to = surfacePosition(skin, SurfacePoint{path.points[i].triangle, path.arrival[i + 1]});
    piece.direction = piece.to - piece.from;
    piece.length2 = piece.direction.squaredNorm();
    piece.reach = float(0.5 * widest) * (1.0f + kFilmEdgeFraction) * (1.0f + kFilmEdgeWander);
    piece.peak = float(simulation.maxFilmThicknessBetween(piece.s0, piece.s1));
    pieces.push_back(piece);
  }
  return pieces;
}

// 1 within the half width h, smoothstep down to 0 at h (1 + kFilmEdgeFraction).
float edgeFalloff(float r, float halfWidth) {
  if (r <= halfWidth) return 1.0f;
  const float x = std::min(1.0f, (r - halfWidth) / (kFilmEdgeFraction * halfWidth));
  return 1.0f - x * x * (3.0f - 2.0f * x);
}

// The film's cells as this frame's simulation holds them, tabulated once: a frame asks for them
// tens of millions of times, and each answer from the simulation costs three divisions.
struct FilmCells {
  explicit FilmCells(const TearLiquidSimulation& simulation) {
    for (size_t c = 0; c < simulation.filmCellCount(); ++c) {
      thickness.push_back(simulation.filmThicknessOfCell(c));
      halfWidth.push_back(float(0.5 * simulation.filmWidthOfCell(c)));
    }
  }
  std::vector<double> thickness;  // m
  std::vector<float> halfWidth;   // m
};

// The film a piece lays on point p: thickness at p's closest point on the piece, times the falloff
// at the half width there scaled by p's edge factor (1 + kFilmEdgeWander v).
float filmFromPiece(const WetPiece& piece, const FilmCells& cells, const TearLiquidSimulation& simulation,
                    const Vec3& p, float edgeFactor) {
  const Vec3& d = piece.direction;
  const float f = piece.length2 > 0.0f ? std::clamp((p - piece.from).dot(d) / piece.length2, 0.0f, 1.0f) : 0.0f;
  const float r = (p - (piece.from + f * d)).norm();
  if (r >= piece.reach) return 0.0f;
  const long cell = simulation.filmCellAt(piece.s0 + double(f) * (piece.s1 - piece.s0));
  if (cell < 0 || cells.thickness[size_t(cell)] <= 0.0) return 0.0f;
  return float(cells.thickness[size_t(cell)]) * edgeFalloff(r, edgeFactor * cells.halfWidth[size_t(cell)]);
}

// The wet pieces by the cells of a uniform grid over their boxes: each piece is listed in every
// cell its box overlaps, in the order given, so a vertex tests only the pieces of its own cell,
// among them every piece whose box contains it. Cells are an eighth of a typical (median) piece box
// wide: a piece is much shorter than its reach (the default shot's ~0.07 mm pieces reach ~3 mm), so
// a box holds ~100 pieces along the path and a cell as wide as a box made each wet vertex test
// ~700 pieces where ~200 boxes contain it (kCellsAcrossPieceBox 1 -> 8: 58 -> 32 M tests a frame).
// At most kMaxCells cells (larger cells on a long, sparse trail); the lists are stored flat (cell
// c's pieces: entries_[first_[c]] to entries_[first_[c + 1]]), one allocation each, rebuilt every frame.
class WetPieceGrid {
 public:
  WetPieceGrid(const std::vector<Eigen::AlignedBox3f>& pieceBoxes, const std::vector<uint32_t>& order,
               const Eigen::AlignedBox3f& bounds)
      : origin_(bounds.min()) {
    const Vec3 extent = bounds.sizes();
    cellSize_ = std::max(medianBoxSize(pieceBoxes) / kCellsAcrossPieceBox, 1e-9f);
    while (cellCount(extent) > kMaxCells) cellSize_ *= 1.25f;
    for (int k = 0; k < 3; ++k) cells_[k] = int(extent[k] / cellSize_) + 1;
    first_.assign(size_t(cells_[0]) * cells_[1] * cells_[2] + 1, 0);
    forEachCell(pieceBoxes, order, [&](uint32_t, size_t cell) { ++first_[cell + 1]; });
    for (size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
    entries_.resize(first_.back());
    std::vector<uint32_t> filled(first_.begin(), first_.end() - 1);
    forEachCell(pieceBoxes, order, [&](uint32_t piece, size_t cell) { entries_[filled[cell]++] = piece; });
  }

  // The pieces whose boxes may contain p (a point inside the bounds), in the order given.
  std::span<const uint32_t> piecesNear(const Vec3& p) const {
    const size_t c = index(cellOf(p));
    return {entries_.data() + first_[c], entries_.data() + first_[c + 1]};
  }

 private:
  static constexpr float kCellsAcrossPieceBox = 8.0f;
  static constexpr double kMaxCells = 1 << 21;

  double cellCount(const Vec3& extent) const {
    double count = 1.0;
    for (int k = 0; k < 3; ++k) count *= double(int(extent[k] / cellSize_) + 1);
    return count;
  }

  static float medianBoxSize(const std::vector<Eigen::AlignedBox3f>& boxes) {
    std::vector<float> sizes;
    for (const Eigen::AlignedBox3f& b : boxes) sizes.push_back(b.sizes().maxCoeff());
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    return sizes[sizes.size() / 2];
  }

  // Calls visit(piece, cell) for every cell each piece's box overlaps, pieces in `order`.
  template <typename Visit>
  void forEachCell(const std::vector<Eigen::AlignedBox3f>& boxes, const std::vector<uint32_t>& order, Visit visit) const {
    for (const uint32_t i : order) {
      const Eigen::Vector3i lo = cellOf(boxes[i].min()), hi = cellOf(boxes[i].max());
      for (int z = lo.z(); z <= hi.z(); ++z)
        for (int y = lo.y(); y <= hi.y(); ++y)
          for (int x = lo.x(); x <= hi.x(); ++x) visit(i, index(Eigen::Vector3i(x, y, z)));
    }
  }

  Eigen::Vector3i cellOf(const Vec3& p) const {
    Eigen::Vector3i c;
    for (int k = 0; k < 3; ++k) c[k] = std::clamp(int((p[k] - origin_[k]) / cellSize_), 0, cells_[k] - 1);
    return c;
  }
  size_t index(const Eigen::Vector3i& c) const { return (size_t(c.z()) * cells_[1] + c.y()) * cells_[0] + c.x(); }

  Vec3 origin_;
  float cellSize_ = 1.0f;
  int cells_[3] = {1, 1, 1};
  std::vector<uint32_t> first_;    // per cell, where its pieces start in entries_ (one more at the end)
  std::vector<uint32_t> entries_;  // piece indices, cell after cell
};

}  // namespace

std::vector<float> filmEdgeVariation(const TriangleMesh& skinAtFirstFrame) {
  std::vector<float> variation(skinAtFirstFrame.positions.size());
  // A fixed seed: the pattern is a property of the skin, the same in every shot.
  constexpr uint64_t kSeed = 0x7ea5f11e;
  for (size_t v = 0; v < variation.size(); ++v)
    variation[v] = std::clamp(
        kFilmEdgeContrast * fractalGradientNoise(skinAtFirstFrame.positions[v] / kFilmEdgeFeatureSize, kFilmEdgeOctaves, kSeed),
        -1.0f, 1.0f);
  return variation;
}

void addLiquidTearFilm(const ShotLiquidTear& tear, const FlowPath& course, const TearLiquidSimulation& simulation,
                       const TriangleMesh& skin, std::vector<float>& wetness) {
  const std::vector<WetPiece> pieces = wetPieces(tear, course, simulation, skin);
  if (pieces.empty()) return;
  // Only vertices in the box around the wet pieces, grown by their reach, can get film.
  Eigen::AlignedBox3f box;
  std::vector<Eigen::AlignedBox3f> pieceBoxes;
  for (const WetPiece& piece : pieces) {
    Eigen::AlignedBox3f b(piece.from.cwiseMin(piece.to), piece.from.cwiseMax(piece.to));
    b.min().array() -= piece.reach;
    b.max().array() += piece.reach;
    pieceBoxes.push_back(b);
    box.extend(b);
  }
  // Thickest first: once a vertex has as much film as the next piece could give it, no later piece
  // can raise its maximum, and the rest are skipped (the maximum, hence the film, is unchanged).
  std::vector<uint32_t> thickestFirst(pieces.size());
  std::iota(thickestFirst.begin(), thickestFirst.end(), 0u);
  std::stable_sort(thickestFirst.begin(), thickestFirst.end(),
                   [&](uint32_t a, uint32_t b) { return pieces[a].peak > pieces[b].peak; });
  const WetPieceGrid grid(pieceBoxes, thickestFirst, box);
  // Each vertex's film depends on nothing but its position: the vertices are split between the
  // threads, and the result does not depend on how.
  const FilmCells cells(simulation);
  const bool hasVariation = tear.filmEdgeVariation.size() == skin.positions.size();
  std::vector<float> films(skin.positions.size(), 0.0f);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, skin.positions.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v != r.end(); ++v) {
      const Vec3& p = skin.positions[v];
      if (!box.contains(p)) continue;
      const float edgeFactor = hasVariation ? 1.0f + kFilmEdgeWander * tear.filmEdgeVariation[v] : 1.0f;
      float film = 0.0f;
      for (const uint32_t i : grid.piecesNear(p)) {
        if (pieces[i].peak <= film) break;
        if (pieceBoxes[i].contains(p)) film = std::max(film, filmFromPiece(pieces[i], cells, simulation, p, edgeFactor));
      }
      films[v] = film;
    }
  });
  for (size_t v = 0; v < films.size(); ++v) {
    if (films[v] <= 0.0f) continue;
    if (wetness.empty()) wetness.assign(skin.positions.size(), 0.0f);
    wetness[v] = std::max(wetness[v], films[v]);
  }
}

}  // namespace lacrima::shotfile
