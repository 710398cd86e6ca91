// The cost before the first ray (bench.hpp): the scene update's parts as Renderer makes it, the
// renderer's whole set-up, and raw Embree's refit of the same triangles for comparison.
#include <embree3/rtcore.h>
#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include "embree_scene.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/renderer/bench.hpp"
#include "lacrima/renderer/render.hpp"

namespace lacrima {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

tbb::task_arena arenaFor(const Frame& frame) {
  return tbb::task_arena(frame.settings.threads > 0 ? frame.settings.threads : tbb::task_arena::automatic);
}

void throwEmbreeError(void*, RTCError code, const char* message) {
  throw std::runtime_error(fmt::format("Embree error {}: {}", int(code), message ? message : ""));
}

// A bare Embree scene of a frame's triangle meshes (measureRawEmbreeRefit).
class RawTriangleScene {
 public:
  RawTriangleScene(const Frame& frame, bool withMotion) : withMotion_(withMotion) {
    const int threads = frame.settings.threads;
    const std::string config = threads > 0 ? fmt::format("threads={}", threads) : std::string();
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw std::runtime_error("could not create the Embree device");
    rtcSetDeviceErrorFunction(device_, throwEmbreeError, nullptr);
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);  // as EmbreeScene: the two-level BVH
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    for (const MeshInstance& instance : frame.meshes) geometries_.push_back(addMesh(instance));
    rtcCommitScene(scene_);
  }
  ~RawTriangleScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  RawTriangleScene(const RawTriangleScene&) = delete;
  RawTriangleScene& operator=(const RawTriangleScene&) = delete;

  // Gives the moved meshes `to`'s positions (untimed), then times their commits and the scene's.
  double refitSeconds(const Frame& from, const Frame& to) {
    std::vector<RTCGeometry> moved;
    for (size_t i = 0; i < to.meshes.size(); ++i)
      if (geometries_[i] && positionsDiffer(from.meshes[i], to.meshes[i])) {
        for (unsigned step = 0; step < stepsOf(to.meshes[i]); ++step) writeStep(geometries_[i], to.meshes[i], step);
        moved.push_back(geometries_[i]);
      }
    const auto start = Clock::now();
    for (RTCGeometry geometry : moved) rtcCommitGeometry(geometry);
    rtcCommitScene(scene_);
    return secondsSince(start);
  }

 private:
  unsigned stepsOf(const MeshInstance& instance) const { return withMotion_ && instance.moves() ? 2u : 1u; }

  bool positionsDiffer(const MeshInstance& a, const MeshInstance& b) const {
    return a.mesh.positions != b.mesh.positions || (withMotion_ && a.positionsAtClose != b.positionsAtClose);
  }

  static void writeStep(RTCGeometry geometry, const MeshInstance& instance, unsigned step) {
    const std::vector<Vec3>& positions = step == 0 ? instance.mesh.positions : instance.positionsAtClose;
    void* buffer = rtcGetGeometryBufferData(geometry, RTC_BUFFER_TYPE_VERTEX, step);
    std::memcpy(buffer, positions.data(), positions.size() * sizeof(Vec3));
    rtcUpdateGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, step);
  }

  RTCGeometry addMesh(const MeshInstance& instance) {
    const TriangleMesh& mesh = instance.mesh;
    if (mesh.triangleCount() == 0) return nullptr;
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_REFIT);
    rtcSetGeometryTimeStepCount(geometry, stepsOf(instance));
    for (unsigned step = 0; step < stepsOf(instance); ++step) {
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, step, RTC_FORMAT_FLOAT3, sizeof(Vec3),
                              mesh.vertexCount());
      writeStep(geometry, instance, step);
    }
    void* indices = rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                            3 * sizeof(uint32_t), mesh.triangleCount());
    std::memcpy(indices, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);  // the scene keeps it alive
    return geometry;
  }

  bool withMotion_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<RTCGeometry> geometries_;  // per frame mesh; null for a mesh without triangles
};

void requireSameMeshLayout(const Frame& from, const Frame& to) {
  bool same = from.meshes.size() == to.meshes.size();
  for (size_t i = 0; same && i < from.meshes.size(); ++i) {
    const MeshInstance &a = from.meshes[i], &b = to.meshes[i];
    same = a.mesh.indices == b.mesh.indices && a.mesh.vertexCount() == b.mesh.vertexCount() && a.moves() == b.moves();
  }
  if (!same) throw InputError("bench: the two frames do not have the same triangle meshes (no refit possible)");
}

}  // namespace

SceneUpdateProbe::SceneUpdateProbe() = default;
SceneUpdateProbe::~SceneUpdateProbe() = default;

SceneUpdateSplit SceneUpdateProbe::update(const Frame& frame) {
  const int threads = frame.settings.threads;
  SceneUpdateSplit split;
  arenaFor(frame).execute([&] {
    if (scene_ && scene_->canFollow(threads)) {
      const SceneFollowReport report = scene_->follow(frame);
      split = {report.keptLayout() ? SceneUpdate::Refit : SceneUpdate::Update, report.uploadSeconds,
               report.commitSeconds};
      return;
    }
    const auto start = Clock::now();
    scene_.reset();  // as Renderer: the old device goes before the next is made
    scene_ = std::make_unique<EmbreeScene>(frame, threads);
    split.bvhSeconds = secondsSince(start);
  });
  return split;
}

double secondsBeforeFirstRay(Renderer& renderer, const Frame& frame) {
  const std::atomic<bool> cancelled{true};
  const auto start = Clock::now();
  try {
    renderer.render(frame, nullptr, {}, &cancelled);
  } catch (const RenderCancelled&) {
    // expected: every tile was skipped
  }
  return secondsSince(start);
}

RawRefitTimes measureRawEmbreeRefit(const Frame& from, const Frame& to) {
  requireSameMeshLayout(from, to);
  RawRefitTimes times;
  for (const MeshInstance& instance : from.meshes) times.triangles += instance.mesh.triangleCount();
  arenaFor(from).execute([&] {
    RawTriangleScene withMotion(from, true);
    times.sameTimeStepsSeconds = withMotion.refitSeconds(from, to);
    RawTriangleScene stillMeshes(from, false);
    times.oneTimeStepSeconds = stillMeshes.refitSeconds(from, to);
  });
  return times;
}

}  // namespace lacrima
