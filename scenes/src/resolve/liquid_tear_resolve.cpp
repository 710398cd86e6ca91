// Resolving liquid tears at load; see liquid_tear_resolve.hpp.
#include "resolve/liquid_tear_resolve.hpp"

#include <fmt/format.h>

#include <optional>

#include "asset_pose.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "read/json_source.hpp"  // childPointer
#include "lacrima/base/error.hpp"
#include "lacrima/liquid/meniscus_swelling.hpp"
#include "resolve/film_edge_variation.hpp"
#include "resolve/liquid_tear_pinning.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "resolve/surface_anchor.hpp"

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

bool sameMotion(const std::vector<Affine3>& a, const std::vector<Affine3>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].matrix() != b[i].matrix()) return false;
  return true;
}

// True when two poses give bitwise the same posed meshes (every input of posedPrimitive equal).
bool samePose(const AssetPose& a, const AssetPose& b) {
  const FacePose &x = a.face, &y = b.face;
  if (x.blendshapeWeights != y.blendshapeWeights || x.eyeEulerDegrees != y.eyeEulerDegrees) return false;
  if (x.head.eulerDegrees != y.head.eulerDegrees || x.head.translation != y.head.translation) return false;
  if (x.jaw.eulerDegrees != y.jaw.eulerDegrees || x.jaw.translation != y.jaw.translation) return false;
  if (!sameMotion(a.primitiveMotion, b.primitiveMotion) || a.skinJointMatrices.size() != b.skinJointMatrices.size())
    return false;
  for (size_t i = 0; i < a.skinJointMatrices.size(); ++i)
    if (!sameMotion(a.skinJointMatrices[i], b.skinJointMatrices[i])) return false;
  return true;
}

// The tear's primitive posed at integer frames, and the smoothed copy the path is traced on: at the
// reference frame's pose its smoothed skin (kLiquidPathSmoothing, or carried through the trail
// refinement); at any other pose that plus the deformation since the reference (posed - reference
// posed, per vertex) low-passed by kLiquidDeformationSmoothing. Taubin's filter is linear, so
// smoothing the pose is smoothing the reference plus smoothing the deformation; the deformation
// (a turn of the head, blendshapes) is smooth but for the small bumps a sob's blendshapes make
// around the eye, which its few iterations remove (unsmoothed, one of them stopped the default
// shot's path in a pit 2 mm below the source at frames 27 and 49).
class PosedTearSurface final : public LiquidTearSurface {
 public:
  PosedTearSurface(const ShotAsset& asset, size_t primitive, int referenceFrame, const std::vector<Vec3>* carried)
      : asset_(asset), primitive_(primitive), referencePose_(assetPoseAt(asset, double(referenceFrame))) {
    const TriangleMesh skin = posedPrimitive(asset_, referencePose_, primitive_);
    referencePosed_ = skin.positions;
    referenceSmoothed_ = liquidPathSmoothedSkin(skin, carried).positions;
    deformationFilter_ = std::make_shared<const TaubinSmoother>(skin, findCoincidentVertices(skin),
                                                                kLiquidDeformationSmoothing);
  }

  LiquidTearSkin at(int frame) const override {
    const AssetPose pose = assetPoseAt(asset_, double(frame));
    LiquidTearSkin surface{posedPrimitive(asset_, pose, primitive_), TriangleMesh()};
    surface.smoothed = surface.skin;
    surface.smoothed.normals.clear();  // the walk uses the triangles' own normals
    if (samePose(pose, referencePose_)) {
      surface.smoothed.positions = referenceSmoothed_;
      return surface;
    }
    std::vector<Vec3> deformation(referencePosed_.size());
    for (size_t v = 0; v < deformation.size(); ++v) deformation[v] = surface.skin.positions[v] - referencePosed_[v];
    deformation = deformationFilter_->smoothed(deformation);
    for (size_t v = 0; v < deformation.size(); ++v) surface.smoothed.positions[v] = referenceSmoothed_[v] + deformation[v];
    return surface;
  }

  bool sameAsPrevious(int frame) const override {
    return samePose(assetPoseAt(asset_, double(frame)), assetPoseAt(asset_, double(frame - 1)));
  }

 private:
  ShotAsset asset_;  // a copy (its meshes and rig are shared): the surface outlives any Shot copy
  size_t primitive_;
  AssetPose referencePose_;
  std::vector<Vec3> referencePosed_;
  std::vector<Vec3> referenceSmoothed_;
  std::shared_ptr<const TaubinSmoother> deformationFilter_;
};

