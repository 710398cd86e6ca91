// Procedural pores; see pores.hpp for the field and its sources.
#include "lacrima/materials/pores.hpp"

#include <cmath>

#include "lacrima/base/hash.hpp"
#include "lattice_cell.hpp"

namespace lacrima {

namespace {

constexpr uint64_t kPoreSeed = 0x706f726573ULL;  // "pores": decorrelates from other hashed streams

// The pore centre of lattice cell (i, j, k), in lattice units: the cell corner plus a hashed jitter.
Vec3 poreCentre(int64_t i, int64_t j, int64_t k) {
  const uint64_t cell = hashCombine(hashCombine(hashCombine(kPoreSeed, uint64_t(i)), uint64_t(j)), uint64_t(k));
  return Vec3(float(i) + uint64ToUnitFloat(hashCombine(cell, 0)), float(j) + uint64ToUnitFloat(hashCombine(cell, 1)),
              float(k) + uint64ToUnitFloat(hashCombine(cell, 2)));
}

// The neighbour cells along one axis that can hold a pore reaching a point at `local` (its
// coordinate from the cell corner, in [0, 1]): a centre of cell -1 lies below 0 and reaches less
// than kPoreRadius above it, a centre of cell +1 lies at or above 1 and reaches less than
// kPoreRadius below it; cell 0 always. Since kPoreRadius < 1/2, never both neighbours, so at most
// 8 of the 27 surrounding cells are visited (the others add nothing). The margin covers the
// rounding of the centres' float coordinates.
struct AxisCells {
  int first, last;
};
AxisCells cellsReaching(float local) {
  constexpr float kMargin = 1e-3f;
  return {local < kPoreRadius + kMargin ? -1 : 0, local > 1.0f - kPoreRadius - kMargin ? 1 : 0};
}
static_assert(kPoreRadius < 0.5f, "cellsReaching assumes a pore reaches at most one neighbour per axis");

}  // namespace

PoreHeight poreHeight(const Vec3& p, float scale, float depth) {
  PoreHeight result;
  if (depth <= 0.0f) return result;
  const LatticeCell cell = latticeCellOf(p, scale);
  const int64_t ci = cell.i, cj = cell.j, ck = cell.k;
  const Vec3& local = cell.local;
  constexpr float invR2 = 1.0f / (kPoreRadius * kPoreRadius);
  float sumB = 0.0f;
  Vec3 sumGrad = Vec3::Zero();
  // A centre lies in its own cell and R < 1, so only the surrounding cells can reach p; of those,
  // only the ones cellsReaching names (the same sum in the same order as over all 27).
  const AxisCells cx = cellsReaching(local.x()), cy = cellsReaching(local.y()), cz = cellsReaching(local.z());
  for (int64_t di = cx.first; di <= cx.last; ++di) {
    for (int64_t dj = cy.first; dj <= cy.last; ++dj) {
      for (int64_t dk = cz.first; dk <= cz.last; ++dk) {
        const Vec3 centre = poreCentre(ci + di, cj + dj, ck + dk) - Vec3(float(ci), float(cj), float(ck));
        const Vec3 d = local - centre;
        const float s = d.squaredNorm() * invR2;
        if (s >= 1.0f) continue;
        // b(s) = (1 - s)^2, db/dq = -2 (1 - s) * 2 d / R^2.
        sumB += (1.0f - s) * (1.0f - s);
        sumGrad += (-4.0f * (1.0f - s) * invR2) * d;
      }
    }
  }
  result.height = -depth * sumB;
  result.gradient = (-depth / scale) * sumGrad;  // chain rule: dq/dp = 1 / scale
  return result;
}

Vec3 perturbNormalByPores(const Vec3& p, const Vec3& ns, const Vec3& ng, float scale, float depth) {
  if (depth <= 0.0f) return ns;
  return tiltNormalBySlope(poreHeight(p, scale, depth).gradient, ns, ng);
}

Vec3 tiltNormalBySlope(const Vec3& g, const Vec3& ns, const Vec3& ng) {
  Vec3 slope = g - g.dot(ns) * ns;  // tangential part: the height field lives over ns's tangent plane
  const float slopeLength = slope.norm();
  if (slopeLength > kMaxPoreSlope) slope *= kMaxPoreSlope / slopeLength;
  const Vec3 tilted = (ns - slope).normalized();  // |ns - slope| >= 1: never degenerate
  if (!tilted.allFinite() || tilted.dot(ng) < kMinPoreCosToGeometric) return ns;
  return tilted;
}

}  // namespace lacrima
