// The courses of a liquid tear's flow path as the face moves, and the simulation run that follows
// them; see lacrima/scenes/liquid_tear.hpp.
#include <fmt/format.h>

#include <cmath>

#include "lacrima/base/error.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "resolve/liquid_tear_resolve.hpp"  // flowPathOnSkin

namespace lacrima {

namespace {

bool carriesLiquid(const LiquidTearCourse& course) {
  return course.path.points.size() >= 2 && course.path.length() >= kMinLiquidCourseLength;
}

LiquidTearInput inputOn(const ShotLiquidTear& tear, const LiquidTearCourse& course) {
  LiquidTearInput input = tear.input;
  input.path = course.samples;
  return input;
}

}  // namespace

// ---- Courses --------------------------------------------------------------------------------------

void assignContactAngleRegions(std::vector<LiquidPathSample>& samples, const TriangleMesh& skin,
                               const std::vector<LiquidCourseRegion>& regions) {
  std::vector<Vec3d> centres;
  for (const LiquidCourseRegion& region : regions) centres.push_back(surfacePosition(skin, region.center).cast<double>());
  for (LiquidPathSample& sample : samples) {
    sample.contactAngleRegion = -1;
    for (size_t i = 0; i < regions.size() && sample.contactAngleRegion < 0; ++i)
      if ((sample.position - centres[i]).norm() <= regions[i].radius) sample.contactAngleRegion = int(i);
  }
}

void assignPinning(std::vector<LiquidPathSample>& samples, const FlowPath& path, const TriangleMesh& skin,
                   const std::vector<float>& pinningPerVertex) {
  if (pinningPerVertex.empty()) return;
  if (pinningPerVertex.size() != skin.vertexCount() || samples.size() != path.points.size())
    throw InputError(fmt::format("liquid tear: {} pinning factors for a skin of {} vertices, {} samples for a path of {} points",
                                 pinningPerVertex.size(), skin.vertexCount(), samples.size(), path.points.size()));
  for (size_t i = 0; i < samples.size(); ++i) {
    const SurfacePoint& point = path.points[i];
    const Vec3 w = point.barycentric;
    double factor = 0.0;
    for (int k = 0; k < 3; ++k) factor += double(w[k]) * pinningPerVertex[skin.indices[3 * size_t(point.triangle) + k]];
    samples[i].pinning = factor;
  }
}

LiquidTearCourses::LiquidTearCourses(std::shared_ptr<const LiquidTearSurface> surface, const SurfacePoint& start,
                                     const Vec3& gravity, float maxLength, int firstFrame,
                                     std::vector<LiquidCourseRegion> regions, std::vector<float> pinning)
    : surface_(std::move(surface)),
      start_(start),
      gravity_(gravity),
      maxLength_(maxLength),
      firstFrame_(firstFrame),
      regions_(std::move(regions)),
      pinning_(std::move(pinning)) {
  const LiquidTearSkin first = surface_->at(firstFrame);
  adjacency_ = buildTriangleAdjacency(first.skin, findCoincidentVertices(first.skin));
  courses_.push_back(trace(firstFrame, first, nullptr));
  traced_ = 1;
}

std::shared_ptr<const LiquidTearCourse> LiquidTearCourses::trace(int frame, const LiquidTearSkin& surface,
                                                                 const LiquidTearCourse* previous) const {
  FlowPathOptions options;
  options.maxLength = maxLength_;
  const FlowPath traced = traceFlowPath(surface.smoothed, adjacency_, start_, gravity_, options);
  auto course = std::make_shared<LiquidTearCourse>();
  course->frame = frame;
  course->smoothedLength = traced.length();
  course->path = shotfile::flowPathOnSkin(traced, surface.skin);
  if (!carriesLiquid(*course)) return course;
  course->samples = liquidPathFromFlowPath(course->path, surface.skin);
  assignContactAngleRegions(course->samples, surface.skin, regions_);
  assignPinning(course->samples, course->path, surface.skin, pinning_);
  if (previous && carriesLiquid(*previous))
    course->fromPrevious = std::make_shared<FlowPathTransfer>(previous->path, course->path, surface.skin);
  return course;
}

std::shared_ptr<const LiquidTearCourse> LiquidTearCourses::at(int frame) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (frame <= firstFrame_) return courses_.front();
  // Courses are traced in frame order: each one's transfer starts from the one before it.
  while (courses_.size() <= size_t(frame - firstFrame_)) {
    const int next = firstFrame_ + int(courses_.size());
    const std::shared_ptr<const LiquidTearCourse> previous = courses_.back();
    if (surface_->sameAsPrevious(next)) {
      courses_.push_back(previous);
      continue;
    }
    const std::shared_ptr<const LiquidTearCourse> course = trace(next, surface_->at(next), previous.get());
    ++traced_;
    const bool runsOn = course->path.length() >= kMinLiquidCourseLengthRatio * previous->path.length();
    courses_.push_back(carriesLiquid(*course) && course->fromPrevious && runsOn ? course : previous);
  }
  return courses_[size_t(frame - firstFrame_)];
}

