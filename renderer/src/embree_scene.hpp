#pragma once
// The Embree 3 scene of one Frame: triangle meshes, exact spheres, and the area lights as
// emitting geometry. Maps Embree's geometry ids back to Frame objects and computes the
// surface data the integrator needs.
#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct SurfaceHit {
  float distance = 0.0f;
  Vec3 position;
  Vec3 geometricNormal;  // unit; for meshes the winding normal, for spheres outward
  Vec3 shadingNormal;    // unit; interpolated vertex normal when the mesh has normals
  uint32_t materialId = 0;
  int lightIndex = -1;   // >= 0 when the surface is an area light (emits, does not reflect)
};

class EmbreeScene {
 public:
  EmbreeScene(const Frame& frame, int threads);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  bool intersect(const Ray& ray, SurfaceHit& hit) const;
  // True when anything blocks the segment origin + t * direction, 0 < t < maxDistance.
  // time: the shutter time of the path, as in Ray::time.
  bool occluded(const Vec3& origin, const Vec3& direction, float maxDistance, float time = 0.0f) const;

  RTCScene handle() const { return scene_; }

 private:
  enum class Kind : uint8_t { Mesh, Sphere, RectLight, SphereLight };
  struct GeometryRecord {
    Kind kind = Kind::Mesh;
    uint32_t index = 0;  // into frame meshes / spheres / lights
  };

  // positionsAtClose / centerAtClose: null for still geometry, else the shutter-close state.
  void addMesh(const TriangleMesh& mesh, Kind kind, uint32_t index, const std::vector<Vec3>* positionsAtClose);
  void addSphere(const Vec3& center, float radius, Kind kind, uint32_t index, const Vec3* centerAtClose);
  void recordGeometry(unsigned geometryId, Kind kind, uint32_t index);
  void surfaceOfMesh(const MeshInstance& instance, float time, const RTCHit& rtcHit, SurfaceHit& hit) const;

  const Frame& frame_;
  std::vector<MeshInstance> lightMeshes_;  // rectangle lights as two triangles
  std::vector<GeometryRecord> records_;    // indexed by Embree geomID
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace lacrima
