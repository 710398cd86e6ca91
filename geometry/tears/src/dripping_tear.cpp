// The dripping tear of Lin & Cheng 2013 section 4.1, eq. 7; the interpretation is documented in
// dripping_tear.hpp.
#include <cmath>

#include <fmt/format.h>

#include "lacrima/tears/dripping_tear.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

void requireDrippingTearParameters(const DrippingTearParams& p, float t, int rings, int segments) {
  if (rings < 2 || segments < 3)
    throw InputError(fmt::format("dripping tear: needs at least 2 rings and 3 segments, got {} and {}", rings, segments));
  if (!std::isfinite(t)) throw InputError("dripping tear: the time t must be finite");
  if (!(p.alpha > 0.0f) || !std::isfinite(p.alpha) || !(p.beta > 0.0f) || !std::isfinite(p.beta))
    throw InputError(fmt::format("dripping tear: alpha and beta must be positive and finite, got {} and {}", p.alpha, p.beta));
  if (!std::isfinite(p.lambda)) throw InputError("dripping tear: lambda (fall speed) must be finite");
  if (!(p.minTime > 0.0f) || !std::isfinite(p.minTime))
    throw InputError(fmt::format("dripping tear: minTime must be positive and finite, got {}", p.minTime));
  if (!(p.headAngle > 0.0f) || !(p.headAngle <= 1.5f))
    throw InputError(fmt::format("dripping tear: headAngle must be in (0, 1.5] radians, got {}", p.headAngle));
}

// The tail's scaled profile (header: rho(s), eta(s)) for s in [0, 1].
struct TailProfile {
  float rimRadius, rimHeight, slopeTimesLength, length;

  explicit TailProfile(float headAngle)
      : rimRadius(std::tan(headAngle)),
        rimHeight(std::cos(headAngle)),
        slopeTimesLength((1.0f + std::cos(headAngle)) /
                         (std::sin(headAngle) * std::cos(headAngle) * std::cos(headAngle))),
        length(1.0f + std::cos(headAngle)) {}

  float radius(float s) const { return rimRadius + slopeTimesLength * s - (rimRadius + slopeTimesLength) * s * s; }
  float height(float s) const { return rimHeight - s * length; }
};

// Triangles counter-clockwise seen from outside, as makeEllipsoid: the leading apex is at +z,
// circles go towards -z and v grows counter-clockwise around +z.
void addDropTriangles(TriangleMesh& mesh, int rings, int segments) {
  const uint32_t lead = 0;
  const uint32_t tip = uint32_t(1 + (rings - 1) * segments);
  const auto circleVertex = [segments](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
  const auto add = [&mesh](uint32_t a, uint32_t b, uint32_t c) { mesh.indices.insert(mesh.indices.end(), {a, b, c}); };
  for (int s = 0; s < segments; ++s) {
    add(lead, circleVertex(1, s), circleVertex(1, s + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      add(circleVertex(r, s), circleVertex(r + 1, s), circleVertex(r + 1, s + 1));
      add(circleVertex(r, s), circleVertex(r + 1, s + 1), circleVertex(r, s + 1));
    }
    add(circleVertex(rings - 1, s), tip, circleVertex(rings - 1, s + 1));
  }
}

}  // namespace

Vec3 drippingTearEq7(const DrippingTearParams& p, float u, float v, float t) {
  // Lin & Cheng 2013 eq. 7
  const float x = p.alpha * std::sin(u) * std::cos(v) / (t * std::cos(u));
  const float y = p.alpha * std::sin(u) * std::sin(v) / (t * std::cos(u));
  const float z = p.beta * t * std::cos(u) + p.lambda * t;
  return Vec3(x, y, z);
}

float drippingTearShapeTime(const DrippingTearParams& p, float t) { return std::max(t, p.minTime); }

TriangleMesh makeDrippingTear(const DrippingTearParams& p, float t, int rings, int segments) {
  requireDrippingTearParameters(p, t, rings, segments);
  const float ts = drippingTearShapeTime(p, t);  // shape time: guards the division by t
  const float fall = p.lambda * std::max(t, 0.0f);  // eq. 7's lambda t, with the real time
  const float radial = p.alpha / ts;                 // metres per unit scaled radius
  const float axial = p.beta * ts;                   // metres per unit scaled height
  const int headRings = std::max(1, rings / 3);
  const TailProfile tail(p.headAngle);

  TriangleMesh mesh;
  mesh.name = "dripping tear";
  mesh.positions.reserve(size_t(2 + (rings - 1) * segments));
  mesh.indices.reserve(size_t(6 * segments * (rings - 1)));

  // Leading apex: eq. 7 at u = 0 (x = y = 0, z = beta t + lambda t).
  mesh.positions.emplace_back(0.0f, 0.0f, axial + fall);
  for (int r = 1; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const float v = 2.0f * kPi * float(s) / float(segments);
      if (r <= headRings) {
        // Head: eq. 7 itself at the shape time, with the fall term at the real time.
        const float u = p.headAngle * float(r) / float(headRings);
        const Vec3 q = drippingTearEq7(p, u, v, ts);
        mesh.positions.emplace_back(q.x(), q.y(), axial * std::cos(u) + fall);
      } else {
        const float sigma = float(r - headRings) / float(rings - headRings);
        const float rho = radial * tail.radius(sigma);
        mesh.positions.emplace_back(rho * std::cos(v), rho * std::sin(v), axial * tail.height(sigma) + fall);
      }
    }
  }
  // Trailing tip: eq. 7's other pole, u = pi (x = y = 0, z = -beta t + lambda t).
  mesh.positions.emplace_back(0.0f, 0.0f, -axial + fall);

  addDropTriangles(mesh, rings, segments);
  computeSmoothNormals(mesh, /*weldByPosition=*/false);
  return mesh;
}

void placeDrippingTear(TriangleMesh& mesh, const Vec3& startPoint, const Vec3& gravity) {
  const float g = gravity.norm();
  if (!(g > 0.0f) || !std::isfinite(g)) throw InputError("dripping tear: gravity must be a finite non-zero direction");
  if (!startPoint.allFinite()) throw InputError("dripping tear: the start point must be finite");
  Affine3 transform = Affine3::Identity();
  transform.translate(startPoint);
  transform.rotate(Eigen::Quaternionf::FromTwoVectors(Vec3::UnitZ(), gravity / g).toRotationMatrix());
  transformMesh(mesh, transform);
}

}  // namespace lacrima
