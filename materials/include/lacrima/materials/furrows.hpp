#pragma once
// Procedural skin furrows: the fine network of shallow grooves that divides skin into small
// polygonal plateaus (the "microrelief" of dermatology), as a height field that tilts the shading
// normal and shades its grooves darker (skin_relief.hpp).
//
// Field: a Voronoi diagram of one feature point per cell of a cubic lattice of spacing `scale`
// metres, each jittered uniformly inside its cell by a hash of the cell (Worley 1996, "A Cellular
// Texture Basis Function", SIGGRAPH: feature points, neighbours searched in the surrounding cells).
// The grooves run along the walls between neighbouring Voronoi cells. A point's distance to the
// wall between its nearest feature point c1 and another c_k is the distance to their bisector
// plane,
//   d_k(q) = (|q - c_k|^2 - |q - c1|^2) / (2 |c_k - c1|),
// and its distance to the cell's boundary is d = min_k d_k (exact for the neighbours searched).
// Unlike Worley's F2 - F1, d is a true distance, so every groove has the same width. Each groove
// has the profile
//   h(p) = -depth * b(d / w),  b(t) = (1 - t^2)^2 for t < 1, else 0,
// with w = kFurrowHalfWidth * scale: b'(0) = 0 makes h C1 across the wall (the two sides meet
// level), b(1) = b'(1) = 0 at the groove's edge. Where two walls meet the gradient turns (a crease
// along the groove's junctions). The field lives in 3D and the surface slices it, so the
// plateaus are polygons of varying size and the grooves meet at varying angles.
// The feature points of the 27 cells around p are all hashed (one mix each); walls are sought only
// to points nearer than |q - c1| + 2w (d_k >= (|q - c_k| - |q - c1|) / 2, the triangle
// inequality, so farther points have no wall within w).
#include "lacrima/base/math.hpp"

namespace lacrima {

inline constexpr float kFurrowHalfWidth = 0.06f;  // groove half-width as a fraction of the cell size

struct FurrowHeight {
  float height = 0.0f;           // metres, <= 0 (grooves)
  Vec3 gradient = Vec3::Zero();  // d height / d position (dimensionless slope)
};

// The furrow height field and its analytic gradient at world position p. scale > 0, depth >= 0.
FurrowHeight furrowHeight(const Vec3& p, float scale, float depth);

}  // namespace lacrima
