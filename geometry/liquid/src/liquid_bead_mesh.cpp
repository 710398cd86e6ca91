// The water mesh of a bead draped over the skin; see liquid_bead_mesh.hpp.
#include "lacrima/liquid/liquid_bead_mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "lacrima/base/bucket_lists.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

void validate(const LiquidBeadPlacement& p, const LiquidBeadResolution& r) {
  const bool finite = p.contact.allFinite() && p.normal.allFinite() && p.along.allFinite();
  if (!finite || !(p.normal.norm() > 0.0f)) throw InputError("liquid bead: contact, normal and along must be finite, normal non-zero");
  if (!(p.halfLength > 0.0f) || !(p.halfWidth > 0.0f) || !(p.height > 0.0f) || !std::isfinite(p.halfLength) ||
      !std::isfinite(p.halfWidth) || !std::isfinite(p.height))
    throw InputError(fmt::format("liquid bead: halfLength {}, halfWidth {} and height {} must be finite and positive",
                                 p.halfLength, p.halfWidth, p.height));
  if (!(p.contactAngle > 0.0f && p.contactAngle < float(std::numbers::pi)))
    throw InputError(fmt::format("liquid bead: contact angle {} is not in (0, pi)", p.contactAngle));
  if (!std::isfinite(p.baseOffset) || !(p.baseOffset > -p.height))
    throw InputError(fmt::format("liquid bead: baseOffset {} must be finite and above -height ({})", p.baseOffset,
                                 -p.height));
  if (r.domeRings < 2 || r.baseRings < 1 || r.segments < 3)
    throw InputError(fmt::format("liquid bead: resolution {} dome rings, {} base rings, {} segments is too coarse",
                                 r.domeRings, r.baseRings, r.segments));
}

// The skin triangles near the bead that face the bead's side, as double-precision corners, and
// their shadows on the bead's base plane (along its normal) binned in a grid: a vertex's ray along
// the normal can only hit a triangle whose shadow's box holds the ray's foot, so it tests the
// triangles of its own bin alone (each bin lists them in patch order: the same hit wins a tie).
// Testing every patch triangle from every bead vertex was the default shot's second-largest
// cost of a frame's geometry after the wet film.
struct SkinPatch {
  std::vector<Vec3d> corners;  // three per triangle
  Vec3d centre, u, w;          // the base plane: a point and two axes
  double x0 = 0.0, y0 = 0.0, binSize = 1.0;
  int binsX = 1, binsY = 1;
  BucketLists trianglesByBin;

  // A point's coordinates in the base plane.
  Eigen::Vector2d planar(const Vec3d& p) const { return {(p - centre).dot(u), (p - centre).dot(w)}; }
  int binX(double x) const { return std::clamp(int((x - x0) / binSize), 0, binsX - 1); }
  int binY(double y) const { return std::clamp(int((y - y0) / binSize), 0, binsY - 1); }
};

// The shadow box of each triangle, grown by kShadowMargin: the ray test accepts hits up to 1e-9 of
// the triangle's size outside it, far below the margin.
constexpr double kShadowMargin = 1e-6;  // metres

void binShadows(SkinPatch& patch) {
  const size_t triangles = patch.corners.size() / 3;
  std::vector<Eigen::AlignedBox2d> shadows(triangles);
  Eigen::AlignedBox2d all;
  for (size_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) shadows[t].extend(patch.planar(patch.corners[3 * t + k]));
    shadows[t].min().array() -= kShadowMargin;
    shadows[t].max().array() += kShadowMargin;
    all.extend(shadows[t]);
  }
  if (triangles == 0) return;
  // About one triangle per bin, at most 128 bins a side.
  const int side = std::clamp(int(std::sqrt(double(triangles))), 1, 128);
  patch.x0 = all.min().x(), patch.y0 = all.min().y();
  patch.binSize = std::max(all.sizes().maxCoeff() / double(side), 1e-12);
  patch.binsX = std::clamp(int(all.sizes().x() / patch.binSize) + 1, 1, side + 1);
  patch.binsY = std::clamp(int(all.sizes().y() / patch.binSize) + 1, 1, side + 1);
  patch.trianglesByBin = makeBucketLists(size_t(patch.binsX) * size_t(patch.binsY), [&](auto visit) {
    for (size_t t = 0; t < triangles; ++t)
      for (int y = patch.binY(shadows[t].min().y()); y <= patch.binY(shadows[t].max().y()); ++y)
        for (int x = patch.binX(shadows[t].min().x()); x <= patch.binX(shadows[t].max().x()); ++x)
          visit(uint32_t(t), size_t(y) * size_t(patch.binsX) + size_t(x));
  });
}

