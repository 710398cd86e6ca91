#pragma once
// The Embree 3 scene of one Frame: triangle meshes, exact spheres, and the area lights as
// emitting geometry. Maps Embree's geometry ids back to Frame objects and computes the
// surface data the integrator needs.
#include <embree3/rtcore.h>

#include <cstdint>
#include <string>
#include <vector>

#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/frame.hpp"
#include "specular_manifold.hpp"

namespace lacrima {

struct SurfaceHit {
  float distance = 0.0f;     // from the path's segment start (the depth AOV; see traceToRealSurface)
  float rayDistance = 0.0f;  // Embree's t along the ray that found it, from that ray's origin
  Vec3 position;
  Vec3 geometricNormal;  // unit; for meshes the winding normal, for spheres outward
  Vec3 shadingNormal;    // unit; interpolated vertex normal when the mesh has normals
  uint32_t materialId = 0;
  int lightIndex = -1;   // >= 0 when the surface is an area light (emits, does not reflect)
  float wetness = 0.0f;  // film thickness (m) interpolated from MeshInstance::wetness; 0 = dry
  unsigned geometryId = 0;   // Embree's: which mesh, sphere or light
  int meshIndex = -1;        // the index in Frame::meshes of a mesh hit; -1 for spheres and lights
  int sphereIndex = -1;      // the index in Frame::spheres of a sphere hit; -1 otherwise
  unsigned primitiveId = 0;  // the triangle of a mesh
  Vec2 barycentric = Vec2::Zero();  // Embree's (u, v) on that triangle
  // Texture coordinates, for meshes with uvs and a textured material (hasUv; only textures read
  // them, so untextured hits, shadow walks and MNEE projections skip the work): uv interpolated
  // barycentrically, and the triangle's dP/du and dP/dv (zero when its uvs are degenerate), the
  // tangents of normal maps.
  bool hasUv = false;
  Vec2 uv = Vec2::Zero();
  Vec3 dpdu = Vec3::Zero();
  Vec3 dpdv = Vec3::Zero();
};

// Where a ray crosses a surface, as Embree reports it, before any hit set-up (crossingsOf).
struct SurfaceCrossing {
  float rayDistance = 0.0f;  // Embree's t from the ray's origin
  unsigned geometryId = 0;
  unsigned primitiveId = 0;
  Vec2 barycentric = Vec2::Zero();
};

// What one follow() did and spent: copying the changed vertices (and the buffers of added
// geometries) into Embree's buffers, then the commits (each changed geometry's BVH, the top level).
struct SceneFollowReport {
  double uploadSeconds = 0.0;
  double commitSeconds = 0.0;
  size_t attached = 0;  // geometries added: new meshes, spheres or lights, or ones whose layout changed
  size_t detached = 0;  // geometries removed: gone, or replaced by an attached one
  bool keptLayout() const { return attached == 0 && detached == 0; }
};

// One Embree device and scene that can follow the frames of a shot. The BVH is two-level
// (scene build quality LOW): one BVH per geometry under a top-level BVH, which is what lets
// Embree refit a single geometry's BVH (geometry build quality REFIT) instead of rebuilding it.
class EmbreeScene {
 public:
  // report (optional): what building the scene for `frame` attached (every geometry).
  EmbreeScene(const Frame& frame, int threads, SceneFollowReport* report = nullptr);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // True when follow() can take a frame rendered with `threads` threads (another thread count
  // needs another Embree device).
  bool canFollow(int threads) const { return threads == threads_; }
  // True when `frame` has this scene's geometry layout: the same meshes (vertex and triangle
  // counts, identical indices), spheres and lights (count and shape), the same number of time
  // steps for each, and the same thread count. Then follow() keeps every geometry (a refit).
  bool canRefitTo(const Frame& frame, int threads) const;
  // Moves the scene to `frame` (which must pass canFollow), rebuilding only what changed its
  // topology: a mesh of the same name and layout as one of the previous frame keeps its geometry
  // (its vertices moved, its BVH refitted), as do spheres and lights of the same shape and time
  // steps at the same index; the others are attached anew and the geometries nothing took are
  // detached. Embree then rebuilds only the changed geometries' BVHs and the small top level. Hit
  // lookups read `frame` from now on; it must outlive its use here.
  SceneFollowReport follow(const Frame& frame);

