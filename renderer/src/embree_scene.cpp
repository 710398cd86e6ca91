#include "embree_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/materials/material.hpp"

namespace lacrima {

namespace {

// Hits interpolate MeshInstance::wetness per vertex: it must be empty or one value per vertex.
void checkWetness(const MeshInstance& instance) {
  if (!instance.wetness.empty() && instance.wetness.size() != instance.mesh.vertexCount())
    throw std::invalid_argument(fmt::format("mesh '{}': {} wetness values for {} vertices", instance.mesh.name,
                                            instance.wetness.size(), instance.mesh.vertexCount()));
}

void reportEmbreeError(void*, RTCError code, const char* message) {
  // Embree errors here are programming errors (bad buffers), not user input: fail loudly.
  throw std::runtime_error(fmt::format("Embree error {}: {}", int(code), message ? message : ""));
}

RTCRay makeRay(const Vec3& origin, const Vec3& direction, float tfar, float time, float tnear = 0.0f) {
  RTCRay ray;
  ray.org_x = origin.x();
  ray.org_y = origin.y();
  ray.org_z = origin.z();
  ray.tnear = tnear;
  ray.dir_x = direction.x();
  ray.dir_y = direction.y();
  ray.dir_z = direction.z();
  ray.time = time;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

// The uv at barycentrics (w, u, v) and the triangle's uv tangents: dP/du and dP/dv solve
// dp1 = du1 dpdu + dv1 dpdv, dp2 = du2 dpdu + dv2 dpdv (pbrt-v4 Triangle::InteractionFromIntersection).
void uvOfTriangle(const TriangleMesh& mesh, const uint32_t* tri, const std::array<Vec3, 3>& p, float w, float u,
                  float v, SurfaceHit& hit) {
  const Vec2 &uv0 = mesh.uvs[tri[0]], &uv1 = mesh.uvs[tri[1]], &uv2 = mesh.uvs[tri[2]];
  hit.uv = w * uv0 + u * uv1 + v * uv2;
  const Vec2 duv1 = uv1 - uv0, duv2 = uv2 - uv0;
  const Vec3 dp1 = p[1] - p[0], dp2 = p[2] - p[0];
  const float determinant = duv1.x() * duv2.y() - duv1.y() * duv2.x();
  if (!(std::abs(determinant) > 1e-20f)) {
    hit.dpdu = hit.dpdv = Vec3::Zero();
    return;
  }
  const float inverse = 1.0f / determinant;
  hit.dpdu = (duv2.y() * dp1 - duv1.y() * dp2) * inverse;
  hit.dpdv = (duv1.x() * dp2 - duv2.x() * dp1) * inverse;
}

}  // namespace

EmbreeScene::EmbreeScene(const Frame& frame, int threads, SceneFollowReport* report)
    : frame_(&frame), threads_(threads) {
  const std::string config = threads > 0 ? fmt::format("threads={}", threads) : std::string();
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("could not create the Embree device");
  rtcSetDeviceErrorFunction(device_, reportEmbreeError, nullptr);
  scene_ = rtcNewScene(device_);
  // LOW selects Embree's two-level BVH, the only one that honours a per-geometry REFIT quality;
  // each mesh's own BVH is still a full SAH build (see addMesh).
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);
  // Robust traversal: rays grazing shared edges of the face mesh must not slip through.
  // The context filter lets crossingsOf see every hit of one traversal; other queries pass none.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);

