// Points on triangle meshes in surface coordinates; see surface_point.hpp.
#include "lacrima/mesh/surface_point.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

constexpr const char* kSurfacePoint = "surface point";

void triangleCorners(const TriangleMesh& mesh, uint32_t triangle, Vec3& a, Vec3& b, Vec3& c) {
  if (size_t(triangle) >= mesh.triangleCount())
    throw InputError(fmt::format("{}: triangle {} is out of range (the skin has {} triangles)", kSurfacePoint, triangle,
                                 mesh.triangleCount()));
  const uint32_t* idx = &mesh.indices[size_t(triangle) * 3];
  for (int k = 0; k < 3; ++k)
    if (idx[k] >= mesh.positions.size())
      throw InputError(fmt::format("{}: triangle {} has vertex index {} out of range", kSurfacePoint, triangle, idx[k]));
  a = mesh.positions[idx[0]];
  b = mesh.positions[idx[1]];
  c = mesh.positions[idx[2]];
}

// Closest point on triangle abc to p as barycentric weights (Ericson, Real-Time Collision
// Detection, 5.1.5).
Vec3 closestBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return Vec3(1, 0, 0);
  const Vec3 bp = p - b;
  const float d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0f && d4 <= d3) return Vec3(0, 1, 0);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
    const float v = d1 / (d1 - d3);
    return Vec3(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const float d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0f && d5 <= d6) return Vec3(0, 0, 1);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
    const float w = d2 / (d2 - d6);
    return Vec3(1 - w, 0, w);
  }
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
    const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return Vec3(0, 1 - w, w);
  }
  const float sum = va + vb + vc;
  if (!(sum > 0.0f)) return Vec3(1, 0, 0);  // degenerate triangle: its first corner
  const float v = vb / sum, w = vc / sum;
  return Vec3(1 - v - w, v, w);
}

}  // namespace

Vec3 surfacePosition(const TriangleMesh& mesh, const SurfacePoint& point) {
  Vec3 a, b, c;
  triangleCorners(mesh, point.triangle, a, b, c);
  const Vec3& w = point.barycentric;
  if (!w.allFinite() || w.minCoeff() < -1e-4f || std::abs(w.sum() - 1.0f) > 1e-3f)
    throw InputError(fmt::format("{}: barycentric weights ({}, {}, {}) on triangle {} must be >= 0 and sum to 1",
                                 kSurfacePoint, w.x(), w.y(), w.z(), point.triangle));
  return w.x() * a + w.y() * b + w.z() * c;
}

Vec3 triangleNormal(const TriangleMesh& mesh, uint32_t triangle) {
  Vec3 a, b, c;
  triangleCorners(mesh, triangle, a, b, c);
  const Vec3 n = (b - a).cross(c - a);
  const float len = n.norm();
  if (!(len > 0.0f) || !std::isfinite(len))
    throw InputError(fmt::format("{}: triangle {} has no area, so it has no normal", kSurfacePoint,
                                 triangle));
  return n / len;
}

float closestPointOnTriangle(const TriangleMesh& mesh, uint32_t triangle, const Vec3& p, Vec3& barycentric) {
  Vec3 a, b, c;
  triangleCorners(mesh, triangle, a, b, c);
  barycentric = closestBarycentric(p, a, b, c);
  return (barycentric.x() * a + barycentric.y() * b + barycentric.z() * c - p).squaredNorm();
}

SurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Vec3& p) {
  if (mesh.triangleCount() == 0) throw InputError(fmt::format("{}: the mesh has no triangles", kSurfacePoint));
  SurfacePoint best;
  float bestDistance = std::numeric_limits<float>::infinity();
  for (uint32_t t = 0; t < uint32_t(mesh.triangleCount()); ++t) {
    Vec3 w;
    const float d = closestPointOnTriangle(mesh, t, p, w);
    if (d < bestDistance) {
      bestDistance = d;
      best = SurfacePoint{t, w};
    }
  }
  return best;
}

std::optional<SurfacePoint> vertexSurfacePoint(const TriangleMesh& mesh, uint32_t vertex) {
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] == vertex) {
      Vec3 barycentric = Vec3::Zero();
      barycentric[Eigen::Index(i % 3)] = 1.0f;
      return SurfacePoint{uint32_t(i / 3), barycentric};
    }
  return std::nullopt;
}

std::optional<SurfacePoint> surfacePointAtUv(const TriangleMesh& mesh, const Vec2& uv) {
  if (mesh.uvs.size() != mesh.positions.size()) return std::nullopt;
  constexpr double kTolerance = 1e-5;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* idx = &mesh.indices[3 * t];
    const Eigen::Vector2d a = mesh.uvs[idx[0]].cast<double>(), b = mesh.uvs[idx[1]].cast<double>(),
                          c = mesh.uvs[idx[2]].cast<double>(), p = uv.cast<double>();
    const Eigen::Vector2d ab = b - a, ac = c - a, ap = p - a;
    const double area2 = ab.x() * ac.y() - ab.y() * ac.x();  // twice the signed uv area
    if (std::abs(area2) < 1e-14) continue;
    const double v = (ap.x() * ac.y() - ap.y() * ac.x()) / area2;
    const double w = (ab.x() * ap.y() - ab.y() * ap.x()) / area2;
    const double u = 1.0 - v - w;
    if (u < -kTolerance || v < -kTolerance || w < -kTolerance) continue;
    Eigen::Vector3d weights(std::max(u, 0.0), std::max(v, 0.0), std::max(w, 0.0));
    weights /= weights.sum();
    return SurfacePoint{uint32_t(t), weights.cast<float>()};
  }
  return std::nullopt;
}

}  // namespace lacrima
