#pragma once
// The liquid state of a shot's liquid tears at a frame (ShotLiquidTear; docs/shot-format.md
// "Liquid tears"), for buildFrame and for anyone who needs more than the meshes (the trail's film
// thickness along the path, for a wet-skin material).
#include "lacrima/geometry/surface_point.hpp"
#include "lacrima/geometry/tear_liquid.hpp"
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima {

// The simulation's time at a (fractional) frame: seconds since tear.simulationStartFrame (the
// shot's first frame or an earlier wellStart), clamped at 0.
double liquidTearSeconds(const Shot& shot, const ShotLiquidTear& tear, double frame);

// The tear's liquid state at a (fractional) frame, simulated from its simulationStartFrame: beads,
// falling drops and the film thickness at each path sample (sampleFilmThickness[i] at the
// path's point i, tear.path.points[i]). The same for a frame alone or within a sequence.
TearLiquidState liquidTearStateAt(const Shot& shot, const ShotLiquidTear& tear, double frame);

// The point at arc length s along the tear's path (clamped to the path), in the triangles of its
// primitive, and the piece it lies on (piece i runs from path.points[i] to path.arrival[i + 1]).
SurfacePoint liquidTearPathPoint(const ShotLiquidTear& tear, double arcLength, size_t* piece = nullptr);

}  // namespace lacrima
