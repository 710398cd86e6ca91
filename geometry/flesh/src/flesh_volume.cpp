// buildFleshVolume and the node anchors (flesh_volume.hpp).
#include "lacrima/flesh/flesh_volume.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "lacrima/mesh/closest_point_grid.hpp"
#include "lacrima/mesh/sphere_fit.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "tetgen_call.hpp"

namespace lacrima::flesh {

namespace {

Vec3d triangleNormal(const std::vector<Vec3d>& x, const std::array<int, 3>& t) {
  return (x[size_t(t[1])] - x[size_t(t[0])]).cross(x[size_t(t[2])] - x[size_t(t[0])]);
}

// The inner surface: the skin shrunk towards a centre c, each point moved `depth` along the ray from
// c (the centre of the sphere fitted to the patch, behind the skin). Shrinking along rays maps
// space outside the ball of radius depth round c one-to-one onto itself with a positive Jacobian,
// so the inner surface can neither fold nor cross itself, however finely the skin is tessellated
// (an offset along vertex normals folds wherever small triangles' normals disagree by more than
// their size over the depth, as on a skin refined along a tear's trail). Where no sphere fits (a
// flat patch) or its centre lies in front of the skin (a hollow), the skin is moved along its mean
// normal instead. The thickness measured along the skin's own normal is depth times the cosine
// between it and the ray: a little thinner where the skin is oblique to the centre.
std::vector<Vec3d> innerSurface(const SkinPatch& patch, double depth) {
  Vec3d centroid = Vec3d::Zero(), meanNormal = Vec3d::Zero();
  for (const Vec3d& p : patch.positions) centroid += p;
  centroid /= double(patch.positions.size());
  for (const auto& t : patch.triangles) meanNormal += triangleNormal(patch.positions, t);
  meanNormal.normalize();
  double extent = 0.0;
  for (const Vec3d& p : patch.positions) extent = std::max(extent, (p - centroid).norm());
  std::optional<Vec3d> center;
  try {
    std::vector<Vec3> points;
    for (const Vec3d& p : patch.positions) points.push_back(p.cast<float>());
    const FittedSphere sphere = fitSphere(points);
    const Vec3d c = sphere.center.cast<double>();
    if (meanNormal.dot(centroid - c) > 0.0 && double(sphere.radius) < 20.0 * extent) center = c;
  } catch (const std::exception&) {
    // Coplanar (or too few) points: no sphere; the mean normal serves.
  }
  std::vector<Vec3d> inner(patch.positions.size());
  for (size_t v = 0; v < inner.size(); ++v) {
    const Vec3d& p = patch.positions[v];
    if (!center) {
      inner[v] = p - depth * meanNormal;
      continue;
    }
    const double distance = (p - *center).norm();
    if (!(distance > 1.5 * depth))
      throw FleshVolumeError(fmt::format(
          "the flesh depth {} m is too deep for the skin's curvature near ({:.4f}, {:.4f}, {:.4f}) m (it lies {:.4f} m "
          "from the centre of the sphere the region's skin fits); give a smaller depth",
          depth, p.x(), p.y(), p.z(), distance));
    inner[v] = p - depth * (p - *center) / distance;
  }
  return inner;
}

// The border edges of the patch, each directed as in its one triangle.
std::vector<std::array<int, 2>> borderEdges(const SkinPatch& patch) {
  std::unordered_set<uint64_t> directed;
  const auto key = [](int a, int b) { return (uint64_t(uint32_t(a)) << 32) | uint32_t(b); };
  for (const auto& t : patch.triangles)
    for (int c = 0; c < 3; ++c) directed.insert(key(t[c], t[(c + 1) % 3]));
  std::vector<std::array<int, 2>> border;
  for (const auto& t : patch.triangles)
    for (int c = 0; c < 3; ++c)
      if (!directed.count(key(t[(c + 1) % 3], t[c]))) border.push_back({t[c], t[(c + 1) % 3]});
  return border;
}

// Facet markers of the shell, which TetGen passes on to the nodes it puts on them.
enum ShellMarker : int { kSkinFacet = 1, kInnerFacet = 2, kWallFacet = 3 };

struct Shell {
  std::vector<Vec3d> points;  // the skin's vertices, then the inner surface's
  std::vector<std::array<int, 3>> facets;
  std::vector<int> markers;   // ShellMarker per facet
};

Shell closedShell(const SkinPatch& patch, const std::vector<Vec3d>& inner, const std::vector<std::array<int, 2>>& border) {
  Shell shell;
  const int n = int(patch.positions.size());
  shell.points = patch.positions;
  shell.points.insert(shell.points.end(), inner.begin(), inner.end());
  for (const auto& t : patch.triangles) {
    shell.facets.push_back(t);
    shell.markers.push_back(kSkinFacet);
    shell.facets.push_back({t[0] + n, t[2] + n, t[1] + n});
    shell.markers.push_back(kInnerFacet);
  }
  for (const auto& [a, b] : border) {
    shell.facets.push_back({b, a, a + n});
    shell.facets.push_back({b, a + n, b + n});
    shell.markers.insert(shell.markers.end(), {kWallFacet, kWallFacet});
  }
  return shell;
}

std::string tetgenSwitches(const FleshVolumeSettings& s) {
  // p: a piecewise linear complex; q: radius-edge bound; a: volume bound; Q: quiet. The boundary's
  // triangles may be split (no -Y): kept whole, the skin's long thin triangles left slivers under
  // them that the rig's pose turned inside out (9 of 3,616 on the default shot's cheeks; 1 of
  // 21,154 split), and a tetrahedron whose rest shape is inverted keeps an old one, which pulls the
  // flesh off the rig's pose (0.15 mm kept, 0.003 mm split).
  return fmt::format("pq{:.4f}a{:.18f}Q", s.radiusEdgeRatio, s.maxTetVolume);
}

TetGenResult runTetGen(const Shell& shell, const FleshVolumeSettings& settings) {
  TetGenResult result = tetrahedralizeInChildProcess(shell.points, shell.facets, shell.markers, tetgenSwitches(settings));
  TetMesh& mesh = result.mesh;
  for (size_t i = 0; i < shell.points.size(); ++i)
    if (i >= mesh.nodes.size() || (mesh.nodes[i] - shell.points[i]).norm() > 1e-12)
      throw FleshVolumeError("TetGen renumbered the skin's vertices (coincident skin and inner points?)");
  for (const Tet& t : mesh.tets)
    for (int corner : t)
      if (corner < 0 || size_t(corner) >= mesh.nodes.size()) throw FleshVolumeError("TetGen's answer names a missing node");
  orientPositively(mesh);
  return result;
}

double distanceToSegment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * d)).norm();
}

