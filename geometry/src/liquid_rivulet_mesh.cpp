// The water mesh of a rivulet on the skin; see liquid_rivulet_mesh.hpp.
#include "lacrima/geometry/liquid_rivulet_mesh.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "lacrima/geometry/error.hpp"

namespace lacrima {

namespace {

void validate(const std::vector<LiquidRivuletStation>& stations, float baseOffset, const LiquidRivuletResolution& r) {
  if (stations.empty()) throw InputError("liquid rivulet: no stations");
  if (r.across < 2 || r.baseAcross < 1 || r.capRings < 1)
    throw InputError(fmt::format("liquid rivulet: resolution {} across, {} base, {} cap rings is too coarse", r.across,
                                 r.baseAcross, r.capRings));
  for (size_t i = 0; i < stations.size(); ++i) {
    const LiquidRivuletStation& s = stations[i];
    if (!s.contact.allFinite() || !s.normal.allFinite() || !s.along.allFinite() || !(s.normal.norm() > 0.0f))
      throw InputError(fmt::format("liquid rivulet: station {} needs a finite contact, along and non-zero normal", i));
    const Vec3 n = s.normal.normalized();
    if (!((s.along - s.along.dot(n) * n).norm() > 1e-6f * s.along.norm()))
      throw InputError(fmt::format("liquid rivulet: station {}'s direction along is parallel to its normal", i));
    if (!(std::isfinite(s.halfWidth) && s.halfWidth > 0.0f && std::isfinite(s.height) && s.height > 0.0f))
      throw InputError(fmt::format("liquid rivulet: station {} has half-width {} and height {}; both must be positive",
                                   i, s.halfWidth, s.height));
    if (!std::isfinite(baseOffset) || !(baseOffset > -s.height))
      throw InputError(fmt::format("liquid rivulet: baseOffset {} must be finite and above -height ({}) at station {}",
                                   baseOffset, -s.height, i));
  }
}

// A station's frame: t down the rivulet, w across (w x n = t), n out of the skin.
struct Frame3 {
  Vec3 t, w, n;
};

Frame3 frameOf(const LiquidRivuletStation& s) {
  Frame3 f;
  f.n = s.normal.normalized();
  f.t = (s.along - s.along.dot(f.n) * f.n).normalized();
  f.w = f.n.cross(f.t);
  return f;
}

// The cross-section as (y, z) per ring vertex, counter-clockwise about t: over the top from +1 to
// -1 (the parabola), then back along the base (its inner points), all for a unit half-width and height.
std::vector<Vec2> unitSection(const LiquidRivuletResolution& r) {
  std::vector<Vec2> section;
  for (int k = 0; k <= r.across; ++k) {
    const float y = 1.0f - 2.0f * float(k) / float(r.across);
    section.emplace_back(y, 1.0f - y * y);
  }
  for (int k = 1; k < r.baseAcross; ++k) section.emplace_back(-1.0f + 2.0f * float(k) / float(r.baseAcross), 0.0f);
  return section;
}

}  // namespace

TriangleMesh makeLiquidRivuletMesh(const std::vector<LiquidRivuletStation>& stations, float baseOffset,
                                   const LiquidRivuletResolution& resolution) {
  validate(stations, baseOffset, resolution);
  const std::vector<Vec2> section = unitSection(resolution);
  const uint32_t ringSize = uint32_t(section.size());
  TriangleMesh mesh;
  mesh.name = "liquid rivulet";
  // A ring at `station`, moved by `offset` along its t and scaled by `scale` across and up.
  auto addRing = [&](const LiquidRivuletStation& station, float offset, float scale) {
    const Frame3 f = frameOf(station);
    const uint32_t first = uint32_t(mesh.positions.size());
    for (const Vec2& p : section) {
      const float y = scale * station.halfWidth * p.x();
      const float z = baseOffset + scale * station.height * p.y();
      mesh.positions.push_back(station.contact + offset * f.t + y * f.w + z * f.n);
    }
    return first;
  };
  auto addPoint = [&](const LiquidRivuletStation& station, float offset) {
    const Frame3 f = frameOf(station);
    mesh.positions.push_back(station.contact + offset * f.t + baseOffset * f.n);
    return uint32_t(mesh.positions.size() - 1);
  };
  // Rings in order down the rivulet: the start cap's (from its tip), the stations', the end cap's.
  std::vector<uint32_t> rings;
  const int caps = resolution.capRings;
  const float half = 0.5f * float(std::numbers::pi);
  const LiquidRivuletStation& head = stations.front();
  const LiquidRivuletStation& tail = stations.back();
  const uint32_t startTip = addPoint(head, -head.halfWidth);
  for (int j = caps; j >= 1; --j) {
    const float phi = half * float(j) / float(caps + 1);
    rings.push_back(addRing(head, -head.halfWidth * std::sin(phi), std::cos(phi)));
  }
  for (const LiquidRivuletStation& station : stations) rings.push_back(addRing(station, 0.0f, 1.0f));
  for (int j = 1; j <= caps; ++j) {
    const float phi = half * float(j) / float(caps + 1);
    rings.push_back(addRing(tail, tail.halfWidth * std::sin(phi), std::cos(phi)));
  }
  const uint32_t endTip = addPoint(tail, tail.halfWidth);

  auto at = [&](size_t ring, uint32_t k) { return rings[ring] + k % ringSize; };
  for (uint32_t k = 0; k < ringSize; ++k) mesh.indices.insert(mesh.indices.end(), {startTip, at(0, k + 1), at(0, k)});
  for (size_t r = 0; r + 1 < rings.size(); ++r)
    for (uint32_t k = 0; k < ringSize; ++k)
      mesh.indices.insert(mesh.indices.end(),
                          {at(r, k), at(r, k + 1), at(r + 1, k + 1), at(r, k), at(r + 1, k + 1), at(r + 1, k)});
  const size_t last = rings.size() - 1;
  for (uint32_t k = 0; k < ringSize; ++k) mesh.indices.insert(mesh.indices.end(), {endTip, at(last, k), at(last, k + 1)});
  computeSmoothNormals(mesh, false);
  return mesh;
}

}  // namespace lacrima