  dielectricScene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(dielectricScene_, RTC_BUILD_QUALITY_LOW);
  rtcSetSceneFlags(dielectricScene_, RTC_SCENE_FLAG_ROBUST);
  const SceneFollowReport built = follow(frame);  // nothing to keep yet: every geometry is attached, in the frame's order
  if (report) *report = built;
}

EmbreeScene::~EmbreeScene() {
  if (dielectricScene_) rtcReleaseScene(dielectricScene_);
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

unsigned EmbreeScene::addMesh(const TriangleMesh& mesh, Kind kind, uint32_t index,
                              const std::vector<Vec3>* positionsAtClose) {
  if (mesh.triangleCount() == 0) return kNoGeometry;  // nothing to hit
  if (positionsAtClose && positionsAtClose->size() != mesh.vertexCount())
    throw std::invalid_argument(fmt::format("mesh '{}': {} positions at shutter close for {} vertices", mesh.name,
                                            positionsAtClose->size(), mesh.vertexCount()));
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  // REFIT: the first commit is a full SAH build, later vertex-only changes refit that BVH.
  // Still meshes are never recommitted, so they cost nothing per frame either way. (Embree
  // rebuilds motion-blurred meshes, two time steps, in full on every change: no MB refit.)
  // Measured with Debian's Embree 3.13.5 (lacrima bench, and a bare Embree probe on a 98k and
  // a 720k triangle grid): a REFIT recommit takes as long as the first build, so the saving
  // per frame is the device and buffers, not the BVH. Kept: it is the documented API, and an
  // Embree that refits needs no change here.
  rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_REFIT);
  // A moving mesh has two time steps (shutter open and close); Embree interpolates linearly.
  const std::vector<Vec3>* steps[2] = {&mesh.positions, positionsAtClose};
  const unsigned stepCount = positionsAtClose ? 2 : 1;
  rtcSetGeometryTimeStepCount(geometry, stepCount);
  for (unsigned step = 0; step < stepCount; ++step) {
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertexCount()));
    std::memcpy(vertices, steps[step]->data(), mesh.vertexCount() * 3 * sizeof(float));
  }
  auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangleCount()));
  std::memcpy(triangles, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);  // the scene keeps it alive
  recordGeometry(id, {kind, index, geometry, stepCount, mesh.vertexCount(), mesh.triangleCount(), false, mesh.name});
  return id;
}

unsigned EmbreeScene::addSphere(const Vec3& center, float radius, Kind kind, uint32_t index, const Vec3* centerAtClose) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  const Vec3* steps[2] = {&center, centerAtClose};
  const unsigned stepCount = centerAtClose ? 2 : 1;
  rtcSetGeometryTimeStepCount(geometry, stepCount);
  for (unsigned step = 0; step < stepCount; ++step) {
    auto* point = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    point[0] = steps[step]->x();
    point[1] = steps[step]->y();
    point[2] = steps[step]->z();
    point[3] = radius;
  }
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);  // the scene keeps it alive
  recordGeometry(id, {kind, index, geometry, stepCount, 1, 0, false, ""});  // spheres and lights have no name
  return id;
}

void EmbreeScene::recordGeometry(unsigned geometryId, const GeometryRecord& record) {
  if (records_.size() <= geometryId) records_.resize(geometryId + 1);
  records_[geometryId] = record;
}

bool EmbreeScene::isDielectric(const Frame& frame, uint32_t materialId) {
  return materialId < frame.materials.size() && dielectricMedium(frame.materials[materialId].params).has_value();
}

void EmbreeScene::attachToDielectricScene(unsigned geometryId, uint32_t materialId) {
  if (geometryId == kNoGeometry || !isDielectric(*frame_, materialId)) return;
  rtcAttachGeometryByID(dielectricScene_, records_[geometryId].geometry, geometryId);
  records_[geometryId].dielectric = true;
}

bool EmbreeScene::canRefitTo(const Frame& frame, int threads) const {
  if (!canFollow(threads) || frame.meshes.size() != meshGeometry_.size() ||
      frame.spheres.size() != sphereGeometry_.size() || frame.lights.size() != lightGeometry_.size())
    return false;
  // follow() keeps a geometry only where it passes the same checks as here, so comparing what it
  // would keep with what the scene holds, index by index, says whether it keeps everything.
  return keptMeshGeometries(frame) == meshGeometry_ && keptSphereGeometries(frame) == sphereGeometry_ &&
         keptLightGeometries(frame) == lightGeometry_;
}

// The dielectric scene holds the geometries of dielectric materials: a kept geometry must stay so.
bool EmbreeScene::keepsDielectric(const Frame& frame, unsigned geometryId, uint32_t materialId) const {
  return records_[geometryId].dielectric == isDielectric(frame, materialId);
}

