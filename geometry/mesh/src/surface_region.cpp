// Extracting the region of a mesh around a polyline; see surface_region.hpp.
#include "lacrima/mesh/surface_region.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

// Distance from p to the segment ab (a point when a == b), in double so that the bounding-sphere
// test below is not decided by float rounding.
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double f = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + f * ab)).norm();
}

double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& polyline) {
  if (polyline.size() == 1) return (p - polyline[0]).norm();
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < polyline.size(); ++i) best = std::min(best, distanceToSegment(p, polyline[i], polyline[i + 1]));
  return best;
}

}  // namespace

SurfacePoint SurfaceRegion::toFull(const SurfacePoint& point) const {
  if (size_t(point.triangle) >= fullTriangles.size())
    throw InputError(fmt::format("surface region: triangle {} is out of range (the region has {} triangles)",
                                 point.triangle, fullTriangles.size()));
  return SurfacePoint{fullTriangles[point.triangle], point.barycentric};
}

std::optional<SurfacePoint> SurfaceRegion::fromFull(const SurfacePoint& point) const {
  const auto it = std::lower_bound(fullTriangles.begin(), fullTriangles.end(), point.triangle);
  if (it == fullTriangles.end() || *it != point.triangle) return std::nullopt;
  return SurfacePoint{uint32_t(it - fullTriangles.begin()), point.barycentric};
}

SurfaceRegion extractSurfaceRegion(const TriangleMesh& mesh, const std::vector<Vec3>& polyline, float radius) {
  if (polyline.empty()) throw InputError("surface region: the polyline has no points");
  if (!(radius >= 0.0f) || !std::isfinite(radius))
    throw InputError(fmt::format("surface region: radius {} must be finite and >= 0", radius));
  std::vector<Eigen::Vector3d> line;
  for (const Vec3& p : polyline) line.push_back(p.cast<double>());
  // Slack for the float rounding of closestSurfacePoint's distances (ties must all be kept).
  const double reach = double(radius) * (1.0 + 1e-4) + 1e-7;

  SurfaceRegion region;
  region.mesh.name = mesh.name;
  const bool hasNormals = mesh.normals.size() == mesh.positions.size();
  const bool hasUvs = mesh.uvs.size() == mesh.positions.size();
  std::vector<uint32_t> regionVertex(mesh.positions.size(), UINT32_MAX);
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    for (int k = 0; k < 3; ++k)
      if (v[k] >= mesh.positions.size())
        throw InputError(fmt::format("surface region: triangle {} has vertex index {} out of range", t, v[k]));
    const Eigen::Vector3d a = mesh.positions[v[0]].cast<double>(), b = mesh.positions[v[1]].cast<double>(),
                          c = mesh.positions[v[2]].cast<double>();
    const Eigen::Vector3d centre = (a + b + c) / 3.0;
    const double boundingRadius = std::max({(a - centre).norm(), (b - centre).norm(), (c - centre).norm()});
    if (!(distanceToPolyline(centre, line) <= reach + boundingRadius)) continue;
    for (int k = 0; k < 3; ++k) {
      uint32_t& r = regionVertex[v[k]];
      if (r == UINT32_MAX) {
        r = uint32_t(region.mesh.positions.size());
        region.mesh.positions.push_back(mesh.positions[v[k]]);
        if (hasNormals) region.mesh.normals.push_back(mesh.normals[v[k]]);
        if (hasUvs) region.mesh.uvs.push_back(mesh.uvs[v[k]]);
      }
      region.mesh.indices.push_back(r);
    }
    region.fullTriangles.push_back(uint32_t(t));
  }
  return region;
}

float stripRegionRadius(const std::vector<Vec3>& polyline, float width) {
  float longest = 0.0f;
  for (size_t i = 0; i + 1 < polyline.size(); ++i) longest = std::max(longest, (polyline[i + 1] - polyline[i]).norm());
  return (width + 0.5f * longest) * 1.001f;
}

}  // namespace lacrima
