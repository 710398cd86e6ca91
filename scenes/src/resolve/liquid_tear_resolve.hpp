#pragma once
// Resolving a shot's liquid tears at load: the source on the skin, and the courses of the flow path
// from it (LiquidTearCourses), traced on a smoothed copy of the skin posed at each frame (see
// ShotLiquidTear).
#include <vector>

#include "lacrima/mesh/mesh_smoothing.hpp"
#include "lacrima/scenes/liquid_tear.hpp"  // kMinLiquidCourseLength
#include "lacrima/scenes/shot_model.hpp"
#include "resolve/shedding_tear_resolve.hpp"  // SheddingTearProblem: a problem at a JSON pointer

namespace lacrima::shotfile {

using LiquidTearProblem = SheddingTearProblem;

// The low-pass filter the path is traced through: the ICT face's tessellation has pits a few
// edges wide where an exact steepest-descent walk stops after millimetres; 20 Taubin pairs
// remove them and keep the cheek's and nose's shape.
inline constexpr TaubinOptions kLiquidPathSmoothing{20, 0.5f, -0.53f};  // the defaults, spelled out
// The low-pass filter applied to the skin's deformation since the shot's first frame before it is
// added to that frame's smoothed skin (posedTearSurface): a few pairs remove the small bumps of
// blendshapes (measured on the default shot's 444 000-triangle face: ~8 ms a frame; without it the
// course stopped in a pit 2 mm below the source at frames 27 and 49, with 1 pair it did not; 1, 2
// and 3 pairs give the same 76.8 mm course at frame 72; 2 are taken for margin).
inline constexpr TaubinOptions kLiquidDeformationSmoothing{2, 0.5f, -0.53f};
// A path shorter than this cannot carry a bead (about one bead length): reported at load.
inline constexpr float kMinLiquidPathLength = kMinLiquidCourseLength;

// The ICT face's strip of tear fluid along the lid margins (the lacrimal tear meniscus).
inline constexpr const char* kLacrimalFluidPart = "M_LacrimalFluid";
// A liquid tear swells that strip when its source lies within this distance of it (the ICT
// inner-corner landmarks lie ~1-2 mm from it), ...
inline constexpr float kMeniscusReach = 0.005f;  // metres
// ... over this distance from the source: about a third of a lid margin (~28 mm), so both lids
// swell towards the inner corner where the tear wells (modelling choice).
inline constexpr float kMeniscusFalloffLength = 0.008f;  // metres

// A path traced on a smoothed copy of `skin` (same topology) re-expressed on `skin`: positions and
// arc lengths measured there, pieces of zero length there dropped (the piece before a dropped
// point ends where the dropped piece did).
FlowPath flowPathOnSkin(const FlowPath& traced, const TriangleMesh& skin);

// The copy of `skin` the path is traced on: smoothed by kLiquidPathSmoothing, or with the positions
// `carried` (the smoothed skin carried through a refinement, one per vertex) when given.
TriangleMesh liquidPathSmoothedSkin(const TriangleMesh& skin, const std::vector<Vec3>* carried);
// The flow path from `start` traced on `smoothed` (same topology as `skin`, whose seams are welded
// for the walk), at most maxLength long.
FlowPath traceLiquidPath(const TriangleMesh& skin, const TriangleMesh& smoothed, const SurfacePoint& start,
                         const Vec3& gravity, float maxLength);

// The tear's primitive of `asset` posed at integer frames, with the smoothed copy its path is traced
// on: at the pose of `referenceFrame` the skin smoothed by kLiquidPathSmoothing (or `carried`, see
// liquidPathSmoothedSkin), at any other pose that plus the deformation since then smoothed by
// kLiquidDeformationSmoothing. Keeps a copy of the asset (its meshes and rig shared).
std::shared_ptr<const LiquidTearSurface> posedTearSurface(const ShotAsset& asset, size_t primitive, int referenceFrame,
                                                          const std::vector<Vec3>* carried);
// The tear's courses from the simulation's first step on, from `source` over the asset as it is now
// (posedTearSurface with the shot's first frame as reference; `carried` as above), before the tear
// is resolved: only their paths (the skin refinement along them), so every sample has the tear's
// own contact angles and no pinning. A resolved tear's courses: liquidTearCoursesOf.
std::shared_ptr<const LiquidTearCourses> liquidTearCourses(const Shot& shot, const ShotLiquidTear& tear,
                                                           const ShotSurfacePoint& source, const std::vector<Vec3>* carried);

// For every liquid tear: the source resolved on the first frame's skin, the surface its courses
// are traced on set (tear.surface; the courses themselves are a FrameBuilder's), the course the
// simulation starts on traced and checked, the first frame's one kept as tear.path, and the
// simulation input built and checked. Returns the problems found (a path too short to carry a bead,
// parameters the simulation refuses).
std::vector<LiquidTearProblem> resolveLiquidTears(Shot& shot);

}  // namespace lacrima::shotfile
