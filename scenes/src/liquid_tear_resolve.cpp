// Resolving liquid tears at load; see liquid_tear_resolve.hpp.
#include "liquid_tear_resolve.hpp"

#include <fmt/format.h>

#include <optional>

#include "asset_pose.hpp"
#include "json_source.hpp"  // childPointer
#include "lacrima/geometry/error.hpp"
#include "lacrima/geometry/meniscus_swelling.hpp"
#include "lacrima/geometry/surface_point.hpp"
#include "surface_anchor.hpp"

namespace lacrima::shotfile {

namespace {

// Positions and arc lengths of `path` on `skin` (the path's points are topological, so they are
// valid on any mesh of the same topology). A piece of zero length on `skin` is dropped by
// removing its start point: the piece before it then ends where the dropped one did.
FlowPath onSkin(const FlowPath& traced, const TriangleMesh& skin) {
  FlowPath path;
  path.stop = traced.stop;
  std::optional<Vec3> pendingArrival;  // the end of the piece before a dropped point
  for (size_t i = 0; i < traced.points.size(); ++i) {
    const Vec3 position = surfacePosition(skin, traced.points[i]);
    const bool last = i + 1 == traced.points.size();
    const float arc = path.positions.empty() ? 0.0f : path.arcLength.back() + (position - path.positions.back()).norm();
    const bool emptyPieceStarts = !last && surfacePosition(skin, traced.points[i + 1]) == position;
    if (emptyPieceStarts || (!path.points.empty() && !(arc > path.arcLength.back()))) {
      if (!pendingArrival) pendingArrival = traced.arrival[i];
      continue;
    }
    path.points.push_back(traced.points[i]);
    path.arrival.push_back(pendingArrival.value_or(traced.arrival[i]));
    pendingArrival.reset();
    path.positions.push_back(position);
    path.arcLength.push_back(arc);
  }
  return path;
}

// The lacrimal strip of the tear's asset nearest the source, if within kMeniscusReach, with the
// falloff weights of its vertices on the first frame's pose.
void resolveMeniscus(const ShotAsset& asset, const AssetPose& pose, const Vec3& source, ShotLiquidTear& tear) {
  float nearest = kMeniscusReach;
  for (size_t i = 0; i < asset.gltf->primitives.size(); ++i) {
    if (asset.gltf->primitives[i].part != kLacrimalFluidPart) continue;
    const TriangleMesh strip = posedPrimitive(asset, pose, i);
    if (strip.triangleCount() == 0) continue;
    const float distance = (surfacePosition(strip, closestSurfacePoint(strip, source)) - source).norm();
    if (!(distance <= nearest)) continue;
    nearest = distance;
    tear.meniscusPrimitive = int(i);
    tear.meniscusWeights = meniscusFalloffWeights(strip, source, kMeniscusFalloffLength);
  }
}

void resolveTear(const Shot& shot, ShotLiquidTear& tear, std::vector<LiquidTearProblem>& problems) {
  tear.sourcePoint = resolveSurfaceAnchor(shot, tear.asset, tear.part, tear.source);
  const ShotAsset& asset = shot.assets[tear.asset];
  const AssetPose pose = assetPoseAt(asset, double(shot.frameStart));
  const TriangleMesh skin = posedPrimitive(asset, pose, tear.sourcePoint.primitive);
  const SurfacePoint sourceOnSkin{tear.sourcePoint.triangle, tear.sourcePoint.barycentric};
  resolveMeniscus(asset, pose, surfacePosition(skin, sourceOnSkin), tear);
  const size_t primitive = tear.sourcePoint.primitive;
  const std::vector<Vec3>* carried =
      primitive < tear.smoothedSkins.size() && tear.smoothedSkins[primitive] ? tear.smoothedSkins[primitive].get() : nullptr;
  const TriangleMesh smoothed = liquidPathSmoothedSkin(skin, carried);
  const FlowPath traced = traceLiquidPath(skin, smoothed, sourceOnSkin, tear.gravity, tear.maxLength);
  tear.smoothedPathLength = traced.length();
  tear.path = flowPathOnSkin(traced, skin);
  if (tear.path.points.size() < 2 || tear.path.length() < kMinLiquidPathLength) {
    problems.push_back({childPointer(tear.pointer, "source"),
                        fmt::format("the flow path from the source runs only {:.3g} m over part '{}' before it stops "
                                    "({}); a liquid tear needs at least {} m (move the source or change gravity)",
                                    tear.path.length(), tear.part, flowStopName(tear.path.stop), kMinLiquidPathLength)});
    return;
  }
  tear.input.path = liquidPathFromFlowPath(tear.path, skin);
  tear.input.gravityDirection = tear.gravity.cast<double>();
  tear.input.params = tear.params;
  try {
    TearLiquidSimulation check(tear.input);
  } catch (const InputError& e) {
    problems.push_back({tear.pointer, e.what()});
  }
}

}  // namespace

FlowPath flowPathOnSkin(const FlowPath& traced, const TriangleMesh& skin) { return onSkin(traced, skin); }

TriangleMesh liquidPathSmoothedSkin(const TriangleMesh& skin, const std::vector<Vec3>* carried) {
  if (!carried || carried->size() != skin.vertexCount())
    return taubinSmoothed(skin, findCoincidentVertices(skin), kLiquidPathSmoothing);
  TriangleMesh smoothed = skin;
  smoothed.positions = *carried;
  smoothed.normals.clear();  // the walk uses the triangles' own normals
  return smoothed;
}

FlowPath traceLiquidPath(const TriangleMesh& skin, const TriangleMesh& smoothed, const SurfacePoint& start,
                         const Vec3& gravity, float maxLength) {
  const TriangleAdjacency adjacency = buildTriangleAdjacency(skin, findCoincidentVertices(skin));
  FlowPathOptions options;
  options.maxLength = maxLength;
  return traceFlowPath(smoothed, adjacency, start, gravity, options);
}

std::vector<LiquidTearProblem> resolveLiquidTears(Shot& shot) {
  std::vector<LiquidTearProblem> problems;
  for (ShotLiquidTear& tear : shot.liquidTears)
    if (shot.assets[tear.asset].gltf) resolveTear(shot, tear, problems);
  return problems;
}

}  // namespace lacrima::shotfile
