// A shot's flesh volumes resolved; see flesh_resolve.hpp.
#include "resolve/flesh_resolve.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <array>

#include "asset_pose.hpp"
#include "lacrima/base/user_cache.hpp"
#include "lacrima/flesh/flesh_volume_cache.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "resolve/surface_anchor.hpp"

namespace lacrima::shotfile {

namespace {

// A skin vertex is carried by the flesh when it lies in a tetrahedron or this little outside one
// (in barycentric weight): the vertices of a skin refined after the volume was built lie on its
// boundary, a hair inside or outside it.
constexpr double kEmbeddingSlack = 0.02;

TriangleMesh posedSkin(const ShotAsset& asset, size_t primitive, double frame) {
  return posedPrimitive(asset, assetPoseAt(asset, frame), primitive);
}


// The patch of the skin in the regions, its vertices welded by position first (glTF splits
// vertices along uv seams: unwelded, a seam would be a border inside the patch, with walls on both
// sides of it), triangles of no area left out.
std::shared_ptr<const flesh::SkinPatch> skinPatchOf(const TriangleMesh& skin, const std::vector<uint32_t>& weld,
                                                    const std::vector<ShotSkinRegion>& regions) {
  TriangleMesh withNormals = skin;
  if (withNormals.normals.size() != withNormals.positions.size()) computeSmoothNormals(withNormals, weld);
  std::vector<Vec3d> positions, normals;
  for (size_t v = 0; v < skin.positions.size(); ++v) {
    positions.push_back(skin.positions[v].cast<double>());
    normals.push_back(withNormals.normals[v].cast<double>());
  }
  std::vector<bool> selected = trianglesWithinRegions(skin, regions);
  std::vector<std::array<uint32_t, 3>> triangles;
  for (size_t t = 0; t < skin.triangleCount(); ++t) {
    const std::array<uint32_t, 3> corners{weld[skin.indices[3 * t]], weld[skin.indices[3 * t + 1]],
                                          weld[skin.indices[3 * t + 2]]};
    const Vec3d area = (positions[corners[1]] - positions[corners[0]]).cross(positions[corners[2]] - positions[corners[0]]);
    if (!(area.norm() > 0.0)) selected[t] = false;
    triangles.push_back(corners);
  }
  return std::make_shared<const flesh::SkinPatch>(flesh::extractSkinPatch(positions, normals, triangles, selected));
}

std::optional<FleshProblem> resolveOne(Shot& shot, ShotFlesh& flesh) {
  for (ShotSkinRegion& region : flesh.regions)
    region.centerPoint = resolveSurfaceAnchor(shot, flesh.asset, flesh.part, region.center);
  flesh.primitive = flesh.regions.front().centerPoint.primitive;
  for (size_t i = 1; i < flesh.regions.size(); ++i)
    if (flesh.regions[i].centerPoint.primitive != flesh.primitive)
      return FleshProblem{fmt::format("{}/regions/{}/center", flesh.pointer, i),
                          "the regions' centres lie on different primitives of the part; a flesh volume lies under one"};
  const ShotAsset& asset = shot.assets[flesh.asset];
  const TriangleMesh skin = posedSkin(asset, flesh.primitive, shot.frameStart);
  flesh.patch = skinPatchOf(skin, findCoincidentVertices(skin), flesh.regions);
  if (flesh.patch->triangles.empty())
    return FleshProblem{flesh.pointer + "/regions",
                        "no triangle of the skin lies wholly within the regions: give larger radii"};
  try {
    flesh.tetVolume = std::make_shared<const flesh::FleshVolume>(
        flesh::cachedFleshVolume(*flesh.patch, flesh.volume, fleshCacheDirectory()));
  } catch (const flesh::FleshVolumeError& e) {
    return FleshProblem{flesh.pointer, fmt::format("the flesh volume cannot be built: {}", e.what())};
  }
  flesh.unrefinedAsset = std::make_shared<const ShotAsset>(asset);
  return std::nullopt;
}

}  // namespace

std::filesystem::path fleshCacheDirectory() { return userCacheDirectory("flesh"); }

std::vector<FleshProblem> resolveFleshVolumes(Shot& shot) {
  std::vector<FleshProblem> problems;
  for (ShotFlesh& flesh : shot.flesh)
    if (std::optional<FleshProblem> problem = resolveOne(shot, flesh)) problems.push_back(*problem);
  return problems;
}

void embedFleshSkins(Shot& shot) {
  for (ShotFlesh& flesh : shot.flesh) {
    if (!flesh.tetVolume) continue;
    const TriangleMesh skin = posedSkin(shot.assets[flesh.asset], flesh.primitive, shot.frameStart);
    const flesh::TetMesh& mesh = flesh.tetVolume->mesh;
    Eigen::AlignedBox3d box;
    for (const Vec3d& p : mesh.nodes) box.extend(p);
    std::vector<Vec3d> points;
    std::vector<size_t> vertices;
    for (size_t v = 0; v < skin.positions.size(); ++v)
      if (box.contains(skin.positions[v].cast<double>())) {
        points.push_back(skin.positions[v].cast<double>());
        vertices.push_back(v);
      }
    flesh.skinEmbedding.assign(skin.positions.size(), flesh::TetEmbedding{});
    const std::vector<flesh::TetEmbedding> embedded = flesh::embedPoints(mesh, points, kEmbeddingSlack);
    for (size_t i = 0; i < vertices.size(); ++i) flesh.skinEmbedding[vertices[i]] = embedded[i];
  }
}

}  // namespace lacrima::shotfile
