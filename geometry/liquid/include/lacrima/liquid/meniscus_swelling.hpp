#pragma once
// The lacrimal tear meniscus swelling as it fills: the thin
// strip of tear fluid along the lid margins (the ICT face's M_LacrimalFluid) is thickened near the
// tear's source by the volume the simulated meniscus holds (LiquidTearSimulation::meniscusVolume),
// and thins back when it overflows.
//
// Model (modelling choice): the meniscus volume V is laid onto the strip as a thickness field along
// the vertex normals, delta_v = h0 w_v, with a smooth falloff w_v = (1 - (d_v / L)^2)^2 of the
// distance d_v from the source (0 beyond L): the fluid gathers at the canthus where it wells and
// spreads along both lids. To first order h0 = V / sum_v A_v w_v, A_v a third of the area of the
// triangles around v (a shell of thickness delta over area A holds A delta). The strip is thin and
// strongly curved across (its cross-section's radius is about its width, ~1 mm, comparable to
// delta), so the second- and third-order terms matter (~20% at 8 uL on a 1.2 mm strip): h0 is then
// refined by the secant method until the volume swept between the strip and its thickened copy
// (sweptVolume) is V to 1e-6. The cross-section stays the strip's own, lifted along its normals:
// not the circular-arc meniscus (1 - pi/4) r^2 of a liquid filling the corner between lid and globe,
// which would need the globe as a second wall.
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

// w_v for every vertex of `mesh`: (1 - (d / L)^2)^2 for d = |p_v - source| < L, else 0. L > 0.
std::vector<float> meniscusFalloffWeights(const TriangleMesh& mesh, const Vec3& source, float falloffLength);

// A_v: a third of the area of every triangle using vertex v (their sum is the mesh's area).
std::vector<double> vertexAreas(const TriangleMesh& mesh);

// Volume swept between `before` and `after` (one topology, vertices moved), summed over the
// triangles' prisms, each as three tetrahedra (a b c c') + (a b c' b') + (a b' c' a') for corners
// a b c moved to a' b' c': positive where the surface moved to the side its counter-clockwise
// winding faces. Exact for prisms with planar sides. Throws InputError for different topologies.
double sweptVolume(const TriangleMesh& before, const TriangleMesh& after);

// Thickens `mesh` by `volume` m^3 (>= 0) spread with `weights` (one per vertex): every vertex with
// w_v > 0 moves by h0 w_v along its normal (the mesh's normals; smooth welded ones when it has
// none), h0 such that sweptVolume(before, after) = volume (relative 1e-6), and the normals of the moved vertices and their neighbours are recomputed. Returns h0, the
// thickness where w = 1; with volume 0 or no weight it returns 0 and leaves the mesh untouched.
// Throws InputError for a negative or non-finite volume or weights of the wrong size.
double swellMeniscus(TriangleMesh& mesh, const std::vector<float>& weights, double volume);

}  // namespace lacrima
