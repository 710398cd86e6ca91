// Procedural skin furrows; see furrows.hpp for the field and its sources.
#include "lacrima/materials/furrows.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "lacrima/base/hash.hpp"
#include "lattice_cell.hpp"

namespace lacrima {

namespace {

constexpr uint64_t kFurrowSeed = 0x6675727277ULL;  // "furrw": decorrelates from the pores' lattice

// One mix per cell (the coordinates folded by odd constants, then SplitMix64's finaliser), three
// 21-bit fractions from it: the jitter of the cell's feature point. Cheaper than chaining a
// hash per coordinate; the field is evaluated at every skin hit.
Vec3 jitterOfCell(int64_t i, int64_t j, int64_t k) {
  const uint64_t h = mix64(kFurrowSeed ^ (uint64_t(i) * 0x9e3779b97f4a7c15ULL) ^ (uint64_t(j) * 0xc2b2ae3d27d4eb4fULL) ^
                           (uint64_t(k) * 0x165667b19e3779f9ULL));
  constexpr float kUnit = 0x1p-21f;
  constexpr uint64_t kMask = (1u << 21) - 1;
  return Vec3(float(h >> 43) * kUnit, float((h >> 22) & kMask) * kUnit, float((h >> 1) & kMask) * kUnit);
}

// The feature points of the 27 cells around the home cell, in home-cell coordinates, and their
// squared distances to `local`. All are hashed: cheaper than pruning cells by branches.
struct FeaturePoints {
  std::array<Vec3, 27> points;
  std::array<float, 27> squaredDistances;
  int nearest = 0;
};

FeaturePoints featurePointsAround(const LatticeCell& cell) {
  FeaturePoints f;
  int index = 0;
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj)
      for (int dk = -1; dk <= 1; ++dk, ++index) {
        f.points[index] = Vec3(float(di), float(dj), float(dk)) + jitterOfCell(cell.i + di, cell.j + dj, cell.k + dk);
        f.squaredDistances[index] = (cell.local - f.points[index]).squaredNorm();
      }
  // Select without branches: which point is nearest is unpredictable from hit to hit.
  float best = f.squaredDistances[0];
  for (int i = 1; i < 27; ++i) {
    const bool nearer = f.squaredDistances[i] < best;
    best = nearer ? f.squaredDistances[i] : best;
    f.nearest = nearer ? i : f.nearest;
  }
  return f;
}

}  // namespace

FurrowHeight furrowHeight(const Vec3& p, float scale, float depth) {
  FurrowHeight result;
  if (depth <= 0.0f) return result;
  const FeaturePoints f = featurePointsAround(latticeCellOf(p, scale));
  const int nearest = f.nearest;
  const Vec3& c1 = f.points[nearest];
  const float d1Squared = f.squaredDistances[nearest];
  const float reach = std::sqrt(d1Squared) + 2.0f * kFurrowHalfWidth;
  float wallDistance = kFurrowHalfWidth;  // only walls nearer than the half-width shape the field
  Vec3 awayFromWall = Vec3::Zero();       // unit normal of the nearest wall, towards c1
  for (int index = 0; index < 27; ++index) {
    // Farther points have no wall within the half-width (furrows.hpp), and skip c1 itself.
    if (index == nearest || f.squaredDistances[index] >= reach * reach) continue;
    const Vec3 between = c1 - f.points[index];
    const float length = between.norm();
    if (!(length > 1e-6f)) continue;  // coincident feature points: no wall between them
    const float d = (f.squaredDistances[index] - d1Squared) / (2.0f * length);
    if (d < wallDistance) {
      wallDistance = d;
      awayFromWall = between / length;
    }
  }
  if (wallDistance >= kFurrowHalfWidth) return result;
  // b(t) = (1 - t^2)^2, db/dt = -4 t (1 - t^2); t = d / w, dd/dq = awayFromWall.
  const float t = std::max(wallDistance, 0.0f) / kFurrowHalfWidth;
  const float oneMinusT2 = 1.0f - t * t;
  result.height = -depth * oneMinusT2 * oneMinusT2;
  const float dbdt = -4.0f * t * oneMinusT2;
  result.gradient = (-depth * dbdt / (kFurrowHalfWidth * scale)) * awayFromWall;  // chain rule: dq/dp = 1 / scale
  return result;
}

}  // namespace lacrima
