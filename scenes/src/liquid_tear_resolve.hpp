#pragma once
// Resolving a shot's liquid tears at load: the source on the skin and the flow path from it, traced
// once on a smoothed copy of the skin posed at the shot's first frame (see ShotLiquidTear).
#include <vector>

#include "lacrima/geometry/mesh_smoothing.hpp"
#include "lacrima/scenes/shot_model.hpp"
#include "shedding_tear_resolve.hpp"  // SheddingTearProblem: a problem at a JSON pointer

namespace lacrima::shotfile {

using LiquidTearProblem = SheddingTearProblem;

// The low-pass filter the path is traced through: the ICT face's tessellation has pits a few
// edges wide where an exact steepest-descent walk stops after millimetres; 20 Taubin pairs
// remove them and keep the cheek's and nose's shape.
inline constexpr TaubinOptions kLiquidPathSmoothing{20, 0.5f, -0.53f};  // the defaults, spelled out
// A path shorter than this cannot carry a bead (about one bead length): reported at load.
inline constexpr float kMinLiquidPathLength = 0.002f;  // metres

// A path traced on a smoothed copy of `skin` (same topology) re-expressed on `skin`: positions and
// arc lengths measured there, pieces of zero length there dropped (the piece before a dropped
// point ends where the dropped piece did).
FlowPath flowPathOnSkin(const FlowPath& traced, const TriangleMesh& skin);

// For every liquid tear: the source resolved on the first frame's skin, the path traced and the
// simulation input built and checked. Returns the problems found (a path too short to carry a bead,
// parameters the simulation refuses).
std::vector<LiquidTearProblem> resolveLiquidTears(Shot& shot);

}  // namespace lacrima::shotfile