// The nodes on the tetrahedral mesh's boundary (on a face that only one tetrahedron has).
std::vector<bool> boundaryNodes(const TetMesh& mesh) {
  std::unordered_map<std::string, int> faceUse;
  static constexpr int kOpposite[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  const auto keyOf = [&](const Tet& t, const int* f) {
    std::array<int, 3> k{t[size_t(f[0])], t[size_t(f[1])], t[size_t(f[2])]};
    std::sort(k.begin(), k.end());
    return std::string(reinterpret_cast<const char*>(k.data()), sizeof k);
  };
  for (const Tet& t : mesh.tets)
    for (const auto& f : kOpposite) ++faceUse[keyOf(t, f)];
  std::vector<bool> onBoundary(mesh.nodes.size(), false);
  for (const Tet& t : mesh.tets)
    for (const auto& f : kOpposite)
      if (faceUse[keyOf(t, f)] == 1)
        for (int c = 0; c < 3; ++c) onBoundary[size_t(t[size_t(f[c])])] = true;
  return onBoundary;
}

// The rig moves the inner surface, the walls and the skin's border (the skull, and the flesh
// outside the region); the simulation moves the rest. Nodes TetGen added are classified by where
// they lie: TetGen marks those inside its facets with the facet's marker but not always those on
// the facets' shared edges, so a boundary node is free only when it lies on the skin (within a
// micrometre) and off the skin's border edges.
std::vector<bool> kinematicNodes(const SkinPatch& patch, const std::vector<std::array<int, 2>>& border,
                                 const TetGenResult& result) {
  const size_t n = patch.positions.size();
  const TetMesh& mesh = result.mesh;
  std::vector<bool> kinematic(mesh.nodes.size(), false);
  for (const auto& edge : border)
    for (int v : edge) kinematic[size_t(v)] = true;
  for (size_t i = n; i < 2 * n; ++i) kinematic[i] = true;
  const std::vector<bool> onBoundary = boundaryNodes(mesh);
  TriangleMesh skin;
  for (const Vec3d& p : patch.positions) skin.positions.push_back(p.cast<float>());
  for (const auto& t : patch.triangles)
    for (int c : t) skin.indices.push_back(uint32_t(c));
  const ClosestPointGrid grid(skin);
  constexpr double kOnSurface = 1e-6;  // metres; the skin is stored in float
  for (size_t i = 2 * n; i < kinematic.size(); ++i) {
    const int marker = result.nodeMarkers[i];
    if (marker == kInnerFacet || marker == kWallFacet) {
      kinematic[i] = true;
      continue;
    }
    if (!onBoundary[i]) continue;
    const Vec3d& p = mesh.nodes[i];
    const double toSkin = (surfacePosition(skin, grid.closest(p.cast<float>())).cast<double>() - p).norm();
    bool onBorder = false;
    for (const auto& [a, b] : border)
      onBorder = onBorder || distanceToSegment(p, patch.positions[size_t(a)], patch.positions[size_t(b)]) < kOnSurface;
    kinematic[i] = toSkin > kOnSurface || onBorder;
  }
  return kinematic;
}

// The orthonormal frame of a triangle: first edge, in-plane perpendicular, normal (as columns).
Mat3d triangleFrame(const std::vector<Vec3d>& x, const std::array<int, 3>& t) {
  const Vec3d e1 = (x[size_t(t[1])] - x[size_t(t[0])]).normalized();
  const Vec3d n = triangleNormal(x, t).normalized();
  Mat3d frame;
  frame << e1, n.cross(e1), n;
  return frame;
}

Vec3d pointOn(const std::vector<Vec3d>& x, const std::array<int, 3>& t, const Vec3d& b) {
  return b[0] * x[size_t(t[0])] + b[1] * x[size_t(t[1])] + b[2] * x[size_t(t[2])];
}

NodeAnchor anchorAt(const SkinPatch& patch, int triangle, const Vec3d& barycentric, const Vec3d& node) {
  const auto& t = patch.triangles[size_t(triangle)];
  NodeAnchor anchor{triangle, barycentric, Vec3d::Zero()};
  anchor.offset = triangleFrame(patch.positions, t).transpose() * (node - pointOn(patch.positions, t, barycentric));
  return anchor;
}

std::vector<NodeAnchor> anchorNodes(const SkinPatch& patch, const TetMesh& mesh) {
  const size_t n = patch.positions.size();
  std::vector<NodeAnchor> anchors(mesh.nodes.size());
  std::vector<int> triangleOf(n, -1);
  std::vector<int> cornerOf(n, 0);
  for (size_t t = 0; t < patch.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      if (triangleOf[size_t(patch.triangles[t][c])] < 0) {
        triangleOf[size_t(patch.triangles[t][c])] = int(t);
        cornerOf[size_t(patch.triangles[t][c])] = c;
      }
  // The skin's own vertices and the inner surface's points under them.
  for (size_t v = 0; v < n; ++v) {
    const Vec3d corner = Vec3d::Unit(cornerOf[v]);
    anchors[v] = anchorAt(patch, triangleOf[v], corner, mesh.nodes[v]);
    anchors[v + n] = anchorAt(patch, triangleOf[v], corner, mesh.nodes[v + n]);
  }
  // Points TetGen added inside: the nearest point of the skin.
  TriangleMesh skin;
  for (const Vec3d& p : patch.positions) skin.positions.push_back(p.cast<float>());
  for (const auto& t : patch.triangles)
    for (int c : t) skin.indices.push_back(uint32_t(c));
  const ClosestPointGrid grid(skin);
  for (size_t i = 2 * n; i < mesh.nodes.size(); ++i) {
    const SurfacePoint nearest = grid.closest(mesh.nodes[i].cast<float>());
    // Summing to exactly 1 in double, so that the anchor point moves as an affine combination.
    const Vec3d weights = nearest.barycentric.cast<double>();
    const Vec3d barycentric = weights / weights.sum();
    anchors[i] = anchorAt(patch, int(nearest.triangle), barycentric, mesh.nodes[i]);
  }
  return anchors;
}

}  // namespace

std::string fleshVolumeRecipe(const FleshVolumeSettings& settings) {
  // Change the words with the method: a volume is filed under them (its nodes, tetrahedra,
  // kinematic flags and anchors).
  return "inner surface shrunk towards the fitted sphere's centre; TetGen -" + tetgenSwitches(settings) +
         "; kinematic: inner surface, walls and border, added nodes by position; anchors: nearest skin triangle";
}

FleshVolume buildFleshVolume(const SkinPatch& patch, const FleshVolumeSettings& settings) {
  if (patch.triangles.empty()) throw FleshVolumeError("the flesh region holds no skin triangle");
  if (!(settings.depth > 0.0) || !(settings.maxTetVolume > 0.0) || !(settings.radiusEdgeRatio >= 1.0))
    throw FleshVolumeError("the flesh volume needs a positive depth and tetrahedron volume and a radius-edge bound >= 1");
  const std::vector<std::array<int, 2>> border = borderEdges(patch);
  const std::vector<Vec3d> inner = innerSurface(patch, settings.depth);
  const TetGenResult result = runTetGen(closedShell(patch, inner, border), settings);
  FleshVolume volume;
  volume.mesh = result.mesh;
  volume.skinNodes = int(patch.positions.size());
  volume.kinematic = kinematicNodes(patch, border, result);
  volume.anchors = anchorNodes(patch, volume.mesh);
  return volume;
}

std::vector<Vec3d> anchoredNodePositions(const FleshVolume& volume, const SkinPatch& patch,
                                         const std::vector<Vec3d>& posedPatchPositions) {
  std::vector<Mat3d> frames(patch.triangles.size());
  for (size_t t = 0; t < frames.size(); ++t) frames[t] = triangleFrame(posedPatchPositions, patch.triangles[t]);
  std::vector<Vec3d> nodes(volume.anchors.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const NodeAnchor& a = volume.anchors[i];
    const auto& t = patch.triangles[size_t(a.triangle)];
    nodes[i] = pointOn(posedPatchPositions, t, a.barycentric) + frames[size_t(a.triangle)] * a.offset;
  }
  // The skin's own vertices exactly where the pose puts them (no rounding through the frame).
  for (size_t v = 0; v < size_t(volume.skinNodes); ++v) nodes[v] = posedPatchPositions[v];
  return nodes;
}

}  // namespace lacrima::flesh
