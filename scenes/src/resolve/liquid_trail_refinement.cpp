// Refinement along liquid tears' paths; see liquid_trail_refinement.hpp.
#include "resolve/liquid_trail_refinement.hpp"

#include <algorithm>
#include <map>
#include <memory>

#include "asset_pose.hpp"
#include "lacrima/rig/region_refinement.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "resolve/liquid_tear_resolve.hpp"
#include "resolve/surface_anchor.hpp"

namespace lacrima::shotfile {

namespace {

using PrimitiveKey = std::pair<size_t, size_t>;  // asset, primitive
using SmoothedSkins = std::map<PrimitiveKey, std::vector<Vec3>>;

float distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const float length2 = d.squaredNorm();
  const float f = length2 > 0.0f ? std::clamp((p - a).dot(d) / length2, 0.0f, 1.0f) : 0.0f;
  return (p - (a + f * d)).norm();
}

// The triangles along every course of the tear over the shot's frames (its path traced again on
// each frame's pose, LiquidTearCourses), the courses placed on the first frame's skin: the film
// lies along all of them. None when the tear has no path (resolveLiquidTears reports it).
std::vector<bool> trailAlongCourses(const Shot& shot, const ShotLiquidTear& tear, const ShotSurfacePoint& source,
                                    const TriangleMesh& skin, const std::vector<Vec3>& smoothed,
                                    const std::vector<uint32_t>& weldMap) {
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCourses(shot, tear, source, &smoothed);
  std::vector<bool> selected;
  const LiquidTearCourse* previous = nullptr;
  for (int frame = courses->firstFrame(); frame <= shot.frameEnd; ++frame) {
    const std::shared_ptr<const LiquidTearCourse> course = courses->at(frame);
    if (course.get() == previous || course->path.points.size() < 2) continue;
    previous = course.get();
    std::vector<Vec3> onFirstFrame;
    for (const SurfacePoint& p : course->path.points) onFirstFrame.push_back(surfacePosition(skin, p));
    const std::vector<bool> along = trailTriangles(skin, weldMap, onFirstFrame, kTrailRefinementMargin);
    if (selected.empty()) selected.assign(along.size(), false);
    for (size_t t = 0; t < along.size(); ++t) selected[t] = selected[t] || along[t];
  }
  return selected;
}

// Refines the triangles along the tear's courses on the first frame's smoothed skin.
void refineAlongTear(const Shot& shot, const ShotLiquidTear& tear, GltfAsset& gltf, SmoothedSkins& smoothedSkins) {
  const ShotSurfacePoint source = resolveSurfaceAnchor(shot, tear.asset, tear.part, tear.source);
  const ShotAsset& asset = shot.assets[tear.asset];
  const TriangleMesh skin = posedPrimitive(asset, assetPoseAt(asset, double(shot.frameStart)), source.primitive);
  const PrimitiveKey key{tear.asset, source.primitive};
  const auto known = smoothedSkins.find(key);
  const TriangleMesh smoothed =
      liquidPathSmoothedSkin(skin, known == smoothedSkins.end() ? nullptr : &known->second);
  GltfPrimitive& primitive = gltf.primitives[source.primitive];
  const std::vector<bool> selected = trailAlongCourses(shot, tear, source, skin, smoothed.positions, primitive.weldMap);
  if (selected.empty()) return;
  std::vector<Vec3> carried = smoothed.positions;  // refined with the same stencils as the primitive
  primitive = refinePrimitive(primitive, selected, RefinementScheme::Linear, tear.trailRefinementLevels, &carried);
  smoothedSkins[key] = std::move(carried);
}

}  // namespace

std::vector<bool> trailTriangles(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                                 const std::vector<Vec3>& path, float margin) {
  Eigen::AlignedBox3f box;
  for (const Vec3& p : path) box.extend(p);
  box.min().array() -= margin;
  box.max().array() += margin;
  // Each segment's box grown by a little more than the margin: a point outside it is farther than
  // the margin from the segment (the slack covers the distance's rounding), so only the segments
  // whose boxes hold the point are measured, and `near` is what measuring them all would give.
  const float reach = margin * 1.001f + 1e-6f;
  std::vector<Eigen::AlignedBox3f> segmentBoxes;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    Eigen::AlignedBox3f b(path[i].cwiseMin(path[i + 1]), path[i].cwiseMax(path[i + 1]));
    b.min().array() -= reach;
    b.max().array() += reach;
    segmentBoxes.push_back(b);
  }
  std::vector<bool> near(mesh.vertexCount(), false);
  for (size_t v = 0; v < near.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    if (!box.contains(p)) continue;
    for (size_t i = 0; i + 1 < path.size() && !near[v]; ++i)
      near[v] = segmentBoxes[i].contains(p) && distanceToSegment(p, path[i], path[i + 1]) <= margin;
  }
  // Triangles with a near corner, then one more ring: every triangle touching their corners' positions.
  std::vector<bool> touched(mesh.vertexCount(), false);
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* v = &mesh.indices[3 * t];
    if (near[v[0]] || near[v[1]] || near[v[2]])
      for (int k = 0; k < 3; ++k) touched[weldMap.at(v[k])] = true;
  }
  std::vector<bool> selected(mesh.triangleCount(), false);
  for (size_t t = 0; t < selected.size(); ++t)
    for (int k = 0; k < 3; ++k) selected[t] = selected[t] || touched[weldMap.at(mesh.indices[3 * t + k])];
  return selected;
}

void refineLiquidTrails(Shot& shot) {
  SmoothedSkins smoothedSkins;
  for (size_t a = 0; a < shot.assets.size(); ++a) {
    ShotAsset& asset = shot.assets[a];
    if (!asset.gltf) continue;
    std::shared_ptr<GltfAsset> refined;
    for (const ShotLiquidTear& tear : shot.liquidTears) {
      if (tear.asset != a || tear.trailRefinementLevels <= 0) continue;
      if (!refined) refined = std::make_shared<GltfAsset>(*asset.gltf);
      // The refined copy is what the next tear's path is traced on.
      asset.gltf = refined;
      refineAlongTear(shot, tear, *refined, smoothedSkins);
      // The rig copies the primitives and derives per-vertex jaw weights: rebuild it on the new ones
      // (the next tear poses the refined asset).
      if (asset.rig) asset.rig = std::make_shared<const FaceRig>(*refined, asset.rig->config());
    }
  }
  for (ShotLiquidTear& tear : shot.liquidTears)
    for (const auto& [key, positions] : smoothedSkins) {
      if (key.first != tear.asset) continue;
      tear.smoothedSkins.resize(shot.assets[tear.asset].gltf->primitives.size());
      tear.smoothedSkins[key.second] = std::make_shared<const std::vector<Vec3>>(positions);
    }
}

}  // namespace lacrima::shotfile