  bool intersect(const Ray& ray, SurfaceHit& hit) const;
  // Every crossing of a mesh or sphere of material `materialId` along the ray (tnear < t < tfar),
  // found in one traversal (an intersection filter that records each hit and rejects it, so
  // Embree goes on: Cycles' "local" intersection for subsurface does the same). Sorted by
  // distance; crossings within a relative 1e-5 of the previous one are taken as the same
  // crossing reported twice (a ray through a shared edge); the nearest `capacity` are kept.
  // Returns how many were written to `crossings`.
  int crossingsOf(const Ray& ray, uint32_t materialId, SurfaceCrossing* crossings, int capacity) const;
  // The hit at a crossing that crossingsOf found along `ray`, as intersect would have set it up.
  void hitAt(const Ray& ray, const SurfaceCrossing& crossing, SurfaceHit& hit) const;
  // The nearest hit among the dielectric surfaces alone (meshes and spheres whose material is a
  // dielectric medium: water, cornea), ignoring everything else. A second, small BVH holds them,
  // so the query costs a fraction of intersect's for a ray that starts on the large skin mesh.
  bool intersectDielectrics(const Ray& ray, SurfaceHit& hit) const;
  // True when a dielectric surface lies on the segment origin + t * direction, 0 < t < maxDistance
  // (the same small BVH, any hit, no hit set-up).
  bool dielectricOnSegment(const Vec3& origin, const Vec3& direction, float maxDistance, float time) const;
  // True when anything blocks the segment origin + t * direction, 0 < t < maxDistance.
  // time: the shutter time of the path, as in Ray::time.
  bool occluded(const Vec3& origin, const Vec3& direction, float maxDistance, float time = 0.0f) const;

  // The local parametrisation of the surface at `hit` (a mesh or a sphere, not a light) at
  // shutter time `time`, for manifold next-event estimation (specular_manifold.hpp). The
  // parameters are Embree's barycentrics; surfaceId is hit.geometryId.
  SurfacePatch patchOf(const SurfaceHit& hit, float time) const;

  RTCScene handle() const { return scene_; }

 private:
  enum class Kind : uint8_t { Mesh, Sphere, RectLight, SphereLight };
  struct GeometryRecord {
    Kind kind = Kind::Mesh;
    uint32_t index = 0;  // into frame meshes / spheres / lights
    RTCGeometry geometry = nullptr;  // owned by scene_
    unsigned timeSteps = 1;
    size_t vertexCount = 0;
    size_t triangleCount = 0;
    bool dielectric = false;  // also in dielectricScene_
    std::string name;         // a mesh's, to find it again in the next frame
  };
  static constexpr unsigned kNoGeometry = RTC_INVALID_GEOMETRY_ID;  // a mesh without triangles
  static constexpr unsigned kReplace = RTC_INVALID_GEOMETRY_ID - 1;  // follow(): no geometry to keep

  // positionsAtClose / centerAtClose: null for still geometry, else the shutter-close state.
  unsigned addMesh(const TriangleMesh& mesh, Kind kind, uint32_t index, const std::vector<Vec3>* positionsAtClose);
  unsigned addSphere(const Vec3& center, float radius, Kind kind, uint32_t index, const Vec3* centerAtClose);
  void recordGeometry(unsigned geometryId, const GeometryRecord& record);
  static bool isDielectric(const Frame& frame, uint32_t materialId);
  void attachToDielectricScene(unsigned geometryId, uint32_t materialId);
  bool meshHasLayout(const MeshInstance& instance, unsigned geometryId) const;
  bool sphereHasLayout(bool moves, unsigned geometryId) const;
  bool keepsDielectric(const Frame& frame, unsigned geometryId, uint32_t materialId) const;
  // Which geometry of the previous frame each mesh / sphere / light of `frame` keeps (kNoGeometry
  // for an empty mesh), or kReplace: see follow().
  std::vector<unsigned> keptMeshGeometries(const Frame& frame) const;
  std::vector<unsigned> keptSphereGeometries(const Frame& frame) const;
  std::vector<unsigned> keptLightGeometries(const Frame& frame) const;
  size_t detachAllBut(const std::vector<unsigned>& kept);
  void followMeshes(const Frame& frame, const std::vector<unsigned>& kept, SceneFollowReport& report);
  void followSpheres(const Frame& frame, const std::vector<unsigned>& kept, SceneFollowReport& report);
  void followLights(const Frame& frame, const std::vector<unsigned>& kept, SceneFollowReport& report);
  void moveMesh(const TriangleMesh& mesh, const std::vector<Vec3>* positionsAtClose, unsigned geometryId);
  void moveSphere(const Vec3& center, float radius, const Vec3* centerAtClose, unsigned geometryId);
  void commitChangedGeometries();
  void surfaceOfMesh(const MeshInstance& instance, float time, const uint32_t* triangle, float u, float v,
                     SurfaceHit& hit) const;
  bool hasMaterial(unsigned geometryId, uint32_t materialId) const;
  bool nearestHit(RTCScene scene, const Ray& ray, SurfaceHit& hit) const;
  static bool anyHit(RTCScene scene, const Vec3& origin, const Vec3& direction, float maxDistance, float time);
  static void recordCrossing(const RTCFilterFunctionNArguments* arguments);

  const Frame* frame_;
  int threads_;
  std::vector<MeshInstance> lightMeshes_;  // per light: a rectangle as two triangles, else empty
  std::vector<GeometryRecord> records_;    // indexed by Embree geomID
  // Embree geomID of each frame mesh / sphere / light, for following the next frame.
  std::vector<unsigned> meshGeometry_, sphereGeometry_, lightGeometry_;
  std::vector<unsigned> changedGeometries_;  // moved by this refitTo, committed together at its end
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  RTCScene dielectricScene_ = nullptr;  // the dielectric geometries again, with the same ids
};

}  // namespace lacrima