std::vector<unsigned> EmbreeScene::keptMeshGeometries(const Frame& frame) const {
  // The previous frame's mesh geometries by name, in its order: a mesh takes the first one of its
  // name that nothing took yet and has its layout, so meshes that come and go (a bead born, a drop
  // fallen) leave the others' geometries in place whatever their indices become.
  std::unordered_map<std::string_view, std::vector<unsigned>> byName;
  for (unsigned id : meshGeometry_)
    if (id != kNoGeometry) byName[records_[id].name].push_back(id);
  std::vector<bool> taken(records_.size(), false);
  std::vector<unsigned> kept(frame.meshes.size(), kReplace);
  for (size_t i = 0; i < frame.meshes.size(); ++i) {
    const MeshInstance& instance = frame.meshes[i];
    if (instance.mesh.triangleCount() == 0) {
      kept[i] = kNoGeometry;
      continue;
    }
    const auto candidates = byName.find(instance.mesh.name);
    if (candidates == byName.end()) continue;
    for (unsigned id : candidates->second)
      if (!taken[id] && meshHasLayout(instance, id) && keepsDielectric(frame, id, instance.materialId)) {
        kept[i] = id;
        taken[id] = true;
        break;
      }
  }
  return kept;
}

std::vector<unsigned> EmbreeScene::keptSphereGeometries(const Frame& frame) const {
  std::vector<unsigned> kept(frame.spheres.size(), kReplace);
  for (size_t i = 0; i < frame.spheres.size() && i < sphereGeometry_.size(); ++i) {
    const Sphere& sphere = frame.spheres[i];
    const unsigned id = sphereGeometry_[i];
    if (sphereHasLayout(sphere.centerAtClose.has_value(), id) && keepsDielectric(frame, id, sphere.materialId))
      kept[i] = id;
  }
  return kept;
}

std::vector<unsigned> EmbreeScene::keptLightGeometries(const Frame& frame) const {
  std::vector<unsigned> kept(frame.lights.size(), kReplace);
  for (size_t i = 0; i < frame.lights.size() && i < lightGeometry_.size(); ++i) {
    const bool isRectangle = frame.lights[i].shape == AreaLight::Shape::Rectangle;
    if (isRectangle == (records_[lightGeometry_[i]].kind == Kind::RectLight)) kept[i] = lightGeometry_[i];
  }
  return kept;
}

bool EmbreeScene::meshHasLayout(const MeshInstance& instance, unsigned geometryId) const {
  const TriangleMesh& mesh = instance.mesh;
  if (geometryId == kNoGeometry) return mesh.triangleCount() == 0;
  const GeometryRecord& record = records_[geometryId];
  if (record.vertexCount != mesh.vertexCount() || record.triangleCount != mesh.triangleCount() ||
      record.timeSteps != (instance.moves() ? 2u : 1u))
    return false;
  if (instance.moves() && instance.positionsAtClose.size() != mesh.vertexCount()) return false;  // rebuild reports it
  // The triangles Embree holds, compared in place: no copy of the previous frame's indices.
  const void* indices = rtcGetGeometryBufferData(record.geometry, RTC_BUFFER_TYPE_INDEX, 0);
  return std::memcmp(indices, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t)) == 0;
}

bool EmbreeScene::sphereHasLayout(bool moves, unsigned geometryId) const {
  return records_[geometryId].kind == Kind::Sphere && records_[geometryId].timeSteps == (moves ? 2u : 1u);
}

namespace {

// Copies `source` into a geometry's vertex buffer; false (and no Embree update) when unchanged.
bool writeVertexBuffer(RTCGeometry geometry, unsigned slot, const void* source, size_t bytes) {
  void* buffer = rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, slot);
  if (std::memcmp(buffer, source, bytes) == 0) return false;
  std::memcpy(buffer, source, bytes);
  rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, slot);
  return true;
}

}  // namespace

