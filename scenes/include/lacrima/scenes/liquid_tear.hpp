#pragma once
// The liquid tear's flow path as it follows the moving face (its courses) and the simulation that
// runs along them (ShotLiquidTear; docs/shot-format.md "Liquid tears"). A FrameBuilder
// (frame_builder.hpp) owns each tear's courses and run; its liquidTearStateAt serves anyone who
// needs more than the meshes (the trail's film thickness along the path, for a wet-skin material).
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "lacrima/mesh/flow_path_transfer.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/liquid/liquid_tear.hpp"
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima {

// The simulation's time at a (fractional) frame: seconds since tear.simulationStartFrame (the
// shot's first frame or an earlier wellStart), clamped at 0.
double liquidTearSeconds(const Shot& shot, const ShotLiquidTear& tear, double frame);

// ---- The course: the flow path re-traced as the face moves -------------------------------------

// The surface a tear runs over, posed at integer frames: the real skin of its primitive and the
// smoothed copy (same topology) the flow path is traced on.
struct LiquidTearSkin {
  TriangleMesh skin;
  TriangleMesh smoothed;
};
class LiquidTearSurface {
 public:
  virtual ~LiquidTearSurface() = default;
  // The surface at integer frame k.
  virtual LiquidTearSkin at(int frame) const = 0;
  // True when the surface at frame k is bitwise the one at k - 1 (its course is kept, not traced).
  virtual bool sameAsPrevious(int frame) const = 0;
};

// A contact-angle region on the surface a tear runs over (ShotContactAngleRegion resolved): its
// centre on the surface's triangles and its radius in metres.
struct LiquidCourseRegion {
  SurfacePoint center;
  double radius = 0.0;
};

// Sets each sample's contactAngleRegion: the index of the first region whose centre (posed on
// `skin`, the skin the samples lie on) is within its radius of the sample (straight-line
// distance), -1 for none.
void assignContactAngleRegions(std::vector<LiquidPathSample>& samples, const TriangleMesh& skin,
                               const std::vector<LiquidCourseRegion>& regions);

// Sets each sample's pinning factor: `pinningPerVertex` (one factor per vertex of the skin the path
// runs over) interpolated at the path's point for that sample (the start of its piece). Leaves the
// factors at 1 when `pinningPerVertex` is empty.
void assignPinning(std::vector<LiquidPathSample>& samples, const FlowPath& path, const TriangleMesh& skin,
                   const std::vector<float>& pinningPerVertex);

// The flow path as traced at one integer frame's pose.
struct LiquidTearCourse {
  int frame = 0;                          // the frame whose pose it was traced on
  FlowPath path;                          // positions and arc lengths on that frame's real skin
  float smoothedLength = 0.0f;            // its length on the smoothed skin it was traced on
  // The simulation's path (liquidPathFromFlowPath), its contact-angle regions assigned on this
  // frame's skin (assignContactAngleRegions) and the skin's pinning under it (assignPinning).
  std::vector<LiquidPathSample> samples;
  // From the course before it (traced at an earlier frame) to this one, measured on this frame's
  // skin; null for the first course.
  std::shared_ptr<const FlowPathTransfer> fromPrevious;
};

// The courses of one tear, one per integer frame from `firstFrame` on, traced on demand in frame
// order and kept (a cache, owned by whoever builds frames: a sequence pays each course once; a
// frame built alone traces the courses up to it and gets bitwise the same ones). A frame whose
// surface is the previous frame's keeps that course (the same object); so does a frame whose
// re-traced path is shorter than kMinLiquidCourseLength or than kMinLiquidCourseLengthRatio times
// the course it would replace: the liquid stays on the last course that could carry it. (On the default shot
// the blink squeezes a pit 2.6 mm below the inner eye corner for frames 35-37; re-routed there,
// every bead on the cheek would be pulled back up to it, while a tear on the cheek follows the
// cheek, not the lid.) Thread-safe.
class LiquidTearCourses {
 public:
  // `start`: the source on the surface's triangles; gravity and maxLength as in ShotLiquidTear;
  // `regions`: the tear's contact-angle regions, in order; `pinning`: the skin's pinning factor
  // per vertex of the surface's skin (ShotLiquidTear::pinning; empty: 1 everywhere). Traces the
  // first course (InputError from the surface or the walk propagate).
  LiquidTearCourses(std::shared_ptr<const LiquidTearSurface> surface, const SurfacePoint& start, const Vec3& gravity,
                    float maxLength, int firstFrame, std::vector<LiquidCourseRegion> regions = {},
                    std::vector<float> pinning = {});

  int firstFrame() const { return firstFrame_; }
  const LiquidTearSurface& surface() const { return *surface_; }
  // The course at integer frame k (frames before firstFrame get the first course).
  std::shared_ptr<const LiquidTearCourse> at(int frame) const;
  // Paths traced so far (one per frame whose pose changed, taken or not), for cost reports.
  size_t tracedCount() const;

 private:
  std::shared_ptr<const LiquidTearCourse> trace(int frame, const LiquidTearSkin& surface,
                                                const LiquidTearCourse* previous) const;

  std::shared_ptr<const LiquidTearSurface> surface_;
  SurfacePoint start_;
  Vec3 gravity_;
  float maxLength_;
  int firstFrame_;
  std::vector<LiquidCourseRegion> regions_;
  std::vector<float> pinning_;
  TriangleAdjacency adjacency_;  // the topology's, built once
  mutable std::mutex mutex_;
  mutable std::vector<std::shared_ptr<const LiquidTearCourse>> courses_;  // frame firstFrame_ + i
  mutable size_t traced_ = 0;
};

// A re-traced course shorter than this keeps the previous one (about one bead length) ...
inline constexpr float kMinLiquidCourseLength = 0.002f;  // metres
// ... and so does one shorter than this fraction of the previous one (a modelling choice: on the
// default shot successive courses differ in length by under 3%, a pit opening near the source cuts
// one to 3%).
inline constexpr float kMinLiquidCourseLengthRatio = 0.5f;

// The frame whose course the simulation step starting at `seconds` runs on: the frame nearest
// to that time (each course serves the half frame either side of its frame).
int liquidTearCourseFrame(const Shot& shot, const ShotLiquidTear& tear, double seconds);

// The tear's simulation with its course following the pose: from t = 0 on the first course, each
// step on the course of its nearest frame, the liquid carried across at each change
// (LiquidTearSimulation::reroute with the course's FlowPathTransfer). A pure function of the
// time reached: a run advanced to t in one go or in several gives bitwise the same state, so a
// copy kept at one frame can be continued to the next.
class LiquidTearRun {
 public:
  // `courses`: the tear's (liquidTearCoursesOf); shot, tear and courses must outlive the run.
  LiquidTearRun(const Shot& shot, const ShotLiquidTear& tear, const LiquidTearCourses& courses);
  // Whether it has stepped past the (fractional) frame, so cannot be advanced to it.
  bool hasPassed(double frame) const;
  // Simulates to the (fractional) frame, which may not be earlier than the last one (InputError).
  void advanceTo(double frame);
  LiquidTearState state(double frame) const;  // after advanceTo(frame)
  const LiquidTearSimulation& simulation() const { return simulation_; }
  const LiquidTearCourse& course() const { return *course_; }
  const std::shared_ptr<const LiquidTearCourse>& coursePointer() const { return course_; }
  // Course changes that moved the liquid so far.
  int reroutes() const { return reroutes_; }

 private:
  void followCourse(int frame);

  const Shot* shot_;
  const ShotLiquidTear* tear_;
  const LiquidTearCourses* courses_;
  std::shared_ptr<const LiquidTearCourse> course_;
  int courseFrame_ = 0;
  LiquidTearSimulation simulation_;
  int reroutes_ = 0;
};

// New courses of a tear resolved by loadShot (on ShotLiquidTear::surface, from its source, with its
// contact-angle regions and pinning), holding only the first course. InputError for a tear that
// was not resolved.
std::shared_ptr<LiquidTearCourses> liquidTearCoursesOf(const Shot& shot, const ShotLiquidTear& tear);

// The course the tear's state at a (fractional) frame lies on (its arc lengths are this course's).
std::shared_ptr<const LiquidTearCourse> liquidTearCourseAt(const Shot& shot, const ShotLiquidTear& tear,
                                                           const LiquidTearCourses& courses, double frame);

// The point at arc length s along a course (clamped to it), in the triangles of its primitive,
// and the piece it lies on (piece i runs from path.points[i] to path.arrival[i + 1]).
SurfacePoint liquidTearPathPoint(const FlowPath& path, double arcLength, size_t* piece = nullptr);
// The same on the course of the shot's first frame (tear.path).
SurfacePoint liquidTearPathPoint(const ShotLiquidTear& tear, double arcLength, size_t* piece = nullptr);

}  // namespace lacrima