SkinPatch nearbySkin(const TriangleMesh& skin, const Vec3d& centre, const Vec3d& normal, const Vec3d& u, const Vec3d& w,
                     double reach) {
  SkinPatch patch;
  const double reach2 = reach * reach;
  for (size_t t = 0; t + 2 < skin.indices.size(); t += 3) {
    const Vec3d a = skin.positions[skin.indices[t]].cast<double>(), b = skin.positions[skin.indices[t + 1]].cast<double>(),
                c = skin.positions[skin.indices[t + 2]].cast<double>();
    if ((a - centre).squaredNorm() > reach2 && (b - centre).squaredNorm() > reach2 && (c - centre).squaredNorm() > reach2)
      continue;
    if ((b - a).cross(c - a).dot(normal) <= 0.0) continue;  // the other side of a fold: not under the bead
    patch.corners.insert(patch.corners.end(), {a, b, c});
  }
  patch.centre = centre, patch.u = u, patch.w = w;
  binShadows(patch);
  return patch;
}

// Signed distance along `dir` (the base plane's normal) from `origin` to the skin hit nearest to it
// (Moller-Trumbore), if any.
std::optional<double> skinHeight(const SkinPatch& patch, const Vec3d& origin, const Vec3d& dir) {
  std::optional<double> best;
  if (patch.trianglesByBin.items.empty()) return best;
  const Eigen::Vector2d foot = patch.planar(origin);
  const size_t bin = size_t(patch.binY(foot.y())) * size_t(patch.binsX) + size_t(patch.binX(foot.x()));
  for (const uint32_t triangle : patch.trianglesByBin.in(bin)) {
    const size_t i = 3 * size_t(triangle);
    const Vec3d e1 = patch.corners[i + 1] - patch.corners[i], e2 = patch.corners[i + 2] - patch.corners[i];
    const Vec3d p = dir.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-30) continue;
    const Vec3d s = origin - patch.corners[i];
    const double u = s.dot(p) / det;
    if (u < -1e-9 || u > 1.0 + 1e-9) continue;
    const Vec3d q = s.cross(e1);
    const double v = dir.dot(q) / det;
    if (v < -1e-9 || u + v > 1.0 + 1e-9) continue;
    const double h = e2.dot(q) / det;
    if (!best || std::abs(h) < std::abs(*best)) best = h;
  }
  return best;
}

}  // namespace