// Each contact-angle region's centre on the first frame's skin; false (reported) when one lies on
// another primitive of the part than the source (the course's surface is the source's primitive).
bool resolveRegions(const Shot& shot, ShotLiquidTear& tear, std::vector<LiquidTearProblem>& problems) {
  bool ok = true;
  for (size_t i = 0; i < tear.contactAngleRegions.size(); ++i) {
    ShotContactAngleRegion& region = tear.contactAngleRegions[i];
    region.centerPoint = resolveSurfaceAnchor(shot, tear.asset, tear.part, region.center);
    if (region.centerPoint.primitive == tear.sourcePoint.primitive) continue;
    problems.push_back({childPointer(childPointer(childPointer(tear.pointer, "contactAngleRegions"), i), "center"),
                        fmt::format("the region's centre lies on primitive {} of part '{}', the source on primitive {}; "
                                    "a region must lie on the source's primitive",
                                    region.centerPoint.primitive, tear.part, tear.sourcePoint.primitive)});
    ok = false;
  }
  return ok;
}

void resolveTear(const Shot& shot, ShotLiquidTear& tear, std::vector<LiquidTearProblem>& problems) {
  tear.sourcePoint = resolveSurfaceAnchor(shot, tear.asset, tear.part, tear.source);
  if (!resolveRegions(shot, tear, problems)) return;
  const ShotAsset& asset = shot.assets[tear.asset];
  const AssetPose pose = assetPoseAt(asset, double(shot.frameStart));
  const TriangleMesh skin = posedPrimitive(asset, pose, tear.sourcePoint.primitive);
  const SurfacePoint sourceOnSkin{tear.sourcePoint.triangle, tear.sourcePoint.barycentric};
  resolveMeniscus(asset, pose, surfacePosition(skin, sourceOnSkin), tear);
  tear.filmEdgeVariation = filmEdgeVariation(skin);
  if (tear.pinningFactor > 1.0) tear.pinning = skinPinning(skin, tear.pinningFactor, tear.pinningPatchSize);
  const size_t primitive = tear.sourcePoint.primitive;
  const std::vector<Vec3>* carried =
      primitive < tear.smoothedSkins.size() && tear.smoothedSkins[primitive] ? tear.smoothedSkins[primitive].get() : nullptr;
  // The courses from the simulation's first step on, traced here to check them (a FrameBuilder
  // traces its own); the path checked and reported is the one the simulation starts on.
  tear.surface = posedTearSurface(asset, primitive, shot.frameStart, carried);
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, tear);
  const std::shared_ptr<const LiquidTearCourse> first = courses->at(courses->firstFrame());
  if (first->path.points.size() < 2 || first->path.length() < kMinLiquidPathLength) {
    problems.push_back({childPointer(tear.pointer, "source"),
                        fmt::format("the flow path from the source runs only {:.3g} m over part '{}' before it stops "
                                    "({}); a liquid tear needs at least {} m (move the source or change gravity)",
                                    first->path.length(), tear.part, flowStopName(first->path.stop), kMinLiquidPathLength)});
    return;
  }
  const std::shared_ptr<const LiquidTearCourse> atShotStart = courses->at(shot.frameStart);
  tear.smoothedPathLength = atShotStart->smoothedLength;
  tear.path = atShotStart->path;
  tear.input.path = atShotStart->samples;
  tear.input.gravityDirection = tear.gravity.cast<double>();
  tear.input.params = tear.params;
  try {
    LiquidTearSimulation check(tear.input);
  } catch (const InputError& e) {
    problems.push_back({tear.pointer, e.what()});
  }
}

}  // namespace

FlowPath flowPathOnSkin(const FlowPath& traced, const TriangleMesh& skin) { return onSkin(traced, skin); }

std::shared_ptr<const LiquidTearSurface> posedTearSurface(const ShotAsset& asset, size_t primitive, int referenceFrame,
                                                          const std::vector<Vec3>* carried) {
  return std::make_shared<const PosedTearSurface>(asset, primitive, referenceFrame, carried);
}

std::shared_ptr<const LiquidTearCourses> liquidTearCourses(const Shot& shot, const ShotLiquidTear& tear,
                                                           const ShotSurfacePoint& source, const std::vector<Vec3>* carried) {
  return std::make_shared<const LiquidTearCourses>(
      posedTearSurface(shot.assets[tear.asset], source.primitive, shot.frameStart, carried),
      SurfacePoint{source.triangle, source.barycentric}, tear.gravity, tear.maxLength,
      liquidTearCourseFrame(shot, tear, 0.0));
}

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
