#pragma once
// Refinement of the skin along liquid tears' flow paths (a liquid tear's "trailRefinement",
// docs/shot-format.md "Liquid tears"): the wet trail is a film thickness per skin vertex, and the
// ICT cheek's ~2 mm vertex spacing draws a 2-3 mm trail as a blocky band about twice as wide. The
// triangles along the path are split linearly (the surface does not change) so the trail resolves.
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// Triangles within this distance of the path (plus one ring) are refined: the film reaches 0.75
// bead base widths from the path (1.5 half widths, liquid_tear_film.hpp), ~2.6 mm for an 8 uL bead.
inline constexpr float kTrailRefinementMargin = 0.003f;  // metres

// For every liquid tear with trailRefinement > 0, in file order: its courses over the shot's
// frames are traced as resolveLiquidTears would (on each frame's smoothed skin), the triangles along
// any of them (placed on the first frame's skin) are refined linearly, replacing ShotAsset::gltf (the rig rebuilt, as refineDetailRegions does), and every
// liquid tear on that primitive keeps the smoothed skin carried over to the refined vertices
// (ShotLiquidTear::smoothedSkin): a linear split of the smoothed skin is the same surface, so the
// path traced again at resolve time runs where it ran before the refinement. Run after
// refineDetailRegions and before any surface point is resolved (they index the refined triangles).
void refineLiquidTrails(Shot& shot);

// The triangles with a corner within `margin` of the polyline `path` (world positions on `mesh`),
// grown by one ring across seams (`weldMap`).
std::vector<bool> trailTriangles(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                                 const std::vector<Vec3>& path, float margin);

}  // namespace lacrima::shotfile
