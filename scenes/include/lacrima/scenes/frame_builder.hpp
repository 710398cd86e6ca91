#pragma once
// FrameBuilder: a loaded Shot -> the renderer's Frame at each frame number, through the geometry
// stage. The Shot is plain, immutable data; the builder keeps what a sequence advances from frame
// to frame: each liquid tear's courses and run, each simulated flesh's run, each SPH liquid's run.
// Every simulation is a pure function of the time it reaches, so a frame gives the same pixels
// whether it is built alone, in a sequence, or after a later frame (then it starts again from the
// simulation's start, or from a state filed on disk).
#include <cstddef>
#include <memory>

#include "lacrima/renderer/frame.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima {

struct FrameBuildTimes;  // frame_build_times.hpp

class FrameBuilder {
 public:
  // `shot` (from loadShot) must outlive the builder. Traces each liquid tear's first course.
  explicit FrameBuilder(const Shot& shot);
  ~FrameBuilder();
  FrameBuilder(const FrameBuilder&) = delete;
  FrameBuilder& operator=(const FrameBuilder&) = delete;

  const Shot& shot() const { return shot_; }

  // The renderer input for one frame number of the shot (InputError outside its frame range),
  // recording its stages' times in `times` when not null. Reads nothing from disk but filed
  // simulation states. Build frames in increasing order: each continues the simulations the one
  // before advanced.
  Frame build(int frameNumber, FrameBuildTimes* times = nullptr);

  // Liquid tear `tear` (index into shot.liquidTears) at a (fractional) frame: its beads, falling
  // drops and film thickness along the course (sampleFilmThickness[i] at
  // liquidTearCourseAt(...)->path.points[i]), the same as its frame's meshes are built from.
  LiquidTearState liquidTearStateAt(size_t tear, double frame);
  // The course the state at that frame lies on (its arc lengths are this course's).
  std::shared_ptr<const LiquidTearCourse> liquidTearCourseAt(size_t tear, double frame);
  // The tear's courses, traced so far.
  const LiquidTearCourses& liquidTearCourses(size_t tear) const;

 private:
  struct Simulations;  // frame_builder.cpp
  const Shot& shot_;
  std::unique_ptr<Simulations> simulations_;
};

}  // namespace lacrima