SceneFollowReport EmbreeScene::follow(const Frame& frame) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<unsigned> keptMeshes = keptMeshGeometries(frame), keptSpheres = keptSphereGeometries(frame),
                        keptLights = keptLightGeometries(frame);
  std::vector<unsigned> kept = keptMeshes;
  kept.insert(kept.end(), keptSpheres.begin(), keptSpheres.end());
  kept.insert(kept.end(), keptLights.begin(), keptLights.end());
  SceneFollowReport report;
  report.detached = detachAllBut(kept);  // first, so that their ids are free for the new ones
  frame_ = &frame;
  followMeshes(frame, keptMeshes, report);
  followSpheres(frame, keptSpheres, report);
  followLights(frame, keptLights, report);
  const auto uploaded = std::chrono::steady_clock::now();
  commitChangedGeometries();
  rtcCommitScene(scene_);
  rtcCommitScene(dielectricScene_);
  const auto committed = std::chrono::steady_clock::now();
  report.uploadSeconds = std::chrono::duration<double>(uploaded - start).count();
  report.commitSeconds = std::chrono::duration<double>(committed - uploaded).count();
  return report;
}

size_t EmbreeScene::detachAllBut(const std::vector<unsigned>& kept) {
  std::vector<bool> keep(records_.size(), false);
  for (unsigned id : kept)
    if (id < records_.size()) keep[id] = true;
  size_t detached = 0;
  for (unsigned id = 0; id < records_.size(); ++id) {
    GeometryRecord& record = records_[id];
    if (!record.geometry || keep[id]) continue;
    if (record.dielectric) rtcDetachGeometry(dielectricScene_, id);
    rtcDetachGeometry(scene_, id);  // the scene held the last reference: Embree frees it
    record = GeometryRecord{};
    ++detached;
  }
  return detached;
}

void EmbreeScene::followMeshes(const Frame& frame, const std::vector<unsigned>& kept, SceneFollowReport& report) {
  meshGeometry_.assign(frame.meshes.size(), kNoGeometry);
  for (uint32_t i = 0; i < frame.meshes.size(); ++i) {
    const MeshInstance& instance = frame.meshes[i];
    checkWetness(instance);
    const std::vector<Vec3>* positionsAtClose = instance.moves() ? &instance.positionsAtClose : nullptr;
    if (kept[i] == kReplace) {
      meshGeometry_[i] = addMesh(instance.mesh, Kind::Mesh, i, positionsAtClose);
      attachToDielectricScene(meshGeometry_[i], instance.materialId);
      ++report.attached;
      continue;
    }
    meshGeometry_[i] = kept[i];
    if (kept[i] == kNoGeometry) continue;
    records_[kept[i]].index = i;  // the frame's meshes may have moved up or down the list
    moveMesh(instance.mesh, positionsAtClose, kept[i]);
  }
}

void EmbreeScene::followSpheres(const Frame& frame, const std::vector<unsigned>& kept, SceneFollowReport& report) {
  sphereGeometry_.assign(frame.spheres.size(), kNoGeometry);
  for (uint32_t i = 0; i < frame.spheres.size(); ++i) {
    const Sphere& sphere = frame.spheres[i];
    const Vec3* centerAtClose = sphere.centerAtClose ? &*sphere.centerAtClose : nullptr;
    if (kept[i] == kReplace) {
      sphereGeometry_[i] = addSphere(sphere.center, sphere.radius, Kind::Sphere, i, centerAtClose);
      attachToDielectricScene(sphereGeometry_[i], sphere.materialId);
      ++report.attached;
    } else {
      sphereGeometry_[i] = kept[i];
      moveSphere(sphere.center, sphere.radius, centerAtClose, kept[i]);
    }
  }
}

void EmbreeScene::followLights(const Frame& frame, const std::vector<unsigned>& kept, SceneFollowReport& report) {
  lightGeometry_.assign(frame.lights.size(), kNoGeometry);
  lightMeshes_.resize(frame.lights.size());
  for (uint32_t i = 0; i < frame.lights.size(); ++i) {
    const AreaLight& light = frame.lights[i];
    const bool isRectangle = light.shape == AreaLight::Shape::Rectangle;
    lightMeshes_[i].mesh = isRectangle ? makeRectangle(light.center, light.edgeU, light.edgeV) : TriangleMesh{};
    if (kept[i] == kReplace) {
      lightGeometry_[i] = isRectangle ? addMesh(lightMeshes_[i].mesh, Kind::RectLight, i, nullptr)
                                      : addSphere(light.center, light.radius, Kind::SphereLight, i, nullptr);
      ++report.attached;
    } else {
      lightGeometry_[i] = kept[i];
      if (isRectangle)
        moveMesh(lightMeshes_[i].mesh, nullptr, kept[i]);
      else
        moveSphere(light.center, light.radius, nullptr, kept[i]);
    }
  }
}