TriangleMesh makeLiquidBeadMesh(const TriangleMesh& skin, const LiquidBeadPlacement& placement,
                                const LiquidBeadResolution& resolution) {
  validate(placement, resolution);
  const Vec3d n = placement.normal.cast<double>().normalized();
  Vec3d u = placement.along.cast<double>() - placement.along.cast<double>().dot(n) * n;
  if (!(u.norm() > 1e-9)) throw InputError("liquid bead: the long axis is parallel to the skin normal");
  u.normalize();
  const Vec3d w = n.cross(u);
  const Vec3d centre = placement.contact.cast<double>();
  const double theta = placement.contactAngle;
  const double rho = 1.0 / std::sin(theta), apexHeight = rho * (1.0 - std::cos(theta));
  const double footprint = std::max(placement.halfLength, placement.halfWidth) * std::max(rho, 1.0);
  const SkinPatch patch = nearbySkin(skin, centre, n, u, w, 2.0 * footprint + 2.0 * placement.height);

  TriangleMesh mesh;
  mesh.name = "liquid bead";
  // A vertex at unit-cap radius r, angle phi and unit height z (0 on the base, 1 at the apex).
  auto addVertex = [&](double r, double phi, double z) {
    const double x = placement.halfLength * r * std::cos(phi), y = placement.halfWidth * r * std::sin(phi);
    const Vec3d inPlane = centre + x * u + y * w;
    const double lift = skinHeight(patch, inPlane, n).value_or(0.0) + placement.baseOffset + placement.height * z;
    mesh.positions.push_back((inPlane + lift * n).cast<float>());
    return uint32_t(mesh.positions.size() - 1);
  };
  const int segments = resolution.segments;
  auto phiOf = [segments](int k) { return 2.0 * std::numbers::pi * double(k % segments) / double(segments); };

  // Dome: apex, then rings down to the contact line (ring domeRings is the contact line, z = 0).
  const uint32_t apex = addVertex(0.0, 0.0, 1.0);
  std::vector<uint32_t> ringStart;
  for (int i = 1; i <= resolution.domeRings; ++i) {
    const double psi = theta * double(i) / double(resolution.domeRings);
    const double z = i == resolution.domeRings ? 0.0 : rho * (std::cos(psi) - std::cos(theta)) / apexHeight;
    ringStart.push_back(uint32_t(mesh.positions.size()));
    for (int k = 0; k < segments; ++k) addVertex(rho * std::sin(psi), phiOf(k), z);
  }
  // Base: the contact line again, then rings inwards and the centre (all at z = 0: on the skin).
  // The surface turns sharply at the contact line (by the contact angle), so the base has its own
  // copy of that ring, bitwise at the same places (the mesh is closed once coincident vertices are
  // welded, as the renderer's openness check does), and the dome's and the base's normals there
  // are each their own side's: shared vertices would average them into a rim of normals tilted
  // halfway between the two, and water refracts by its shading normal.
  const uint32_t contactRing = ringStart.back();
  ringStart.push_back(uint32_t(mesh.positions.size()));
  for (int k = 0; k < segments; ++k) mesh.positions.push_back(mesh.positions[contactRing + uint32_t(k)]);
  for (int j = resolution.baseRings - 1; j >= 1; --j) {
    ringStart.push_back(uint32_t(mesh.positions.size()));
    for (int k = 0; k < segments; ++k) addVertex(double(j) / double(resolution.baseRings), phiOf(k), 0.0);
  }
  const uint32_t baseCentre = addVertex(0.0, 0.0, 0.0);

  auto at = [&](size_t ring, int k) { return ringStart[ring] + uint32_t(k % segments); };
  // Seen from outside (+n above the dome), increasing phi runs counter-clockwise about n.
  for (int k = 0; k < segments; ++k) mesh.indices.insert(mesh.indices.end(), {apex, at(0, k), at(0, k + 1)});
  const size_t contactRingIndex = size_t(resolution.domeRings) - 1;  // its copy follows it: no strip between them
  for (size_t r = 0; r + 1 < ringStart.size(); ++r) {
    if (r == contactRingIndex) continue;
    for (int k = 0; k < segments; ++k)
      mesh.indices.insert(mesh.indices.end(), {at(r, k), at(r + 1, k), at(r + 1, k + 1), at(r, k), at(r + 1, k + 1),
                                               at(r, k + 1)});
  }
  const size_t last = ringStart.size() - 1;
  for (int k = 0; k < segments; ++k) mesh.indices.insert(mesh.indices.end(), {baseCentre, at(last, k + 1), at(last, k)});
  computeSmoothNormals(mesh, false);
  return mesh;
}

}  // namespace lacrima
