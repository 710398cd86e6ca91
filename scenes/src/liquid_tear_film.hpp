#pragma once
// The wet trail of a liquid tear as a per-vertex film thickness on the skin it runs over
// (MeshInstance::wetness; the renderer shades it as wet skin, materials/wet_skin.hpp).
#include <vector>

#include "lacrima/geometry/tear_liquid.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::shotfile {

// Beyond the film's half width h the thickness falls smoothly to 0 at h (1 + kFilmEdgeFraction)
// (modelling choice: the film thins out at its edge instead of ending in a step the vertex
// interpolation would turn into a saw-tooth).
inline constexpr float kFilmEdgeFraction = 0.5f;

// Writes the tear's film, as `simulation` holds it now on `course` (the course it runs on, the
// simulation's arc lengths), onto `wetness` (one value per vertex of `skin`, the posed primitive the
// path runs over; resized from empty on the first wet vertex): a vertex at distance r from the
// course (its polyline on `skin`) gets the film thickness d(s)
// at the arc length s of its closest point on a piece, times 1 within half the film's width
// there and a smooth falloff beyond; the largest value over the pieces and over earlier tears
// is kept. Only vertices within reach of a wet piece are visited.
void addLiquidTearFilm(const ShotLiquidTear& tear, const FlowPath& course, const TearLiquidSimulation& simulation,
                       const TriangleMesh& skin, std::vector<float>& wetness);

}  // namespace lacrima::shotfile