void EmbreeScene::commitChangedGeometries() {
  for (unsigned geometryId : changedGeometries_) rtcCommitGeometry(records_[geometryId].geometry);
  changedGeometries_.clear();
}

void EmbreeScene::moveMesh(const TriangleMesh& mesh, const std::vector<Vec3>* positionsAtClose, unsigned geometryId) {
  if (geometryId == kNoGeometry) return;
  const GeometryRecord& record = records_[geometryId];
  const size_t bytes = record.vertexCount * 3 * sizeof(float);
  bool changed = writeVertexBuffer(record.geometry, 0, mesh.positions.data(), bytes);
  if (positionsAtClose) changed |= writeVertexBuffer(record.geometry, 1, positionsAtClose->data(), bytes);
  // An uncommitted geometry keeps its BVH as it is: still meshes cost nothing.
  if (changed) changedGeometries_.push_back(geometryId);
}

void EmbreeScene::moveSphere(const Vec3& center, float radius, const Vec3* centerAtClose, unsigned geometryId) {
  const GeometryRecord& record = records_[geometryId];
  const Vec3* steps[2] = {&center, centerAtClose};
  bool changed = false;
  for (unsigned step = 0; step < record.timeSteps; ++step) {
    const float point[4] = {steps[step]->x(), steps[step]->y(), steps[step]->z(), radius};
    changed |= writeVertexBuffer(record.geometry, step, point, sizeof(point));
  }
  if (changed) changedGeometries_.push_back(geometryId);
}

void EmbreeScene::surfaceOfMesh(const MeshInstance& instance, float time, const uint32_t* tri, float u, float v,
                                SurfaceHit& hit) const {
  const TriangleMesh& mesh = instance.mesh;
  // Vertices at the ray's time, as Embree interpolated them (linear between the time steps).
  const auto positionAt = [&](uint32_t i) -> Vec3 {
    return instance.moves() ? Vec3((1.0f - time) * mesh.positions[i] + time * instance.positionsAtClose[i])
                            : mesh.positions[i];
  };
  const auto normalAt = [&](uint32_t i) -> Vec3 {
    return instance.normalsAtClose.empty() ? mesh.normals[i]
                                           : Vec3((1.0f - time) * mesh.normals[i] + time * instance.normalsAtClose[i]);
  };
  const Vec3 p0 = positionAt(tri[0]), p1 = positionAt(tri[1]), p2 = positionAt(tri[2]);
  const float w = 1.0f - u - v;
  // Barycentric position is more precise than origin + t * direction far from the origin.
  hit.position = w * p0 + u * p1 + v * p2;
  hit.geometricNormal = (p1 - p0).cross(p2 - p0).normalized();
  if (!mesh.normals.empty()) {
    const Vec3 n = w * normalAt(tri[0]) + u * normalAt(tri[1]) + v * normalAt(tri[2]);
    const float length = n.norm();
    hit.shadingNormal = length > 1e-8f ? Vec3(n / length) : hit.geometricNormal;
  } else {
    hit.shadingNormal = hit.geometricNormal;
  }
  const std::vector<float>& film = instance.wetness;
  hit.wetness = film.empty() ? 0.0f : w * film[tri[0]] + u * film[tri[1]] + v * film[tri[2]];
  hit.hasUv = !mesh.uvs.empty() && frame_->materials[instance.materialId].textures.any();
  if (hit.hasUv) uvOfTriangle(mesh, tri, {p0, p1, p2}, w, u, v, hit);
}

bool EmbreeScene::intersect(const Ray& ray, SurfaceHit& hit) const { return nearestHit(scene_, ray, hit); }

bool EmbreeScene::intersectDielectrics(const Ray& ray, SurfaceHit& hit) const {
  return nearestHit(dielectricScene_, ray, hit);
}

bool EmbreeScene::nearestHit(RTCScene scene, const Ray& ray, SurfaceHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  rayHit.ray = makeRay(ray.origin, ray.direction, ray.tfar, ray.time, ray.tnear);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hitAt(ray, {rayHit.ray.tfar, rayHit.hit.geomID, rayHit.hit.primID, Vec2(rayHit.hit.u, rayHit.hit.v)}, hit);
  return true;
}

