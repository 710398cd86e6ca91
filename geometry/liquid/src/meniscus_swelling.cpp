// The lacrimal meniscus thickening with its volume; see meniscus_swelling.hpp.
#include "lacrima/liquid/meniscus_swelling.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lacrima/base/error.hpp"

namespace lacrima {

std::vector<float> meniscusFalloffWeights(const TriangleMesh& mesh, const Vec3& source, float falloffLength) {
  if (!(falloffLength > 0.0f)) throw InputError(fmt::format("the meniscus falloff length must be positive, got {}", falloffLength));
  std::vector<float> weights(mesh.vertexCount(), 0.0f);
  for (size_t v = 0; v < weights.size(); ++v) {
    const float x2 = (mesh.positions[v] - source).squaredNorm() / (falloffLength * falloffLength);
    if (x2 < 1.0f) weights[v] = (1.0f - x2) * (1.0f - x2);
  }
  return weights;
}

std::vector<double> vertexAreas(const TriangleMesh& mesh) {
  std::vector<double> areas(mesh.vertexCount(), 0.0);
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    const Vec3d a = mesh.positions[v[0]].cast<double>(), b = mesh.positions[v[1]].cast<double>(),
                c = mesh.positions[v[2]].cast<double>();
    const double third = (b - a).cross(c - a).norm() / 6.0;
    for (int k = 0; k < 3; ++k) areas[v[k]] += third;
  }
  return areas;
}

double sweptVolume(const TriangleMesh& before, const TriangleMesh& after) {
  if (before.indices != after.indices || before.vertexCount() != after.vertexCount())
    throw InputError("sweptVolume: the two meshes must share their topology");
  const auto tet = [](const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
    return (b - a).cross(c - a).dot(d - a) / 6.0;
  };
  double volume = 0.0;
  for (size_t t = 0; t < before.triangleCount(); ++t) {
    const uint32_t* v = &before.indices[3 * t];
    const Vec3d a = before.positions[v[0]].cast<double>(), b = before.positions[v[1]].cast<double>(),
                c = before.positions[v[2]].cast<double>();
    const Vec3d a2 = after.positions[v[0]].cast<double>(), b2 = after.positions[v[1]].cast<double>(),
                c2 = after.positions[v[2]].cast<double>();
    volume += tet(a, b, c, c2) + tet(a, b, c2, b2) + tet(a, b2, c2, a2);
  }
  return volume;
}

namespace {

// `mesh` with every vertex moved by peak w_v along `normals`.
TriangleMesh thickened(const TriangleMesh& mesh, const std::vector<Vec3>& normals, const std::vector<float>& weights,
                       double peak) {
  TriangleMesh out = mesh;
  for (size_t v = 0; v < weights.size(); ++v)
    if (weights[v] > 0.0f) out.positions[v] += float(peak * double(weights[v])) * normals[v];
  return out;
}

// h0 with sweptVolume = volume: secant iterations from the first-order estimate (the swept volume is
// a cubic in h0, smooth and increasing for the thicknesses of a meniscus).
double peakThickness(const TriangleMesh& mesh, const std::vector<Vec3>& normals, const std::vector<float>& weights,
                     double volume, double firstOrder) {
  double h0 = 0.0, f0 = -volume;
  double h1 = firstOrder, f1 = sweptVolume(mesh, thickened(mesh, normals, weights, h1)) - volume;
  for (int i = 0; i < 30 && std::abs(f1) > 1e-6 * volume && f1 != f0; ++i) {
    const double h2 = h1 - f1 * (h1 - h0) / (f1 - f0);
    h0 = h1;
    f0 = f1;
    h1 = h2;
    f1 = sweptVolume(mesh, thickened(mesh, normals, weights, h1)) - volume;
  }
  return h1;
}

}  // namespace

double swellMeniscus(TriangleMesh& mesh, const std::vector<float>& weights, double volume) {
  if (!(volume >= 0.0) || !std::isfinite(volume))
    throw InputError(fmt::format("the meniscus volume must be finite and >= 0, got {}", volume));
  if (weights.size() != mesh.vertexCount())
    throw InputError(fmt::format("{} meniscus weights for {} vertices", weights.size(), mesh.vertexCount()));
  const std::vector<double> areas = vertexAreas(mesh);
  double weightedArea = 0.0;
  for (size_t v = 0; v < weights.size(); ++v) weightedArea += areas[v] * double(weights[v]);
  if (volume == 0.0 || !(weightedArea > 0.0)) return 0.0;
  TriangleMesh withNormals = mesh;
  if (withNormals.normals.size() != withNormals.positions.size()) computeSmoothNormals(withNormals);
  const double peak = peakThickness(mesh, withNormals.normals, weights, volume, volume / weightedArea);
  const bool hadNormals = mesh.normals.size() == mesh.positions.size();
  mesh = thickened(mesh, withNormals.normals, weights, peak);
  // New normals around the moved vertices only: the rest of the strip keeps its normals bitwise.
  TriangleMesh renormalised = mesh;
  computeSmoothNormals(renormalised);
  if (!hadNormals) {
    mesh.normals = std::move(renormalised.normals);
    return peak;
  }
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    if (weights[v[0]] > 0.0f || weights[v[1]] > 0.0f || weights[v[2]] > 0.0f)
      for (int k = 0; k < 3; ++k) mesh.normals[v[k]] = renormalised.normals[v[k]];
  }
  return peak;
}

}  // namespace lacrima
