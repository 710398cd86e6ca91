#include "embree_scene.hpp"

#include <fmt/format.h>

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "lacrima/geometry/shapes.hpp"

namespace lacrima {

namespace {

void reportEmbreeError(void*, RTCError code, const char* message) {
  // Embree errors here are programming errors (bad buffers), not user input: fail loudly.
  throw std::runtime_error(fmt::format("Embree error {}: {}", int(code), message ? message : ""));
}

RTCRay makeRay(const Vec3& origin, const Vec3& direction, float tfar) {
  RTCRay ray;
  ray.org_x = origin.x();
  ray.org_y = origin.y();
  ray.org_z = origin.z();
  ray.tnear = 0.0f;
  ray.dir_x = direction.x();
  ray.dir_y = direction.y();
  ray.dir_z = direction.z();
  ray.time = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

}  // namespace

EmbreeScene::EmbreeScene(const Frame& frame, int threads) : frame_(frame) {
  const std::string config = threads > 0 ? fmt::format("threads={}", threads) : std::string();
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw std::runtime_error("could not create the Embree device");
  rtcSetDeviceErrorFunction(device_, reportEmbreeError, nullptr);
  scene_ = rtcNewScene(device_);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
  // Robust traversal: rays grazing shared edges of the face mesh must not slip through.
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);

  for (uint32_t i = 0; i < frame.meshes.size(); ++i) addMesh(frame.meshes[i].mesh, Kind::Mesh, i);
  for (uint32_t i = 0; i < frame.spheres.size(); ++i)
    addSphere(frame.spheres[i].center, frame.spheres[i].radius, Kind::Sphere, i);
  lightMeshes_.reserve(frame.lights.size());
  for (uint32_t i = 0; i < frame.lights.size(); ++i) {
    const AreaLight& light = frame.lights[i];
    if (light.shape == AreaLight::Shape::Rectangle) {
      lightMeshes_.push_back(makeRectangle(light.center, light.edgeU, light.edgeV));
      addMesh(lightMeshes_.back(), Kind::RectLight, i);
    } else {
      addSphere(light.center, light.radius, Kind::SphereLight, i);
    }
  }
  rtcCommitScene(scene_);
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeScene::addMesh(const TriangleMesh& mesh, Kind kind, uint32_t index) {
  if (mesh.triangleCount() == 0) return;  // nothing to hit
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertexCount()));
  std::memcpy(vertices, mesh.positions.data(), mesh.vertexCount() * 3 * sizeof(float));
  auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), mesh.triangleCount()));
  std::memcpy(triangles, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  recordGeometry(id, kind, index);
}

void EmbreeScene::addSphere(const Vec3& center, float radius, Kind kind, uint32_t index) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* point = static_cast<float*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
  point[0] = center.x();
  point[1] = center.y();
  point[2] = center.z();
  point[3] = radius;
  rtcCommitGeometry(geometry);
  const unsigned id = rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  recordGeometry(id, kind, index);
}

void EmbreeScene::recordGeometry(unsigned geometryId, Kind kind, uint32_t index) {
  if (records_.size() <= geometryId) records_.resize(geometryId + 1);
  records_[geometryId] = {kind, index};
}

void EmbreeScene::surfaceOfMesh(const TriangleMesh& mesh, const RTCHit& rtcHit, SurfaceHit& hit) const {
  const uint32_t* tri = &mesh.indices[3 * size_t(rtcHit.primID)];
  const Vec3& p0 = mesh.positions[tri[0]];
  const Vec3& p1 = mesh.positions[tri[1]];
  const Vec3& p2 = mesh.positions[tri[2]];
  const float u = rtcHit.u, v = rtcHit.v, w = 1.0f - u - v;
  // Barycentric position is more precise than origin + t * direction far from the origin.
  hit.position = w * p0 + u * p1 + v * p2;
  hit.geometricNormal = (p1 - p0).cross(p2 - p0).normalized();
  if (!mesh.normals.empty()) {
    const Vec3 n = w * mesh.normals[tri[0]] + u * mesh.normals[tri[1]] + v * mesh.normals[tri[2]];
    const float length = n.norm();
    hit.shadingNormal = length > 1e-8f ? Vec3(n / length) : hit.geometricNormal;
  } else {
    hit.shadingNormal = hit.geometricNormal;
  }
}

bool EmbreeScene::intersect(const Ray& ray, SurfaceHit& hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  rayHit.ray = makeRay(ray.origin, ray.direction, std::numeric_limits<float>::infinity());
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

  const GeometryRecord& record = records_[rayHit.hit.geomID];
  hit.distance = rayHit.ray.tfar;
  hit.lightIndex = -1;
  switch (record.kind) {
    case Kind::Mesh: {
      const MeshInstance& instance = frame_.meshes[record.index];
      surfaceOfMesh(instance.mesh, rayHit.hit, hit);
      hit.materialId = instance.materialId;
      break;
    }
    case Kind::RectLight:
      surfaceOfMesh(lightMeshes_[record.index], rayHit.hit, hit);
      hit.lightIndex = int(record.index);
      break;
    case Kind::Sphere:
    case Kind::SphereLight: {
      const bool isLight = record.kind == Kind::SphereLight;
      const Vec3 center = isLight ? frame_.lights[record.index].center : frame_.spheres[record.index].center;
      const float radius = isLight ? frame_.lights[record.index].radius : frame_.spheres[record.index].radius;
      const Vec3 approx = ray.origin + hit.distance * ray.direction;
      const Vec3 normal = (approx - center).normalized();
      hit.position = center + radius * normal;  // reproject onto the exact surface
      hit.geometricNormal = normal;
      hit.shadingNormal = normal;
      if (isLight) hit.lightIndex = int(record.index);
      else hit.materialId = frame_.spheres[record.index].materialId;
      break;
    }
  }
  return true;
}

bool EmbreeScene::occluded(const Vec3& origin, const Vec3& direction, float maxDistance) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = makeRay(origin, direction, maxDistance);
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace lacrima
