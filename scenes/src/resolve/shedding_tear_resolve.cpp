// Resolving shedding tears at load; see shedding_tear_resolve.hpp.
#include "resolve/shedding_tear_resolve.hpp"

#include <fmt/format.h>

#include <limits>

#include "asset_pose.hpp"
#include "read/json_source.hpp"  // childPointer
#include "lacrima/mesh/closest_point_grid.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima::shotfile {

namespace {

struct SnappedPoint {
  size_t primitive = 0;
  SurfacePoint point;
  Vec3 position = Vec3::Zero();
  float distance = std::numeric_limits<float>::infinity();
};

// The nearest surface point of the part's posed primitives (ties keep the earlier primitive).
SnappedPoint snapToPart(const std::vector<std::pair<size_t, TriangleMesh>>& partMeshes,
                        const std::vector<ClosestPointGrid>& locators, const Vec3& target) {
  SnappedPoint best;
  for (size_t m = 0; m < partMeshes.size(); ++m) {
    const auto& [index, mesh] = partMeshes[m];
    const SurfacePoint nearest = locators[m].closest(target);
    const Vec3 position = surfacePosition(mesh, nearest);
    const float distance = (position - target).norm();
    if (distance < best.distance) best = {index, nearest, position, distance};
  }
  return best;
}

std::string formatPoint(const Vec3& p) { return fmt::format("[{:.4f}, {:.4f}, {:.4f}]", p.x(), p.y(), p.z()); }

// The part's primitives posed at the shot's first frame (the rest skin), with their indices.
std::vector<std::pair<size_t, TriangleMesh>> restPartMeshes(const Shot& shot, const ShotSheddingTear& tear) {
  const ShotAsset& asset = shot.assets[tear.asset];
  const AssetPose pose = assetPoseAt(asset, double(shot.frameStart));
  std::vector<std::pair<size_t, TriangleMesh>> partMeshes;
  for (size_t i = 0; i < asset.gltf->primitives.size(); ++i)
    if (asset.gltf->primitives[i].part == tear.part) {
      TriangleMesh mesh = posedPrimitive(asset, pose, i);
      if (mesh.triangleCount() > 0) partMeshes.emplace_back(i, std::move(mesh));
    }
  return partMeshes;
}

// The written path snapped to the rest skin; empty when a point is off the skin, on another
// primitive than the first point or on the same skin point as the one before (appended to problems).
std::vector<SnappedPoint> snapPath(const GltfAsset& gltf, const ShotSheddingTear& tear,
                                   const std::vector<std::pair<size_t, TriangleMesh>>& partMeshes,
                                   std::vector<SheddingTearProblem>& problems) {
  const size_t before = problems.size();
  std::vector<SnappedPoint> snapped;
  std::vector<ClosestPointGrid> locators;
  for (const auto& part : partMeshes) locators.emplace_back(part.second);
  for (size_t k = 0; k < tear.path.size(); ++k) {
    const SnappedPoint s = snapToPart(partMeshes, locators, tear.path[k]);
    const std::string at = childPointer(childPointer(tear.pointer, "path"), k);
    if (s.distance > kMaxPathPointDistance)
      problems.push_back({at, fmt::format("path point {} is {:.3g} m from the skin of part '{}' (its nearest skin "
                                          "point at the first frame is {}); path points must lie within {} m of it",
                                          k, s.distance, tear.part, formatPoint(s.position), kMaxPathPointDistance)});
    else if (k > 0 && s.primitive != snapped[0].primitive)
      problems.push_back({at, fmt::format("path point {} snaps to primitive '{}' of part '{}' but path point 0 to "
                                          "'{}'; a shedding tear runs over one primitive",
                                          k, gltf.primitives[s.primitive].name, tear.part,
                                          gltf.primitives[snapped[0].primitive].name)});
    else if (k > 0 && s.position == snapped.back().position)
      problems.push_back({at, fmt::format("path point {} snaps to the same skin point as path point {}; give "
                                          "distinct points", k, k - 1)});
    snapped.push_back(s);
  }
  if (problems.size() > before) snapped.clear();
  return snapped;
}

// Resolves one tear; appends its problems.
void resolveTear(const Shot& shot, ShotSheddingTear& tear, std::vector<SheddingTearProblem>& problems) {
  const std::vector<std::pair<size_t, TriangleMesh>> partMeshes = restPartMeshes(shot, tear);
  if (partMeshes.empty()) {
    problems.push_back({childPointer(tear.pointer, "part"), fmt::format("part '{}' has no triangles", tear.part)});
    return;
  }
  const std::vector<SnappedPoint> snapped = snapPath(*shot.assets[tear.asset].gltf, tear, partMeshes, problems);
  if (snapped.empty()) return;

  tear.primitive = snapped[0].primitive;
  const TriangleMesh* rest = nullptr;
  for (const auto& [index, mesh] : partMeshes)
    if (index == tear.primitive) rest = &mesh;
  std::vector<Vec3> line;
  float length = 0.0f;
  for (const SnappedPoint& s : snapped) {
    if (!line.empty()) length += (s.position - line.back()).norm();
    line.push_back(s.position);
  }
  const double gridPoints = (double(length) / tear.params.sampleSpacing + 2.0) * tear.params.acrossSamples;
  if (gridPoints > kMaxSheddingTearGridPoints) {
    problems.push_back({tear.pointer, fmt::format("the path ({:.3g} m long) with sampleSpacing {} and acrossSamples "
                                                  "{} makes about {:.0f} grid points; at most {:.0f} (use a larger "
                                                  "sampleSpacing or fewer acrossSamples)",
                                                  length, tear.params.sampleSpacing, tear.params.acrossSamples,
                                                  gridPoints, kMaxSheddingTearGridPoints)});
    return;
  }
  // Lin & Cheng 2013 section 4.2 step 1: the region the tear passes through, extracted from the skin.
  auto region = std::make_shared<SurfaceRegion>(
      extractSurfaceRegion(*rest, line, stripRegionRadius(line, tear.params.width)));
  tear.regionPath.clear();
  for (const SnappedPoint& s : snapped) tear.regionPath.push_back(*region->fromFull(s.point));
  tear.region = std::move(region);
  // The whole path once (no noise): a path that runs along the skin normal is reported now.
  SheddingTearParams full = tear.params;
  full.start = length;
  full.speed = 0.0f;
  full.noiseDensity = 0.0f;
  try {
    buildSheddingTearStrip(tear.region->mesh, tear.regionPath, full, 0.0f);
  } catch (const InputError& e) {
    problems.push_back({childPointer(tear.pointer, "path"), e.what()});
  }
}

}  // namespace

std::vector<SheddingTearProblem> resolveSheddingTears(Shot& shot) {
  std::vector<SheddingTearProblem> problems;
  for (ShotSheddingTear& tear : shot.sheddingTears)
    if (shot.assets[tear.asset].gltf) resolveTear(shot, tear, problems);
  return problems;
}

}  // namespace lacrima::shotfile