void EmbreeScene::hitAt(const Ray& ray, const SurfaceCrossing& crossing, SurfaceHit& hit) const {
  const GeometryRecord& record = records_[crossing.geometryId];
  hit.distance = crossing.rayDistance;
  hit.rayDistance = crossing.rayDistance;
  hit.lightIndex = -1;
  hit.meshIndex = -1;
  hit.sphereIndex = -1;
  hit.geometryId = crossing.geometryId;
  hit.primitiveId = crossing.primitiveId;
  hit.barycentric = crossing.barycentric;
  const float u = crossing.barycentric.x(), v = crossing.barycentric.y();
  switch (record.kind) {
    case Kind::Mesh: {
      const MeshInstance& instance = frame_->meshes[record.index];
      surfaceOfMesh(instance, ray.time, &instance.mesh.indices[3 * size_t(crossing.primitiveId)], u, v, hit);
      hit.meshIndex = int(record.index);
      hit.materialId = instance.materialId;
      break;
    }
    case Kind::RectLight: {
      const TriangleMesh& mesh = lightMeshes_[record.index].mesh;
      surfaceOfMesh(lightMeshes_[record.index], 0.0f, &mesh.indices[3 * size_t(crossing.primitiveId)], u, v, hit);
      hit.lightIndex = int(record.index);
      break;
    }
    case Kind::Sphere:
    case Kind::SphereLight: {
      hit.wetness = 0.0f;
      hit.hasUv = false;
      const bool isLight = record.kind == Kind::SphereLight;
      if (!isLight) hit.sphereIndex = int(record.index);
      const Vec3 center = isLight ? frame_->lights[record.index].center : frame_->spheres[record.index].centerAt(ray.time);
      const float radius = isLight ? frame_->lights[record.index].radius : frame_->spheres[record.index].radius;
      const Vec3 approx = ray.origin + hit.distance * ray.direction;
      const Vec3 normal = (approx - center).normalized();
      hit.position = center + radius * normal;  // reproject onto the exact surface
      hit.geometricNormal = normal;
      hit.shadingNormal = normal;
      if (isLight) hit.lightIndex = int(record.index);
      else hit.materialId = frame_->spheres[record.index].materialId;
      break;
    }
  }
}

bool EmbreeScene::hasMaterial(unsigned geometryId, uint32_t materialId) const {
  const GeometryRecord& record = records_[geometryId];
  if (record.kind == Kind::Mesh) return frame_->meshes[record.index].materialId == materialId;
  return record.kind == Kind::Sphere && frame_->spheres[record.index].materialId == materialId;
}

namespace {

// An intersection context that carries what crossingsOf collects (Embree passes the context's
// address to the filter; the RTCIntersectContext must come first).
struct CrossingCollector {
  RTCIntersectContext context;
  const EmbreeScene* scene;
  uint32_t materialId;
  SurfaceCrossing* crossings;
  int capacity;
  int count;
};

bool nearerCrossing(const SurfaceCrossing& a, const SurfaceCrossing& b) {
  if (a.rayDistance != b.rayDistance) return a.rayDistance < b.rayDistance;
  return a.geometryId != b.geometryId ? a.geometryId < b.geometryId : a.primitiveId < b.primitiveId;
}

}  // namespace

void EmbreeScene::recordCrossing(const RTCFilterFunctionNArguments* arguments) {
  arguments->valid[0] = 0;  // reject every hit: the traversal goes on to the next
  auto* collector = reinterpret_cast<CrossingCollector*>(const_cast<RTCIntersectContext*>(arguments->context));
  const unsigned geometryId = RTCHitN_geomID(arguments->hit, arguments->N, 0);
  if (!collector->scene->hasMaterial(geometryId, collector->materialId)) return;
  const SurfaceCrossing crossing{RTCRayN_tfar(arguments->ray, arguments->N, 0), geometryId,
                                 RTCHitN_primID(arguments->hit, arguments->N, 0),
                                 Vec2(RTCHitN_u(arguments->hit, arguments->N, 0), RTCHitN_v(arguments->hit, arguments->N, 0))};
  if (collector->count < collector->capacity) {
    collector->crossings[collector->count++] = crossing;
    return;
  }
  // Full: the crossing replaces the farthest kept one if it is nearer.
  SurfaceCrossing* farthest = std::max_element(collector->crossings, collector->crossings + collector->count, nearerCrossing);
  if (nearerCrossing(crossing, *farthest)) *farthest = crossing;
}

