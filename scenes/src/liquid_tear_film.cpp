// A liquid tear's wet trail as per-vertex film thickness on the skin; see liquid_tear_film.hpp.
#include "liquid_tear_film.hpp"

#include <algorithm>

#include "lacrima/geometry/surface_point.hpp"

namespace lacrima::shotfile {

namespace {

// One straight piece of the path on this frame's skin, with the film along it.
struct WetPiece {
  Vec3 from, to;       // posed positions
  double s0 = 0.0, s1 = 0.0;  // arc lengths at its ends
  float reach = 0.0f;  // distance beyond which the film has fallen to 0 (widest film on the piece)
};

// The pieces of the path that carry film, each with its reach; empty when the trail is dry.
std::vector<WetPiece> wetPieces(const ShotLiquidTear& tear, const FlowPath& path,
                                const TearLiquidSimulation& simulation, const TriangleMesh& skin) {
  // Cells are trailCellLength long: probing every half cell meets each cell a piece crosses.
  const double probe = 0.5 * tear.input.params.trailCellLength;
  std::vector<WetPiece> pieces;
  for (size_t i = 0; i + 1 < path.points.size(); ++i) {
    WetPiece piece{Vec3::Zero(), Vec3::Zero(), path.arcLength[i], path.arcLength[i + 1], 0.0f};
    double widest = 0.0;
    for (double s = piece.s0;; s = std::min(s + probe, piece.s1)) {
      if (simulation.filmThicknessAt(s) > 0.0) widest = std::max(widest, simulation.filmWidthAt(s));
      if (s >= piece.s1) break;
    }
    if (widest <= 0.0) continue;
    piece.from = surfacePosition(skin, path.points[i]);
    piece.to = surfacePosition(skin, SurfacePoint{path.points[i].triangle, path.arrival[i + 1]});
    piece.reach = float(0.5 * widest) * (1.0f + kFilmEdgeFraction);
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

// The film a piece lays on point p: thickness at p's closest point on the piece, times the falloff.
float filmFromPiece(const WetPiece& piece, const TearLiquidSimulation& simulation, const Vec3& p) {
  const Vec3 d = piece.to - piece.from;
  const float length2 = d.squaredNorm();
  const float f = length2 > 0.0f ? std::clamp((p - piece.from).dot(d) / length2, 0.0f, 1.0f) : 0.0f;
  const float r = (p - (piece.from + f * d)).norm();
  if (r >= piece.reach) return 0.0f;
  const double s = piece.s0 + double(f) * (piece.s1 - piece.s0);
  const double thickness = simulation.filmThicknessAt(s);
  if (thickness <= 0.0) return 0.0f;
  return float(thickness) * edgeFalloff(r, float(0.5 * simulation.filmWidthAt(s)));
}

}  // namespace

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
  for (size_t v = 0; v < skin.positions.size(); ++v) {
    const Vec3& p = skin.positions[v];
    if (!box.contains(p)) continue;
    float film = 0.0f;
    for (size_t i = 0; i < pieces.size(); ++i)
      if (pieceBoxes[i].contains(p)) film = std::max(film, filmFromPiece(pieces[i], simulation, p));
    if (film <= 0.0f) continue;
    if (wetness.empty()) wetness.assign(skin.positions.size(), 0.0f);
    wetness[v] = std::max(wetness[v], film);
  }
}

}  // namespace lacrima::shotfile
