// Liquid tears in a frame: the simulation's state at the frame, beads draped over the posed skin,
// falling drops as moving spheres; see liquid_tear_frame.hpp and lacrima/scenes/liquid_tear.hpp.
#include "frame/liquid_tear_frame.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <functional>
#include <optional>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/drop_oscillation.hpp"
#include "lacrima/liquid/liquid_bead_mesh.hpp"
#include "lacrima/liquid/liquid_rivulet_mesh.hpp"
#include "lacrima/liquid/meniscus_swelling.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "frame/liquid_tear_film.hpp"

namespace lacrima {

double liquidTearSeconds(const Shot& shot, const ShotLiquidTear& tear, double frame) {
  return std::max(0.0, (frame - tear.simulationStartFrame) / shot.fps);
}

SurfacePoint liquidTearPathPoint(const ShotLiquidTear& tear, double arcLength, size_t* piece) {
  return liquidTearPathPoint(tear.path, arcLength, piece);
}

SurfacePoint liquidTearPathPoint(const FlowPath& path, double arcLength, size_t* piece) {
  const size_t pieces = path.points.size() - 1;
  // The last piece starting at or before s (the last one for s beyond the end).
  const auto after = std::upper_bound(path.arcLength.begin(), path.arcLength.end(), float(arcLength));
  const size_t i = std::min(pieces - 1, size_t(std::max<ptrdiff_t>(after - path.arcLength.begin() - 1, 0)));
  if (piece) *piece = i;
  const double length = double(path.arcLength[i + 1]) - double(path.arcLength[i]);
  const double f = std::clamp((arcLength - double(path.arcLength[i])) / length, 0.0, 1.0);
  // Barycentric coordinates are affine in space: the straight piece in its triangle, exactly.
  const Vec3d barycentric = (1.0 - f) * path.points[i].barycentric.cast<double>() + f * path.arrival[i + 1].cast<double>();
  return SurfacePoint{path.points[i].triangle, (barycentric / barycentric.sum()).cast<float>()};
}

namespace shotfile {

namespace {

// The skin's interpolated vertex normal at a point (the triangle's normal without vertex normals).
Vec3 skinNormal(const TriangleMesh& skin, const SurfacePoint& p) {
  const uint32_t* v = &skin.indices[3 * size_t(p.triangle)];
  if (skin.normals.size() == skin.positions.size()) {
    const Vec3 n = p.barycentric.x() * skin.normals[v[0]] + p.barycentric.y() * skin.normals[v[1]] +
                   p.barycentric.z() * skin.normals[v[2]];
    if (n.squaredNorm() > 1e-12f) return n.normalized();
  }
  return triangleNormal(skin, p.triangle);
}

// Where liquid at arc length s of the course sits on this skin: the point, the skin's normal there,
// and the direction down the course's piece (gravity where that piece runs along the normal).
struct CoursePlace {
  Vec3 contact, normal, along;
};

CoursePlace coursePlace(const ShotLiquidTear& tear, const FlowPath& course, double arcLength, const TriangleMesh& skin) {
  size_t piece = 0;
  const SurfacePoint at = liquidTearPathPoint(course, arcLength, &piece);
  const SurfacePoint pieceEnd{course.points[piece].triangle, course.arrival[piece + 1]};
  CoursePlace place{surfacePosition(skin, at), skinNormal(skin, at),
                    surfacePosition(skin, pieceEnd) - surfacePosition(skin, course.points[piece])};
  if (std::abs(place.along.normalized().dot(place.normal)) > 0.999f) place.along = tear.gravity;
  return place;
}

// The bead's mesh on this skin: at its point of the course, long axis along the course's piece there.
TriangleMesh beadMesh(const ShotLiquidTear& tear, const FlowPath& course, const BeadView& bead, const TriangleMesh& skin) {
  const CoursePlace place = coursePlace(tear, course, bead.arcLength, skin);
  LiquidBeadPlacement placement;
  placement.contact = place.contact;
  placement.normal = place.normal;
  placement.along = place.along;
  placement.halfLength = float(bead.shape.halfLength);
  placement.halfWidth = float(bead.shape.halfWidth);
  placement.height = float(bead.shape.height);
  placement.contactAngle = float(bead.contactAngle);  // the local mean angle, as BeadView's shape
  placement.baseOffset = kLiquidBeadBaseOffset;
  return makeLiquidBeadMesh(skin, placement);
}

// A stretch of rivulet on this skin: a station at each cell centre, on the course's point there.
TriangleMesh rivuletMesh(const ShotLiquidTear& tear, const FlowPath& course, const RivuletView& rivulet,
                         const TriangleMesh& skin) {
  std::vector<LiquidRivuletStation> stations;
  for (const RivuletStation& from : rivulet.stations) {
    const CoursePlace place = coursePlace(tear, course, from.arcLength, skin);
    stations.push_back({place.contact, place.normal, place.along, float(from.halfWidth), float(from.height)});
  }
  return makeLiquidRivuletMesh(stations, kLiquidBeadBaseOffset);
}

// The stretch of `rivulets` that starts where `rivulet` does and has as many stations (the same
// mesh layout at shutter close), if any.
const RivuletView* sameLayout(const std::vector<RivuletView>& rivulets, const RivuletView& rivulet) {
  for (const RivuletView& other : rivulets)
    if (other.begin == rivulet.begin && other.stations.size() == rivulet.stations.size()) return &other;
  return nullptr;
}

// A falling drop as drawn: an oscillating spheroid mesh (drop_oscillation.hpp).
TriangleMesh dropMesh(const DropView& drop) { return makeFallingDropMesh(drop.centre, drop.axis, drop.axes); }

// A drop whose ringing has died down below kVisibleDropAmplitude (its envelope, so a drop does not
// flicker between sphere and mesh as its amplitude crosses zero) is drawn as an exact sphere.
bool ringsVisibly(const DropView& drop) { return std::abs(drop.amplitudeEnvelope) >= kVisibleDropAmplitude; }

template <typename T>
const T* findById(const std::vector<T>& items, int id, int T::*key) {
  for (const T& item : items)
    if (item.*key == id) return &item;
  return nullptr;
}

// A mesh at shutter open carrying its vertices at close: `atClose` is the same item's mesh at close
// (the same layout), or nothing when the item is not there at close. The two are made side by side.
MeshInstance blurredInstance(const std::function<TriangleMesh()>& atOpen, const std::function<TriangleMesh()>& atClose,
                             bool closeExists, uint32_t materialId) {
  TriangleMesh open, close;
  tbb::parallel_invoke([&] { open = atOpen(); }, [&] {
    if (closeExists) close = atClose();
  });
  MeshInstance instance(std::move(open), materialId);
  if (closeExists && close.positions != instance.mesh.positions) {
    instance.positionsAtClose = std::move(close.positions);
    instance.normalsAtClose = std::move(close.normals);
  }
  return instance;
}

// A bead's mesh at shutter open, with its vertices at close where it is still there (by id).
MeshInstance beadInstance(const ShotLiquidTear& tear, const BeadView& bead, const std::vector<BeadView>* closeBeads,
                          const LiquidTearCourse& openCourse, const LiquidTearCourse& closeCourse,
                          const TriangleMesh& skinOpen, const TriangleMesh& skinClose) {
  const BeadView* later = closeBeads ? findById(*closeBeads, bead.id, &BeadView::id) : nullptr;
  return blurredInstance([&] { return beadMesh(tear, openCourse.path, bead, skinOpen); },
                         [&] { return beadMesh(tear, closeCourse.path, *later, skinClose); }, later != nullptr,
                         tear.materialId);
}

// A rivulet's mesh at shutter open. It is blurred where its stretch keeps its cells over the shutter
// (it swells or thins there); one whose front moves on to new cells is drawn as at shutter open.
MeshInstance rivuletInstance(const ShotLiquidTear& tear, const RivuletView& rivulet,
                             const std::vector<RivuletView>* closeRivulets, const LiquidTearCourse& openCourse,
                             const LiquidTearCourse& closeCourse, const TriangleMesh& skinOpen,
                             const TriangleMesh& skinClose) {
  const RivuletView* later = closeRivulets ? sameLayout(*closeRivulets, rivulet) : nullptr;
  return blurredInstance([&] { return rivuletMesh(tear, openCourse.path, rivulet, skinOpen); },
                         [&] { return rivuletMesh(tear, closeCourse.path, *later, skinClose); }, later != nullptr,
                         tear.materialId);
}

}  // namespace

LiquidTearKeeper::LiquidTearKeeper(const Shot& shot, const ShotLiquidTear& tear)
    : shot_(shot), tear_(tear), courses_(tear.surface ? liquidTearCoursesOf(shot, tear) : nullptr) {}

const LiquidTearCourses& LiquidTearKeeper::courses() const {
  if (!courses_)
    throw InputError(fmt::format("liquid tear {}: its flow path was not resolved (load the shot with loadShot)", tear_.pointer));
  return *courses_;
}

LiquidTearRun LiquidTearKeeper::runFor(double frame) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (kept_ && !kept_->hasPassed(frame)) return *kept_;
  return LiquidTearRun(shot_, tear_, courses());
}

void LiquidTearKeeper::keep(const LiquidTearRun& run) {
  std::lock_guard<std::mutex> lock(mutex_);
  kept_ = run;
}

LiquidTearShutter simulateLiquidTearShutter(LiquidTearKeeper& tear, double shutterOpen, double shutterClose) {
  LiquidTearShutter result;
  if (!tear.resolved()) return result;
  LiquidTearRun run = tear.runFor(shutterOpen);
  run.advanceTo(shutterOpen);
  tear.keep(run);
  result.open = run.state(shutterOpen);
  result.openCourse = run.coursePointer();
  result.meniscusOpen = run.simulation().meniscusVolume();
  result.simulationAtOpen = std::make_shared<const LiquidTearSimulation>(run.simulation());
  result.blurred = shutterClose > shutterOpen;
  if (!result.blurred) {
    result.close = result.open;
    result.closeCourse = result.openCourse;
    result.meniscusClose = result.meniscusOpen;
    return result;
  }
  run.advanceTo(shutterClose);
  result.close = run.state(shutterClose);
  result.closeCourse = run.coursePointer();
  result.meniscusClose = run.simulation().meniscusVolume();
  return result;
}

void layLiquidTearFilm(const ShotLiquidTear& tear, const std::vector<TriangleMesh>& openSkin, LiquidTearShutter& run) {
  const size_t primitive = tear.sourcePoint.primitive;
  if (!run.simulationAtOpen || !run.openCourse || primitive >= openSkin.size()) return;
  addLiquidTearFilm(tear, run.openCourse->path, *run.simulationAtOpen, openSkin[primitive], run.film);
}

void swellLiquidTearMeniscus(const ShotLiquidTear& tear, double meniscusVolume, std::vector<TriangleMesh>& posed) {
  if (tear.meniscusPrimitive < 0 || posed.empty()) return;
  TriangleMesh& strip = posed[size_t(tear.meniscusPrimitive)];
  if (strip.vertexCount() != tear.meniscusWeights.size()) return;  // not the strip resolved at load
  swellMeniscus(strip, tear.meniscusWeights, meniscusVolume);
}

void addLiquidTear(const ShotLiquidTear& tear, const LiquidTearShutter& run, const std::vector<TriangleMesh>& openSkin,
                   const std::vector<TriangleMesh>* closeSkin, int skinMesh, Frame& frame) {
  if (!run.openCourse || openSkin.empty()) return;  // not resolved (not from loadShot)
  if (skinMesh >= 0 && !run.film.empty()) {
    std::vector<float>& wetness = frame.meshes[size_t(skinMesh)].wetness;
    if (wetness.empty()) wetness.assign(run.film.size(), 0.0f);
    for (size_t v = 0; v < wetness.size(); ++v) wetness[v] = std::max(wetness[v], run.film[v]);
  }
  const bool blurred = run.blurred;
  const LiquidTearState& open = run.open;
  const LiquidTearState& close = run.close;
  const LiquidTearCourse* openCourse = run.openCourse.get();
  const LiquidTearCourse* closeCourse = run.closeCourse.get();
  const size_t primitive = tear.sourcePoint.primitive;
  const TriangleMesh& skinOpen = openSkin[primitive];
  const TriangleMesh& skinClose = closeSkin && !closeSkin->empty() ? (*closeSkin)[primitive] : skinOpen;
  // Each bead's and rivulet's meshes at open and close are independent (rays against the skin,
  // mostly): made side by side, then added in order.
  std::vector<std::optional<MeshInstance>> beads(open.beads.size()), rivulets(open.rivulets.size());
  tbb::parallel_for(size_t(0), beads.size() + rivulets.size(), [&](size_t i) {
    if (i < beads.size())
      beads[i] = beadInstance(tear, open.beads[i], blurred ? &close.beads : nullptr, *openCourse, *closeCourse,
                              skinOpen, skinClose);
    else
      rivulets[i - beads.size()] = rivuletInstance(tear, open.rivulets[i - beads.size()], blurred ? &close.rivulets : nullptr,
                                                   *openCourse, *closeCourse, skinOpen, skinClose);
  });
  for (std::optional<MeshInstance>& bead : beads) frame.meshes.push_back(std::move(*bead));
  for (std::optional<MeshInstance>& rivulet : rivulets) frame.meshes.push_back(std::move(*rivulet));
  for (const DropView& drop : open.drops) {
    const DropView* later = blurred ? findById(close.drops, drop.beadId, &DropView::beadId) : nullptr;
    if (ringsVisibly(drop)) {
      MeshInstance instance(dropMesh(drop), tear.materialId);
      if (later) {
        TriangleMesh atClose = dropMesh(*later);  // same tessellation: vertex by vertex
        instance.positionsAtClose = std::move(atClose.positions);
        instance.normalsAtClose = std::move(atClose.normals);
      }
      frame.meshes.push_back(std::move(instance));
      continue;
    }
    Sphere sphere(drop.centre.cast<float>(), float(drop.radius), tear.materialId);
    if (later && later->centre != drop.centre) sphere.centerAtClose = later->centre.cast<float>();
    frame.spheres.push_back(sphere);
  }
}

}  // namespace shotfile

}  // namespace lacrima