int EmbreeScene::crossingsOf(const Ray& ray, uint32_t materialId, SurfaceCrossing* crossings, int capacity) const {
  constexpr int kCollected = 32;  // more than any probe chord crosses the skin; the nearest are kept
  std::array<SurfaceCrossing, kCollected> collected;
  CrossingCollector collector{{}, this, materialId, collected.data(), kCollected, 0};
  rtcInitIntersectContext(&collector.context);
  collector.context.filter = &EmbreeScene::recordCrossing;
  RTCRayHit rayHit;
  rayHit.ray = makeRay(ray.origin, ray.direction, ray.tfar, ray.time, ray.tnear);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &collector.context, &rayHit);
  std::sort(collected.begin(), collected.begin() + collector.count, nearerCrossing);
  int count = 0;
  for (int i = 0; i < collector.count && count < capacity; ++i) {
    // A crossing just past the previous one is that crossing again (a shared edge reports both
    // triangles), as a ray restarted just past each hit would skip it.
    if (count > 0 && collected[i].rayDistance < crossings[count - 1].rayDistance * (1.0f + 1e-5f)) continue;
    crossings[count++] = collected[i];
  }
  return count;
}

SurfacePatch EmbreeScene::patchOf(const SurfaceHit& hit, float time) const {
  const GeometryRecord& record = records_[hit.geometryId];
  if (record.kind == Kind::Sphere) {
    const Sphere& sphere = frame_->spheres[record.index];
    const Vec3d center = sphere.centerAt(time).cast<double>();
    return SurfacePatch::sphere(center, sphere.radius, (hit.position.cast<double>() - center).normalized(), hit.geometryId);
  }
  // A mesh triangle at the ray's time, as surfaceOfMesh interpolates it.
  const MeshInstance& instance = frame_->meshes[record.index];
  const TriangleMesh& mesh = instance.mesh;
  const uint32_t* tri = &mesh.indices[3 * size_t(hit.primitiveId)];
  const double t = time;
  const auto positionAt = [&](uint32_t i) -> Vec3d {
    const Vec3d open = mesh.positions[i].cast<double>();
    return instance.moves() ? Vec3d((1.0 - t) * open + t * instance.positionsAtClose[i].cast<double>()) : open;
  };
  const auto normalAt = [&](uint32_t i) -> Vec3d {
    const Vec3d open = mesh.normals[i].cast<double>();
    return instance.normalsAtClose.empty() ? open : Vec3d((1.0 - t) * open + t * instance.normalsAtClose[i].cast<double>());
  };
  SurfacePatch patch;
  patch.origin = positionAt(tri[0]);
  patch.edgeU = positionAt(tri[1]) - patch.origin;
  patch.edgeV = positionAt(tri[2]) - patch.origin;
  if (mesh.normals.empty()) {
    patch.normal = patch.edgeU.cross(patch.edgeV).normalized();  // flat: the normal does not vary
  } else {
    patch.normal = normalAt(tri[0]);
    patch.normalU = normalAt(tri[1]) - patch.normal;
    patch.normalV = normalAt(tri[2]) - patch.normal;
  }
  patch.uv = hit.barycentric.cast<double>();
  patch.surfaceId = hit.geometryId;
  return patch;
}

bool EmbreeScene::dielectricOnSegment(const Vec3& origin, const Vec3& direction, float maxDistance, float time) const {
  return anyHit(dielectricScene_, origin, direction, maxDistance, time);
}

bool EmbreeScene::occluded(const Vec3& origin, const Vec3& direction, float maxDistance, float time) const {
  return anyHit(scene_, origin, direction, maxDistance, time);
}

bool EmbreeScene::anyHit(RTCScene scene, const Vec3& origin, const Vec3& direction, float maxDistance, float time) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = makeRay(origin, direction, maxDistance, time);
  rtcOccluded1(scene, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace lacrima
