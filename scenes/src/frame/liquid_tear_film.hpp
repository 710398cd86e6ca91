#pragma once
// The wet trail of a liquid tear as a per-vertex film thickness on the skin it runs over
// (MeshInstance::wetness; the renderer shades it as wet skin, materials/wet_skin.hpp).
#include <vector>

#include "lacrima/liquid/liquid_tear.hpp"
#include "lacrima/scenes/shot.hpp"
#include "resolve/film_edge_variation.hpp"  // ShotLiquidTear::filmEdgeVariation

namespace lacrima::shotfile {

// Beyond the film's half width h the thickness falls smoothly to 0 at h (1 + kFilmEdgeFraction)
// (modelling choice: the film thins out at its edge instead of ending in a step the vertex
// interpolation would turn into a saw-tooth).
inline constexpr float kFilmEdgeFraction = 0.1f;
// The edge wanders (modelling choice): a wet trail does not end in two straight lines; its contact
// line catches on the skin's micro-relief (pores, creases, vellus hairs) and pins wherever it
// happens to. Each skin vertex gets a fixed value v in [-1, 1] (filmEdgeVariation, at load) and the half
// width there is h (1 + kFilmEdgeWander v): the edges wander by about a third of the half width,
// in bays and spurs about kFilmEdgeFeatureSize across with finer ones on them (three octaves); a
// quarter of the half width at 1.5 mm still read as two straight lines at 1:1 on the default
// shot. (1 + kFilmEdgeFraction)(1 + kFilmEdgeWander) = 1.5:
// the film reaches no further than the straight edges of 1.5 half widths it replaced, so the
// trail refinement along the path (liquid_trail_refinement.hpp) still covers it.
inline constexpr float kFilmEdgeWander = 0.36f;
// Writes the tear's film, as `simulation` holds it now on `course` (the course it runs on, the
// simulation's arc lengths), onto `wetness` (one value per vertex of `skin`, the posed primitive the
// path runs over; resized from empty on the first wet vertex): a vertex at distance r from the
// course (its polyline on `skin`) gets the film thickness d(s)
// at the arc length s of its closest point on a piece, times 1 within half the film's width
// there (scaled by the vertex's 1 + kFilmEdgeWander v, when tear.filmEdgeVariation has one value
// per vertex) and a smooth falloff beyond; the largest value over the pieces and over earlier
// tears is kept. Only vertices within reach of a wet piece are visited.
void addLiquidTearFilm(const ShotLiquidTear& tear, const FlowPath& course, const LiquidTearSimulation& simulation,
                       const TriangleMesh& skin, std::vector<float>& wetness);

// The same film by its definition, evaluated directly: every vertex against every wet piece, no
// grid, no early stop (slow: tens of seconds on the default shot). addLiquidTearFilm must write
// bitwise the same; the tests hold it to that (tests/scenes/liquid_tear_film_test.cpp).
void addLiquidTearFilmOverEveryPiece(const ShotLiquidTear& tear, const FlowPath& course,
                                     const LiquidTearSimulation& simulation, const TriangleMesh& skin,
                                     std::vector<float>& wetness);

}  // namespace lacrima::shotfile
