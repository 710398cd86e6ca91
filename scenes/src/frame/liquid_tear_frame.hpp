#pragma once
// The meshes and spheres of a shot's liquid tears in a frame (FrameBuilder's part; see ShotLiquidTear).
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "lacrima/scenes/liquid_tear.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::shotfile {

// Where a bead's flat side lies: 20 um under the skin, so the skin under the bead is inside the
// water, as it is on a face (the bead wets the skin it rides on; a base above the skin would leave
// an air gap, and light reaching the base at more than the critical angle, 48.4 degrees, would be
// totally reflected there: with a 20 um gap, the skin under the cheek bead of
// tools/peers/shots/tear_on_cheek.json got a tenth of the key light it gets in contact, in lacrima's
// brute-force path tracing and in Cycles alike; docs/peers.md).
inline constexpr float kLiquidBeadBaseOffset = -2e-5f;  // metres along the skin normal
// A falling drop whose mode-2 envelope |eps0| exp(-t / tau) is below this is drawn as an exact
// sphere: its axes then differ by under 1.5% (about 20 um on a 1.5 mm drop, below a pixel).
inline constexpr double kVisibleDropAmplitude = 0.01;

// A liquid tear simulated over one frame's shutter: one run advanced to shutter open, then to close
// (bitwise what runs from the start to each give: LiquidTearRun), and what the frame needs of it
// at each moment.
struct LiquidTearShutter {
  bool blurred = false;  // the shutter closes after it opens; otherwise close is a copy of open
  LiquidTearState open, close;
  std::shared_ptr<const LiquidTearCourse> openCourse, closeCourse;  // the course each state lies on
  double meniscusOpen = 0.0, meniscusClose = 0.0;                    // m^3
  // The simulation as it stood at shutter open, for the film (null when the tear is not resolved).
  std::shared_ptr<const LiquidTearSimulation> simulationAtOpen;
  // The wet trail at shutter open (it dries over seconds: no blur) on openSkin[primitive], one value
  // per vertex; empty when nothing is wet or before layLiquidTearFilm (liquid_tear_film.hpp).
  std::vector<float> film;
};

// One liquid tear's courses and the run the last frame advanced, kept at that frame's shutter open
// for the next frame to continue (a continued run gives bitwise the state a new one would): what a
// FrameBuilder keeps of a tear. Thread-safe.
class LiquidTearKeeper {
 public:
  // Traces the first course of a tear resolved by loadShot; a tear not resolved gets no courses.
  LiquidTearKeeper(const Shot& shot, const ShotLiquidTear& tear);

  bool resolved() const { return courses_ != nullptr; }
  // The courses; InputError for a tear that was not resolved.
  const LiquidTearCourses& courses() const;
  // A run to advance to `frame`: the kept one when it has not passed the frame, else a new one.
  LiquidTearRun runFor(double frame) const;
  void keep(const LiquidTearRun& run);

 private:
  const Shot& shot_;
  const ShotLiquidTear& tear_;
  std::shared_ptr<const LiquidTearCourses> courses_;
  mutable std::mutex mutex_;
  std::optional<LiquidTearRun> kept_;
};

// Simulates the tear over the frame whose shutter opens at frame `open` and closes at `close`
// (fractional frames; equal: no blur): the kept run continued to open and kept there, then on to
// close. Needs no posed skin, so it can run while the assets are posed. Empty for a tear that was
// not resolved.
LiquidTearShutter simulateLiquidTearShutter(LiquidTearKeeper& tear, double shutterOpen, double shutterClose);

// Lays the wet trail of `run` at shutter open on the tear's primitive of openSkin (the asset's
// primitives posed at open, flesh and details included) into run.film.
void layLiquidTearFilm(const ShotLiquidTear& tear, const std::vector<TriangleMesh>& openSkin, LiquidTearShutter& run);

// Adds the tear's beads ("liquid bead" meshes on the posed skin `openSkin`, and on `closeSkin` at
// shutter close when given) and its falling drops ("falling drop" spheroid meshes ringing in mode 2,
// their shape and place at shutter close as positionsAtClose; spheres with centerAtClose once the
// ringing is below kVisibleDropAmplitude), as `run` holds them.
// openSkin / closeSkin: the asset's posed primitives (closeSkin null or empty: as at open).
// skinMesh: the index in frame.meshes of the primitive the tear runs over (-1: not rendered); its
// wetness gets the tear's film (the largest value of every tear is kept).
void addLiquidTear(const ShotLiquidTear& tear, const LiquidTearShutter& run, const std::vector<TriangleMesh>& openSkin,
                   const std::vector<TriangleMesh>* closeSkin, int skinMesh, Frame& frame);

// Thickens the tear's lacrimal fluid strip (tear.meniscusPrimitive of `posed`, the asset's primitives
// posed at the moment the volume was simulated) by the meniscus volume (swellMeniscus with
// tear.meniscusWeights). Nothing happens without a strip, without posed primitives, or at volume 0.
void swellLiquidTearMeniscus(const ShotLiquidTear& tear, double meniscusVolume, std::vector<TriangleMesh>& posed);

}  // namespace lacrima::shotfile
