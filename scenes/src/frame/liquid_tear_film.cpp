// A liquid tear's wet trail as per-vertex film thickness on the skin; see liquid_tear_film.hpp.
#include "frame/liquid_tear_film.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>

#include "lacrima/base/bucket_lists.hpp"
#include "lacrima/base/gradient_noise.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima::shotfile {

namespace {

// One straight piece of the path on this frame's skin, with the film along it.
struct WetPiece {
  Vec3 from, to;       // posed positions
  Vec3 direction;      // to - from
  float length2 = 0.0f;  // its squared length
  double s0 = 0.0, s1 = 0.0;  // arc lengths at its ends
  float reach = 0.0f;  // distance beyond which the film has fallen to 0 (widest film on the piece)
  float unitReach = 0.0f;  // the same for a point whose edge factor is 1 (reach / (1 + kFilmEdgeWander))
  float peak = 0.0f;   // no point gets more film from this piece (the thickest cell it crosses)
};

// The pieces of the path that carry film, each with its reach; empty when the trail is dry.
std::vector<WetPiece> wetPieces(const ShotLiquidTear& tear, const FlowPath& path,
                                const LiquidTearSimulation& simulation, const TriangleMesh& skin) {
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
    piece.unitReach = float(0.5 * widest) * (1.0f + kFilmEdgeFraction);
    piece.reach = piece.unitReach * (1.0f + kFilmEdgeWander);
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
  explicit FilmCells(const LiquidTearSimulation& simulation) {
    for (size_t c = 0; c < simulation.filmCellCount(); ++c) {
      thickness.push_back(simulation.filmThicknessOfCell(c));
      halfWidth.push_back(float(0.5 * simulation.filmWidthOfCell(c)));
    }
  }
  std::vector<double> thickness;  // m
  std::vector<float> halfWidth;   // m
};

// The film a piece lays at distance r from it, its closest point a fraction f along it: the
// thickness at that arc length times the falloff at the half width there scaled by the point's edge
// factor (1 + kFilmEdgeWander v); 0 from the piece's reach on.
float filmAtClosestPoint(const WetPiece& piece, const FilmCells& cells, const LiquidTearSimulation& simulation,
                         float f, float r, float edgeFactor) {
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
// At most kMaxCells cells (larger cells on a long, sparse trail); the lists are stored flat
// (BucketLists), rebuilt every frame.
class WetPieceGrid {
 public:
  WetPieceGrid(const std::vector<Eigen::AlignedBox3f>& pieceBoxes, const std::vector<uint32_t>& order,
               const Eigen::AlignedBox3f& bounds)
      : origin_(bounds.min()) {
    const Vec3 extent = bounds.sizes();
    cellSize_ = std::max(medianBoxSize(pieceBoxes) / kCellsAcrossPieceBox, 1e-9f);
    while (cellCount(extent) > kMaxCells) cellSize_ *= 1.25f;
    for (int k = 0; k < 3; ++k) cells_[k] = int(extent[k] / cellSize_) + 1;
    pieces_ = makeBucketLists(size_t(cells_[0]) * cells_[1] * cells_[2],
                              [&](auto visit) { forEachCell(pieceBoxes, order, visit); });
  }

  size_t cellCount() const { return pieces_.bucketCount(); }
  // The cell of p (a point inside the bounds).
  size_t cellIndexOf(const Vec3& p) const { return index(cellOf(p)); }
  // The pieces whose boxes overlap cell c, in the order given.
  std::span<const uint32_t> piecesIn(size_t c) const { return pieces_.in(c); }

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
  BucketLists pieces_;  // piece indices by cell
};

// The skin vertices inside the grid's bounds gathered cell by cell (BucketLists), with their
// positions in separate x, y, z arrays in the same order, so that a piece is measured against a
// cell's vertices in one loop the compiler vectorises.
struct VerticesByCell {
  VerticesByCell(const std::vector<Vec3>& positions, const Eigen::AlignedBox3f& bounds, const WetPieceGrid& grid)
      : byCell(makeBucketLists(grid.cellCount(), [&](auto visit) {
          for (size_t v = 0; v < positions.size(); ++v)
            if (bounds.contains(positions[v])) visit(uint32_t(v), grid.cellIndexOf(positions[v]));
        })) {
    x.reserve(byCell.items.size()), y.reserve(byCell.items.size()), z.reserve(byCell.items.size());
    for (const uint32_t v : byCell.items)
      x.push_back(positions[v].x()), y.push_back(positions[v].y()), z.push_back(positions[v].z());
  }
  BucketLists byCell;          // skin vertex indices by cell
  std::vector<float> x, y, z;  // their positions, in byCell.items' order
};

// What one cell's evaluation needs, shared by all cells.
struct FilmInputs {
  const std::vector<WetPiece>& pieces;
  const std::vector<Eigen::AlignedBox3f>& pieceBoxes;
  const FilmCells& cells;
  const LiquidTearSimulation& simulation;
};

// Per-thread scratch of a cell's evaluation, one value per vertex of the cell.
struct CellScratch {
  std::vector<float> film, edgeFactor, fraction, distance2;
  std::vector<int> candidate;
  void resize(size_t n) {
    film.assign(n, 0.0f);
    edgeFactor.resize(n), fraction.resize(n), distance2.resize(n), candidate.resize(n);
  }
};

// For each vertex k of a cell (positions x, y, z from `begin`): the fraction along the piece of its
// closest point and the squared distance to it, written as filmAtClosestPoint's caller computed them
// per vertex with Eigen (a dot product of three terms sums as a0 b0 + (a1 b1 + a2 b2)), so the film
// is bitwise the same; and whether the vertex can get film from the piece: inside its box, within
// its reach (squared, with a margin: the exact test follows on the square root) and below its peak.
void measureAgainstPiece(const WetPiece& piece, const Eigen::AlignedBox3f& pieceBox, const VerticesByCell& vertices,
                         size_t begin, CellScratch& scratch) {
  const float fx = piece.from.x(), fy = piece.from.y(), fz = piece.from.z();
  const float dx = piece.direction.x(), dy = piece.direction.y(), dz = piece.direction.z();
  const float length2 = piece.length2, peak = piece.peak;
  // A point with edge factor e gets no film beyond e unitReach (edgeFalloff is 0 from 1.1 e half
  // widths on, and no cell the piece crosses is wider than its widest): a tighter bound than the
  // reach for the half of the vertices whose edge lies inside. Both squared, with a margin.
  const float reach2 = piece.reach * piece.reach * (1.0f + 1e-5f);
  const float unitReach2 = piece.unitReach * piece.unitReach * (1.0f + 1e-3f);
  const float* __restrict edgeFactor = scratch.edgeFactor.data();
  const float loX = pieceBox.min().x(), loY = pieceBox.min().y(), loZ = pieceBox.min().z();
  const float hiX = pieceBox.max().x(), hiY = pieceBox.max().y(), hiZ = pieceBox.max().z();
  const float* __restrict x = vertices.x.data() + begin;
  const float* __restrict y = vertices.y.data() + begin;
  const float* __restrict z = vertices.z.data() + begin;
  const float* __restrict film = scratch.film.data();
  float* __restrict fraction = scratch.fraction.data();
  float* __restrict distance2 = scratch.distance2.data();
  int* __restrict candidate = scratch.candidate.data();
  const int n = int(scratch.film.size());
  // Branch-free (bitwise & of the comparisons, selects for the clamp) and free of aliasing (the
  // arrays are distinct; GCC cannot prove it through the vectors) so that it vectorises.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC ivdep
#endif
  for (int k = 0; k < n; ++k) {
    const int inside = int(loX <= x[k]) & int(loY <= y[k]) & int(loZ <= z[k]) & int(x[k] <= hiX) & int(y[k] <= hiY) &
                       int(z[k] <= hiZ);
    const float along = (x[k] - fx) * dx + ((y[k] - fy) * dy + (z[k] - fz) * dz);
    const float quotient = along / length2;
    const float clamped = quotient < 0.0f ? 0.0f : (1.0f < quotient ? 1.0f : quotient);
    const float f = length2 > 0.0f ? clamped : 0.0f;
    const float ex = x[k] - (fx + f * dx), ey = y[k] - (fy + f * dy), ez = z[k] - (fz + f * dz);
    const float r2 = ex * ex + (ey * ey + ez * ez);
    fraction[k] = f;
    distance2[k] = r2;
    const float edgeReach2 = edgeFactor[k] * edgeFactor[k] * unitReach2;
    candidate[k] = inside & int(r2 <= reach2) & int(r2 <= edgeReach2) & int(film[k] < peak);
  }
}

// The film of one cell's vertices: the largest over the pieces listed in the cell (thickest first),
// stopping once no vertex of the cell has less film than the next piece's peak.
void filmOfCell(const FilmInputs& in, std::span<const uint32_t> piecesInCell, const VerticesByCell& vertices,
                size_t cell, const std::vector<float>& edgeFactorOfVertex, CellScratch& scratch, std::vector<float>& films) {
  const size_t begin = vertices.byCell.first[cell], n = vertices.byCell.first[cell + 1] - begin;
  scratch.resize(n);
  for (size_t k = 0; k < n; ++k) scratch.edgeFactor[k] = edgeFactorOfVertex[vertices.byCell.items[begin + k]];
  float leastFilm = 0.0f;
  for (const uint32_t i : piecesInCell) {
    const WetPiece& piece = in.pieces[i];
    if (piece.peak <= leastFilm) break;
    measureAgainstPiece(piece, in.pieceBoxes[i], vertices, begin, scratch);
    leastFilm = std::numeric_limits<float>::infinity();
    for (size_t k = 0; k < n; ++k) {
      if (scratch.candidate[k]) {
        const float r = std::sqrt(scratch.distance2[k]);
        scratch.film[k] = std::max(
            scratch.film[k], filmAtClosestPoint(piece, in.cells, in.simulation, scratch.fraction[k], r, scratch.edgeFactor[k]));
      }
      leastFilm = std::min(leastFilm, scratch.film[k]);
    }
  }
  for (size_t k = 0; k < n; ++k) films[vertices.byCell.items[begin + k]] = scratch.film[k];
}

// The piece's box grown by its reach on every side.
Eigen::AlignedBox3f grownBox(const WetPiece& piece) {
  Eigen::AlignedBox3f b(piece.from.cwiseMin(piece.to), piece.from.cwiseMax(piece.to));
  b.min().array() -= piece.reach;
  b.max().array() += piece.reach;
  return b;
}

// Each vertex's film raised into `wetness` (resized from empty on the first wet vertex).
void raiseWetness(const std::vector<float>& films, std::vector<float>& wetness) {
  for (size_t v = 0; v < films.size(); ++v) {
    if (films[v] <= 0.0f) continue;
    if (wetness.empty()) wetness.assign(films.size(), 0.0f);
    wetness[v] = std::max(wetness[v], films[v]);
  }
}

}  // namespace

void addLiquidTearFilmOverEveryPiece(const ShotLiquidTear& tear, const FlowPath& course,
                                     const LiquidTearSimulation& simulation, const TriangleMesh& skin,
                                     std::vector<float>& wetness) {
  const std::vector<WetPiece> pieces = wetPieces(tear, course, simulation, skin);
  const FilmCells cells(simulation);
  const bool hasVariation = tear.filmEdgeVariation.size() == skin.positions.size();
  std::vector<float> films(skin.positions.size(), 0.0f);
  for (size_t v = 0; v < skin.positions.size(); ++v) {
    const Vec3& p = skin.positions[v];
    const float edgeFactor = hasVariation ? 1.0f + kFilmEdgeWander * tear.filmEdgeVariation[v] : 1.0f;
    for (const WetPiece& piece : pieces) {
      if (!grownBox(piece).contains(p)) continue;  // the reach's box: beyond it, no film
      const Vec3 d = piece.to - piece.from;
      const float f = d.squaredNorm() > 0.0f ? std::clamp((p - piece.from).dot(d) / d.squaredNorm(), 0.0f, 1.0f) : 0.0f;
      const float r = (p - (piece.from + f * d)).norm();
      films[v] = std::max(films[v], filmAtClosestPoint(piece, cells, simulation, f, r, edgeFactor));
    }
  }
  raiseWetness(films, wetness);
}

void addLiquidTearFilm(const ShotLiquidTear& tear, const FlowPath& course, const LiquidTearSimulation& simulation,
                       const TriangleMesh& skin, std::vector<float>& wetness) {
  const std::vector<WetPiece> pieces = wetPieces(tear, course, simulation, skin);
  if (pieces.empty()) return;
  // Only vertices in the box around the wet pieces, grown by their reach, can get film.
  Eigen::AlignedBox3f box;
  std::vector<Eigen::AlignedBox3f> pieceBoxes;
  for (const WetPiece& piece : pieces) {
    pieceBoxes.push_back(grownBox(piece));
    box.extend(pieceBoxes.back());
  }
  // Thickest first: once a vertex has as much film as the next piece could give it, no later piece
  // can raise its maximum, and the rest are skipped (the maximum, hence the film, is unchanged).
  std::vector<uint32_t> thickestFirst(pieces.size());
  std::iota(thickestFirst.begin(), thickestFirst.end(), 0u);
  std::stable_sort(thickestFirst.begin(), thickestFirst.end(),
                   [&](uint32_t a, uint32_t b) { return pieces[a].peak > pieces[b].peak; });
  const WetPieceGrid grid(pieceBoxes, thickestFirst, box);
  // Each vertex's film depends on nothing but its position and the pieces: the grid's cells are
  // split between the threads, and the result does not depend on how.
  const FilmCells cells(simulation);
  const bool hasVariation = tear.filmEdgeVariation.size() == skin.positions.size();
  std::vector<float> edgeFactor(skin.positions.size(), 1.0f);
  if (hasVariation)
    for (size_t v = 0; v < edgeFactor.size(); ++v) edgeFactor[v] = 1.0f + kFilmEdgeWander * tear.filmEdgeVariation[v];
  const VerticesByCell vertices(skin.positions, box, grid);
  const FilmInputs inputs{pieces, pieceBoxes, cells, simulation};
  std::vector<float> films(skin.positions.size(), 0.0f);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, grid.cellCount(), 256), [&](const tbb::blocked_range<size_t>& r) {
    CellScratch scratch;
    for (size_t c = r.begin(); c != r.end(); ++c)
      if (!vertices.byCell.in(c).empty() && !grid.piecesIn(c).empty())
        filmOfCell(inputs, grid.piecesIn(c), vertices, c, edgeFactor, scratch, films);
  });
  raiseWetness(films, wetness);
}

}  // namespace lacrima::shotfile