size_t LiquidTearCourses::tracedCount() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return traced_;
}

int liquidTearCourseFrame(const Shot& shot, const ShotLiquidTear& tear, double seconds) {
  return int(std::floor(tear.simulationStartFrame + seconds * shot.fps + 0.5 + 1e-9));
}

// ---- The run --------------------------------------------------------------------------------------

LiquidTearRun::LiquidTearRun(const Shot& shot, const ShotLiquidTear& tear, const LiquidTearCourses& courses)
    : shot_(&shot),
      tear_(&tear),
      courses_(&courses),
      course_(courses.at(liquidTearCourseFrame(shot, tear, 0.0))),
      courseFrame_(liquidTearCourseFrame(shot, tear, 0.0)),
      simulation_(inputOn(tear, *course_)) {}

bool LiquidTearRun::hasPassed(double frame) const {
  return liquidTearStepsTo(liquidTearSeconds(*shot_, *tear_, frame), tear_->input.params.timeStep) < simulation_.steps();
}

void LiquidTearRun::followCourse(int frame) {
  while (courseFrame_ < frame) {
    ++courseFrame_;
    std::shared_ptr<const LiquidTearCourse> next = courses_->at(courseFrame_);
    if (next == course_) continue;
    if (!next->fromPrevious) throw InputError(fmt::format("liquid tear {}: the course at frame {} has no transfer", tear_->pointer, courseFrame_));
    const FlowPathTransfer& transfer = *next->fromPrevious;  // from course_, the course of the frame before
    simulation_.reroute(next->samples, [&transfer](double s) { return transfer(s); });
    course_ = std::move(next);
    ++reroutes_;
  }
}

void LiquidTearRun::advanceTo(double frame) {
  const double t = liquidTearSeconds(*shot_, *tear_, frame);
  const double dt = tear_->input.params.timeStep;
  const long long target = liquidTearStepsTo(t, dt);
  if (target < simulation_.steps()) simulation_.advanceTo(t);  // refuses to go back, with its message
  // Each step runs on the course of its start time's nearest frame; the state reached is left on
  // the course of the next step, so a run stopped here and continued equals one that did not stop.
  while (simulation_.steps() < target) {
    followCourse(liquidTearCourseFrame(*shot_, *tear_, double(simulation_.steps()) * dt));
    simulation_.step();
  }
  followCourse(liquidTearCourseFrame(*shot_, *tear_, double(simulation_.steps()) * dt));
}

LiquidTearState LiquidTearRun::state(double frame) const {
  return simulation_.state(liquidTearSeconds(*shot_, *tear_, frame));
}

// ---- Queries --------------------------------------------------------------------------------------

std::shared_ptr<LiquidTearCourses> liquidTearCoursesOf(const Shot& shot, const ShotLiquidTear& tear) {
  if (!tear.surface)
    throw InputError(fmt::format("liquid tear {}: its flow path was not resolved (load the shot with loadShot)", tear.pointer));
  std::vector<LiquidCourseRegion> regions;
  for (const ShotContactAngleRegion& region : tear.contactAngleRegions)
    regions.push_back({SurfacePoint{region.centerPoint.triangle, region.centerPoint.barycentric}, region.radius});
  return std::make_shared<LiquidTearCourses>(tear.surface, SurfacePoint{tear.sourcePoint.triangle, tear.sourcePoint.barycentric},
                                             tear.gravity, tear.maxLength, liquidTearCourseFrame(shot, tear, 0.0),
                                             std::move(regions), tear.pinning);
}

std::shared_ptr<const LiquidTearCourse> liquidTearCourseAt(const Shot& shot, const ShotLiquidTear& tear,
                                                           const LiquidTearCourses& courses, double frame) {
  const double dt = tear.input.params.timeStep;
  const long long steps = liquidTearStepsTo(liquidTearSeconds(shot, tear, frame), dt);
  return courses.at(liquidTearCourseFrame(shot, tear, double(steps) * dt));
}

}  // namespace lacrima
