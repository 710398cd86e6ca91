// The water mesh of a rivulet on the skin; see liquid_rivulet_mesh.hpp.
#include "lacrima/liquid/liquid_rivulet_mesh.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "lacrima/base/error.hpp"

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

// The cross-section for a unit half-width and height, counter-clockwise about t: the water's top
// (the parabola, over from y = +1 to -1) and its base (back from -1 to +1). The edges are in both:
// the surface turns sharply there (by the contact angle plus 90 degrees), so each side keeps its
// own vertices and normals, and the two meet edge to edge (closed once coincident vertices are
// welded, as the renderer's openness check does).
struct Section {
  std::vector<Vec2> top, base;
};

Section unitSection(const LiquidRivuletResolution& r) {
  Section section;
  for (int k = 0; k <= r.across; ++k) {
    const float y = 1.0f - 2.0f * float(k) / float(r.across);
    section.top.emplace_back(y, 1.0f - y * y);
  }
  for (int k = 0; k <= r.baseAcross; ++k) section.base.emplace_back(-1.0f + 2.0f * float(k) / float(r.baseAcross), 0.0f);
  return section;
}

}  // namespace

TriangleMesh makeLiquidRivuletMesh(const std::vector<LiquidRivuletStation>& stations, float baseOffset,
                                   const LiquidRivuletResolution& resolution) {
  validate(stations, baseOffset, resolution);
  const Section section = unitSection(resolution);
  TriangleMesh mesh;
  mesh.name = "liquid rivulet";
  // The sweep of one side of the section (top or base) as rings down the rivulet, closed at both
  // ends by a tip: the ends' rings shrink as an ellipsoid's, cos(phi) across and up at sin(phi)
  // half-widths beyond the end station.
  auto sweep = [&](const std::vector<Vec2>& side) {
    auto addVertex = [&](const LiquidRivuletStation& station, float offset, float scale, const Vec2& p) {
      const Frame3 f = frameOf(station);
      const float y = scale * station.halfWidth * p.x();
      const float z = baseOffset + scale * station.height * p.y();
      mesh.positions.push_back(station.contact + offset * f.t + y * f.w + z * f.n);
      return uint32_t(mesh.positions.size() - 1);
    };
    auto addRing = [&](const LiquidRivuletStation& station, float offset, float scale) {
      const uint32_t first = uint32_t(mesh.positions.size());
      for (const Vec2& p : side) addVertex(station, offset, scale, p);
      return first;
    };
    const LiquidRivuletStation& head = stations.front();
    const LiquidRivuletStation& tail = stations.back();
    const int caps = resolution.capRings;
    const float half = 0.5f * float(std::numbers::pi);
    std::vector<uint32_t> rings;
    const uint32_t startTip = addVertex(head, -head.halfWidth, 0.0f, Vec2::Zero());
    for (int j = caps; j >= 1; --j) {
      const float phi = half * float(j) / float(caps + 1);
      rings.push_back(addRing(head, -head.halfWidth * std::sin(phi), std::cos(phi)));
    }
    for (const LiquidRivuletStation& station : stations) rings.push_back(addRing(station, 0.0f, 1.0f));
    for (int j = 1; j <= caps; ++j) {
      const float phi = half * float(j) / float(caps + 1);
      rings.push_back(addRing(tail, tail.halfWidth * std::sin(phi), std::cos(phi)));
    }
    const uint32_t endTip = addVertex(tail, tail.halfWidth, 0.0f, Vec2::Zero());
    const uint32_t segments = uint32_t(side.size() - 1);
    for (uint32_t k = 0; k < segments; ++k)
      mesh.indices.insert(mesh.indices.end(), {startTip, rings[0] + k + 1, rings[0] + k});
    for (size_t r = 0; r + 1 < rings.size(); ++r)
      for (uint32_t k = 0; k < segments; ++k) {
        const uint32_t a = rings[r] + k, b = rings[r + 1] + k;
        mesh.indices.insert(mesh.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
      }
    for (uint32_t k = 0; k < segments; ++k)
      mesh.indices.insert(mesh.indices.end(), {endTip, rings.back() + k, rings.back() + k + 1});
  };
  sweep(section.top);
  sweep(section.base);
  // Per side: the top's normals from the top's triangles only, the base's from the base's.
  computeSmoothNormals(mesh, false);
  return mesh;
}

}  // namespace lacrima
