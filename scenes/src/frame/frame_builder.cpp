// FrameBuilder: a checked Shot at one frame number -> the renderer's Frame, through the geometry
// stage: assets posed by their rig, keyframes and performance tracks, details displacing the
// posed skin, shapes (keyed or attached to the skin), dripping, shedding and liquid tears (on the
// posed, detailed skin), eyes and lashes (on the posed eyeball shells and lash cards), lights and camera, each at shutter open and, when the shot has a shutter
// and it moves, at shutter close (motion blur). Nothing is read from disk here.
#include <fmt/format.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "asset_pose.hpp"
#include "frame/eye_frame.hpp"
#include "frame/flesh_frame.hpp"
#include "frame/sph_liquid.hpp"
#include "lacrima/face/detail_patterns.hpp"
#include "lacrima/tears/dripping_tear.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/tears/shedding_tear.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/scenes/frame_build_times.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"
#include "frame/liquid_tear_frame.hpp"
#include "shot_geometry.hpp"
#include "resolve/surface_attachment.hpp"

namespace lacrima {

namespace {

using shotfile::assetPoseAt;
using shotfile::posedPrimitive;

// Adds the wall time from its construction to its destruction to *seconds (nothing when null).
class StageClock {
 public:
  explicit StageClock(double* seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  ~StageClock() {
    if (seconds_) *seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  StageClock(const StageClock&) = delete;
  StageClock& operator=(const StageClock&) = delete;

 private:
  double* seconds_;
  std::chrono::steady_clock::time_point start_;
};

// The shutter interval of one frame, in (fractional) frames.
struct ShutterTimes {
  double open = 0.0, close = 0.0;
  bool blurred() const { return close > open; }
};

// Every primitive of every asset posed at one time (world space).
using PosedAssets = std::vector<std::vector<TriangleMesh>>;

enum class StillAssets { Posed, Skipped };

PosedAssets poseAssets(const Shot& shot, double frame, StillAssets still) {
  PosedAssets posed(shot.assets.size());
  for (size_t a = 0; a < shot.assets.size(); ++a) {
    const ShotAsset& asset = shot.assets[a];
    if (still == StillAssets::Skipped && !asset.animated()) continue;
    const shotfile::AssetPose pose = assetPoseAt(asset, frame);
    for (size_t i = 0; i < asset.gltf->primitives.size(); ++i) posed[a].push_back(posedPrimitive(asset, pose, i));
  }
  return posed;
}

void checkLoaded(const Shot& shot, const ShotAsset& asset) {
  if (!asset.gltf)
    throw InputError(fmt::format("{}: asset '{}' ({}) is not loaded; shots must come from loadShot", shot.path.string(),
                                 asset.name, asset.file.string()));
  if (asset.primitiveMaterials.size() != asset.gltf->primitives.size())
    throw InputError(fmt::format("{}: asset '{}': {} primitive materials for {} primitives", shot.path.string(),
                                 asset.name, asset.primitiveMaterials.size(), asset.gltf->primitives.size()));
}

// A dielectric primitive with boundary edges bounds no volume: a thin sheet (MeshInstance::
// thinSheet). Decided on the neutral mesh, so every frame of a shot decides alike. materialId
// indexes frame.materials (the shot's materials, then the assets' automatic ones).
bool isOpenDielectric(const Frame& frame, uint32_t materialId, const TriangleMesh& neutral) {
  return dielectricMedium(frame.materials.at(materialId).params) && countBoundaryEdges(neutral) > 0;
}

// The visible primitives as mesh instances; deforming ones carry their shutter-close vertices.
void addAssetMeshes(const Shot& shot, size_t a, const PosedAssets& open, const PosedAssets* close, Frame& frame) {
  const ShotAsset& asset = shot.assets[a];
  for (size_t i = 0; i < open[a].size(); ++i) {
    const int materialId = asset.primitiveMaterials[i];
    if (materialId < 0) continue;  // hidden
    MeshInstance instance(open[a][i], uint32_t(materialId));
    instance.thinSheet = isOpenDielectric(frame, uint32_t(materialId), asset.gltf->primitives[i].mesh);
    if (const std::string defect = findMeshDefect(instance.mesh); !defect.empty())
      throw InputError(fmt::format("{}: asset '{}' ({}), primitive '{}': {}", shot.path.string(), asset.name,
                                   asset.file.string(), asset.gltf->primitives[i].name, defect));
    if (close && !(*close)[a].empty() && (*close)[a][i].positions != instance.mesh.positions) {
      instance.positionsAtClose = (*close)[a][i].positions;
      instance.normalsAtClose = (*close)[a][i].normals;
    }
    frame.meshes.push_back(std::move(instance));
  }
}

// The index in frame.meshes of asset a's primitive (addAssetMeshes adds every asset's visible
// primitives first, in order); -1 for a hidden primitive.
int assetMeshIndex(const Shot& shot, const PosedAssets& open, size_t a, size_t primitive) {
  int index = 0;
  for (size_t b = 0; b <= a; ++b)
    for (size_t i = 0; i < open[b].size() && (b < a || i < primitive); ++i)
      index += shot.assets[b].primitiveMaterials[i] >= 0 ? 1 : 0;
  return shot.assets[a].primitiveMaterials[primitive] >= 0 ? index : -1;
}

// The shape's center at a time: its keys, moved with the skin when it is attached.
Vec3 shapeCenterAt(const ShotShape& shape, double frame, const PosedAssets& posed) {
  Vec3 center = shape.centerCurve ? shape.centerCurve->evaluate(float(frame)) : shape.center;
  if (shape.attachment && !posed[shape.attachment->asset].empty())
    center += shotfile::attachedPoint(posed[shape.attachment->asset], *shape.attachment) - shape.attachment->reference;
  return center;
}

MeshInstance shapeMesh(const Frame& frame, const ShotShape& shape, const Vec3& center) {
  MeshInstance mesh(shotfile::shapeTriangles(shape, center), shape.materialId);
  // A rectangle bounds nothing: as a dielectric it is a thin sheet.
  if (shape.type == ShotShape::Type::Rectangle)
    mesh.thinSheet = dielectricMedium(frame.materials.at(shape.materialId).params).has_value();
  return mesh;
}

void addShape(const ShotShape& shape, const ShutterTimes& shutter, const PosedAssets& open,
              const PosedAssets* close, Frame& frame) {
  const Vec3 centerOpen = shapeCenterAt(shape, shutter.open, open);
  // An attached shape follows its asset at close when the asset moves; otherwise as at open.
  const bool attachedMoves = shape.attachment && close && !(*close)[shape.attachment->asset].empty();
  const Vec3 centerClose =
      close ? shapeCenterAt(shape, shutter.close, attachedMoves ? *close : open) : centerOpen;
  if (shape.type == ShotShape::Type::Sphere) {
    Sphere sphere(centerOpen, shape.radius, shape.materialId);
    if (centerClose != centerOpen) sphere.centerAtClose = centerClose;
    frame.spheres.push_back(sphere);
    return;
  }
  MeshInstance mesh = shapeMesh(frame, shape, centerOpen);
  if (centerClose != centerOpen)
    for (const Vec3& p : mesh.mesh.positions) mesh.positionsAtClose.push_back(p + (centerClose - centerOpen));
  frame.meshes.push_back(std::move(mesh));
}

// The dripping tear's mesh at a (fractional) frame, placed in the world.
TriangleMesh tearMesh(const Shot& shot, const ShotTear& tear, double frame) {
  TriangleMesh mesh = makeDrippingTear(tear.params, float(tear.secondsAt(frame, shot.fps)), tear.rings, tear.segments);
  placeDrippingTear(mesh, tear.origin, tear.gravity);
  return mesh;
}

void addTear(const Shot& shot, const ShotTear& tear, int frameNumber, const ShutterTimes& shutter, Frame& frame) {
  if (frameNumber < tear.startFrame) return;  // the drop has not started yet
  MeshInstance instance(tearMesh(shot, tear, shutter.open), tear.materialId);
  instance.mesh.name = "tear";
  if (shutter.blurred()) {
    TriangleMesh atClose = tearMesh(shot, tear, shutter.close);
    if (atClose.positions != instance.mesh.positions) {
      instance.positionsAtClose = std::move(atClose.positions);
      instance.normalsAtClose = std::move(atClose.normals);
    }
  }
  frame.meshes.push_back(std::move(instance));
}

// Lin & Cheng 2013 section 4.2: the shedding tear's strip on the rest skin region at the shutter-open time,
// placed on the posed (and detailed) primitive; with a shutter the same strip is also placed on
// the shutter-close skin, so the tear moves with the face but its growth within the shutter is
// not blurred.
void addSheddingTear(const Shot& shot, const ShotSheddingTear& tear, int frameNumber, const ShutterTimes& shutter,
                     const PosedAssets& open, const PosedAssets* close, Frame& frame) {
  if (frameNumber < tear.startFrame || !tear.region || open[tear.asset].empty()) return;
  const float t = float(std::max(0.0, tear.secondsAt(shutter.open, shot.fps)));
  SheddingTearStrip strip = buildSheddingTearStrip(tear.region->mesh, tear.regionPath, tear.params, t);
  if (strip.rows == 0) return;  // not grown to a row yet
  for (SurfacePoint& p : strip.points) p = tear.region->toFull(p);
  MeshInstance instance(sheddingTearMesh(open[tear.asset][tear.primitive], strip, tear.params.baseOffset),
                        tear.materialId);
  instance.mesh.name = "shedding tear";
  if (close && !(*close)[tear.asset].empty()) {
    TriangleMesh atClose = sheddingTearMesh((*close)[tear.asset][tear.primitive], strip, tear.params.baseOffset);
    if (atClose.positions != instance.mesh.positions) {
      instance.positionsAtClose = std::move(atClose.positions);
      instance.normalsAtClose = std::move(atClose.normals);
    }
  }
  frame.meshes.push_back(std::move(instance));
}

// The detail's displacement of one posed primitive, in place. New normals only around the
// moved vertices (renewSmoothNormalsAround), so the rest of the skin keeps its normals bitwise; a
// mesh without normals gets them everywhere.
void displaceAndRenormalise(TriangleMesh& mesh, const DetailRegion& region, const DetailPatternApplication& application) {
  const std::vector<Vec3> before = mesh.positions;
  const bool hadNormals = mesh.normals.size() == mesh.positions.size();
  if (!hadNormals) {
    TriangleMesh withNormals = mesh;
    computeSmoothNormals(withNormals);
    mesh.normals = std::move(withNormals.normals);  // the pattern's displacement directions
  }
  if (applyDetailPattern(mesh, mesh.normals, region, application) == 0) {
    if (!hadNormals) mesh.normals.clear();  // nothing moved: the mesh stays as it was
    return;
  }
  if (!hadNormals) {
    computeSmoothNormals(mesh);
    return;
  }
  std::vector<bool> moved(mesh.positions.size());
  for (size_t v = 0; v < moved.size(); ++v) moved[v] = mesh.positions[v] != before[v];
  renewSmoothNormalsAround(mesh, moved);
}

// The detail's displacement of the part's posed primitives at a (fractional) frame, in place.
// The local frame comes from the posed skin at the detail's surface point: its centre there,
// the normal the interpolated skin normal, tangent x the projection of the detail's tangent
// (world +x by default; +y, then +z when that is along the normal).
void applyDetail(const Shot& shot, const ShotDetail& detail, double frame, std::vector<TriangleMesh>& posed) {
  const float amplitude = detail.amplitude.at(frame);
  if (!(amplitude > 0.0f) || detail.scale == 0.0f) return;
  const Vec3 center = shotfile::attachedPoint(posed, detail.surfacePoint);
  const Vec3 normal = shotfile::attachedNormal(posed, detail.surfacePoint);
  Vec3 tangentX = Vec3::Zero();
  for (const Vec3& candidate : {detail.tangent.value_or(Vec3(Vec3::UnitX())), Vec3(Vec3::UnitY()), Vec3(Vec3::UnitZ())}) {
    const Vec3 projected = candidate.normalized() - candidate.normalized().dot(normal) * normal;
    if (projected.norm() > 1e-3f) {
      tangentX = projected.normalized();
      break;
    }
  }
  DetailRegion region;
  region.center = center;
  region.tangentX = tangentX;
  region.tangentY = normal.cross(tangentX).normalized();
  region.semiAxisA = detail.semiAxisA;
  region.semiAxisB = detail.semiAxisB;
  region.innerRadius = detail.innerRadius;
  // Keeps surfaces far off the skin plane (the other side of a head, the mouth's inside) out.
  region.maxNormalDistance = std::max(detail.semiAxisA, detail.semiAxisB);
  DetailPatternApplication application;
  application.patterns = detail.patterns;
  application.time = float((frame - detail.startFrame) / shot.fps);
  application.heightScale = detail.scale * amplitude;
  application.coordinateScale = detail.coordinateScale;
  application.patternOrigin = detail.patternOrigin;
  application.selection = detail.selection;
  const ShotAsset& asset = shot.assets[detail.asset];
  for (size_t i = 0; i < posed.size(); ++i)
    if (asset.gltf->primitives[i].part == detail.part) displaceAndRenormalise(posed[i], region, application);
}

// Moves the posed skin under each simulated flesh (at shutter open and close) before any detail
// displaces it: the flesh carries the skin, the details ride on it.
void applyFleshes(const Shot& shot, const std::vector<std::unique_ptr<shotfile::FleshRun>>& runs,
                  const ShutterTimes& shutter, PosedAssets& open, std::optional<PosedAssets>& close) {
  for (size_t f = 0; f < shot.flesh.size(); ++f) {
    const ShotFlesh& flesh = shot.flesh[f];
    if (open[flesh.asset].empty() || flesh.primitive >= open[flesh.asset].size()) continue;
    const GltfPrimitive& source = shot.assets[flesh.asset].gltf->primitives[flesh.primitive];
    TriangleMesh& atOpen = open[flesh.asset][flesh.primitive];
    TriangleMesh* atClose = close && !(*close)[flesh.asset].empty() ? &(*close)[flesh.asset][flesh.primitive] : nullptr;
    if (!runs[f] || !shotfile::fleshMoves(flesh, atOpen)) continue;
    // The simulation steps forward in time: open's offsets first, then close's.
    const std::vector<Vec3d> offsetsAtOpen = runs[f]->nodeOffsetsAt(shutter.open);
    const std::vector<Vec3d> offsetsAtClose = atClose ? runs[f]->nodeOffsetsAt(shutter.close) : std::vector<Vec3d>{};
    tbb::parallel_invoke([&] { shotfile::moveSkinWithFlesh(flesh, source, offsetsAtOpen, atOpen); },
                         [&] {
                           if (atClose) shotfile::moveSkinWithFlesh(flesh, source, offsetsAtClose, *atClose);
                         });
  }
}

// Applies the shot's details active at this frame to the posed assets (at shutter open and close).
void applyDetails(const Shot& shot, int frameNumber, const ShutterTimes& shutter, PosedAssets& open,
                  std::optional<PosedAssets>& close) {
  std::vector<const ShotDetail*> active;
  for (const ShotDetail& detail : shot.details) {
    if (!detail.activeAt(frameNumber) || open[detail.asset].empty()) continue;
    // A still asset is not posed again at close; its detail may move, so it gets its own copy.
    if (close && (*close)[detail.asset].empty()) (*close)[detail.asset] = open[detail.asset];
    active.push_back(&detail);
  }
  // Open and close are independent copies: displaced side by side.
  tbb::parallel_invoke([&] {
    for (const ShotDetail* detail : active) applyDetail(shot, *detail, shutter.open, open[detail->asset]);
  },
                       [&] {
                         if (close)
                           for (const ShotDetail* detail : active)
                             applyDetail(shot, *detail, shutter.close, (*close)[detail->asset]);
                       });
}

// The assets posed at shutter open and (when the shutter is open for a while) close, then moved by
// their simulated flesh and displaced by the details, each stage timed.
void poseWithFleshAndDetails(const Shot& shot, const std::vector<std::unique_ptr<shotfile::FleshRun>>& fleshRuns,
                             int frameNumber, const ShutterTimes& shutter, PosedAssets& open,
                             std::optional<PosedAssets>& close, FrameBuildTimes& t) {
  {
    const StageClock clock(&t.rigSeconds);
    // At shutter close only what moves is posed again; the two poses are independent.
    tbb::parallel_invoke([&] { open = poseAssets(shot, shutter.open, StillAssets::Posed); },
                         [&] {
                           if (shutter.blurred()) close = poseAssets(shot, shutter.close, StillAssets::Skipped);
                         });
  }
  {
    const StageClock clock(&t.fleshSeconds);
    applyFleshes(shot, fleshRuns, shutter, open, close);
  }
  const StageClock clock(&t.detailSeconds);
  applyDetails(shot, frameNumber, shutter, open, close);
}

// Lays each liquid tear's wet trail on the skin posed at open and swells the lacrimal strip near its
// source with its meniscus (at shutter open and close).
void wetPosedSkin(const Shot& shot, std::vector<shotfile::LiquidTearShutter>& runs, PosedAssets& open,
                  std::optional<PosedAssets>& close) {
  for (size_t i = 0; i < shot.liquidTears.size(); ++i) {
    const ShotLiquidTear& tear = shot.liquidTears[i];
    shotfile::layLiquidTearFilm(tear, open[tear.asset], runs[i]);
    if (tear.meniscusPrimitive < 0 || open[tear.asset].empty()) continue;
    if (close) {
      // A still asset is not posed again at close; its meniscus still fills, so it gets its own copy.
      if ((*close)[tear.asset].empty()) (*close)[tear.asset] = open[tear.asset];
      shotfile::swellLiquidTearMeniscus(tear, runs[i].meniscusClose, (*close)[tear.asset]);
    }
    shotfile::swellLiquidTearMeniscus(tear, runs[i].meniscusOpen, open[tear.asset]);
  }
}

// The renderer camera at a time: keyed look-at cameras are placed again, the rest as loaded.
Camera cameraAt(const ShotCamera& shotCamera, double frame) {
  Camera camera = shotCamera.camera;
  if (shotCamera.kind != ShotCamera::Kind::LookAt || !shotCamera.animated()) return camera;
  const Vec3 position = shotCamera.animatedPosition.at(frame);
  const Vec3 lookAt = shotCamera.animatedLookAt.at(frame);
  if (const auto m = shotfile::lookAtCameraToWorld(position, lookAt, shotCamera.up)) camera.cameraToWorld = *m;
  if (!shotCamera.focusDistance) camera.focusDistance = (lookAt - position).norm();
  return camera;
}

// The lights (keyed centres and intensities) and the camera (at open and, when it moves, close).
void addLightsAndCamera(const Shot& shot, int frameNumber, const ShutterTimes& shutter, Frame& frame) {
  for (const ShotLight& light : shot.lights) frame.lights.push_back(light.at(frameNumber));
  if (shot.environment) frame.environment = shot.environment->map;
  frame.uniformBackground = shot.background;
  frame.camera = cameraAt(shot.camera, shutter.open);
  if (shutter.blurred() && shot.camera.animated()) {
    const Camera atClose = cameraAt(shot.camera, shutter.close);
    if (atClose.cameraToWorld.matrix() != frame.camera.cameraToWorld.matrix())
      frame.camera.cameraToWorldAtClose = atClose.cameraToWorld;
  }
}

using shotfile::LiquidTearKeeper;
using LiquidTearKeepers = std::vector<std::unique_ptr<LiquidTearKeeper>>;

// Simulates each liquid tear over the shutter (no posed asset needed).
std::vector<shotfile::LiquidTearShutter> simulateLiquidTears(const LiquidTearKeepers& tears, const ShutterTimes& shutter) {
  std::vector<shotfile::LiquidTearShutter> shutters;
  for (const std::unique_ptr<LiquidTearKeeper>& tear : tears)
    shutters.push_back(shotfile::simulateLiquidTearShutter(*tear, shutter.open, shutter.close));
  return shutters;
}

}  // namespace

// What the builder advances from frame to frame, one entry per liquid tear, flesh and SPH liquid
// of the shot.
struct FrameBuilder::Simulations {
  LiquidTearKeepers liquidTears;
  std::vector<std::unique_ptr<shotfile::FleshRun>> flesh;  // null: not resolved
  std::vector<std::unique_ptr<shotfile::SphRun>> sph;
};

FrameBuilder::FrameBuilder(const Shot& shot) : shot_(shot), simulations_(std::make_unique<Simulations>()) {
  for (const ShotLiquidTear& tear : shot.liquidTears)
    simulations_->liquidTears.push_back(std::make_unique<LiquidTearKeeper>(shot, tear));
  for (const ShotFlesh& flesh : shot.flesh)
    simulations_->flesh.push_back(flesh.tetVolume ? std::make_unique<shotfile::FleshRun>(shot, flesh) : nullptr);
  for (const ShotSph& liquid : shot.sph) simulations_->sph.push_back(std::make_unique<shotfile::SphRun>(shot, liquid));
}

FrameBuilder::~FrameBuilder() = default;

LiquidTearState FrameBuilder::liquidTearStateAt(size_t tear, double frame) {
  LiquidTearKeeper& keeper = *simulations_->liquidTears.at(tear);
  LiquidTearRun run = keeper.runFor(frame);
  run.advanceTo(frame);
  keeper.keep(run);
  return run.state(frame);
}

std::shared_ptr<const LiquidTearCourse> FrameBuilder::liquidTearCourseAt(size_t tear, double frame) {
  return lacrima::liquidTearCourseAt(shot_, shot_.liquidTears.at(tear), liquidTearCourses(tear), frame);
}

const LiquidTearCourses& FrameBuilder::liquidTearCourses(size_t tear) const {
  return simulations_->liquidTears.at(tear)->courses();
}

Frame FrameBuilder::build(int frameNumber, FrameBuildTimes* times) {
  const Shot& shot = shot_;
  FrameBuildTimes unused;
  FrameBuildTimes& t = times ? *times : unused;
  t = {};
  const StageClock total(&t.totalSeconds);
  if (frameNumber < shot.frameStart || frameNumber > shot.frameEnd)
    throw InputError(fmt::format("{}: frame {} is outside the shot's frame range {}-{}", shot.path.string(),
                                 frameNumber, shot.frameStart, shot.frameEnd));
  for (const ShotAsset& asset : shot.assets) checkLoaded(shot, asset);
  ShutterTimes shutter{double(frameNumber), double(frameNumber)};
  if (shot.shutter) shutter = {frameNumber + shot.shutter->first, frameNumber + shot.shutter->second};

  Frame frame;
  frame.materials = shot.frameMaterials();
  PosedAssets open;
  std::optional<PosedAssets> close;
  std::vector<shotfile::LiquidTearShutter> liquidRuns;
  // The liquid tears' simulation needs no posed asset: it runs beside the posing, whose flesh keeps
  // one core only partly busy (their clocks overlap; `totalSeconds` is the wall time).
  tbb::parallel_invoke([&] { poseWithFleshAndDetails(shot, simulations_->flesh, frameNumber, shutter, open, close, t); },
                       [&] {
                         const StageClock clock(&t.liquidSimulationSeconds);
                         liquidRuns = simulateLiquidTears(simulations_->liquidTears, shutter);
                       });
  {
    const StageClock clock(&t.liquidSeconds);
    wetPosedSkin(shot, liquidRuns, open, close);
  }
  const PosedAssets* closePtr = close ? &*close : nullptr;
  {
    const StageClock clock(&t.otherSeconds);
    for (size_t a = 0; a < shot.assets.size(); ++a) addAssetMeshes(shot, a, open, closePtr, frame);
    for (const ShotShape& shape : shot.shapes) addShape(shape, shutter, open, closePtr, frame);
  }
  {
    const StageClock clock(&t.eyeSeconds);
    shotfile::addEyes(shot, open, closePtr, frame);
  }
  {
    const StageClock clock(&t.otherSeconds);
    for (const ShotTear& tear : shot.tears) addTear(shot, tear, frameNumber, shutter, frame);
    for (const ShotSheddingTear& tear : shot.sheddingTears)
      addSheddingTear(shot, tear, frameNumber, shutter, open, closePtr, frame);
  }
  {
    const StageClock clock(&t.liquidSeconds);
    for (size_t i = 0; i < shot.liquidTears.size(); ++i) {
      const ShotLiquidTear& tear = shot.liquidTears[i];
      shotfile::addLiquidTear(tear, liquidRuns[i], open[tear.asset], closePtr ? &(*closePtr)[tear.asset] : nullptr,
                              assetMeshIndex(shot, open, tear.asset, tear.sourcePoint.primitive), frame);
    }
  }

  {
    const StageClock clock(&t.liquidSeconds);
    shotfile::addSphLiquids(shot, simulations_->sph, shutter.open, shutter.close, frame);
  }

  const StageClock clock(&t.otherSeconds);
  addLightsAndCamera(shot, frameNumber, shutter, frame);
  frame.settings = renderSettingsAt(shot, frameNumber);
  return frame;
}

Frame buildFrame(const Shot& shot, int frameNumber) { return FrameBuilder(shot).build(frameNumber); }

}  // namespace lacrima
