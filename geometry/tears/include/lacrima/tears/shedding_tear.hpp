#pragma once
// The shedding tear of Lin & Cheng 2013 section 4.2 (a tear that runs down the skin), as a closed,
// outward-oriented, watertight triangle mesh lying on a skin mesh.
//
// Surface coordinates
// -------------------
// Everything the tear needs from the skin is stored as SurfacePoints (a triangle of the skin and
// barycentric weights), not as positions. The tear is built once on a rest skin (the strip: where
// its vertices are and how thick it is there) and then placed on any mesh with the same topology
// (a deformed, bent or scaled skin): each vertex follows its skin triangle exactly.
//
// Construction (Lin & Cheng 2013 section 4.2)
// -----------------------------------
// * Step 1 (base surface): the tear path is a polyline of SurfacePoints. It is sampled every
//   sampleSpacing of (rest) arc length; at each sample, acrossSamples points are spread over the
//   width across the path in the skin's tangent plane and projected back to the nearest point of
//   the skin. The result is a rows x acrossSamples grid of SurfacePoints, finer than the face mesh
//   (the paper's "linear subdivision" of the extracted area).
// * Step 2 (top surface and walls): every grid point gets a thickness; the top surface is the base
//   offset along the skin triangle's geometric normal by it. The across profile is a parabola,
//     thickness = maxThickness * g(a) * (1 - (2 v / W(a))^2),   v in [-W(a)/2, W(a)/2],
//   thickest in the middle and zero at both edges, where top and base share their vertices (the
//   tear meets the skin with a lens-shaped cross-section, so no side walls are needed along the
//   path). The two ends of the strip are closed by lens-shaped caps. The base does not lie on the
//   skin but baseOffset above it along the same normal, so the water never coincides with the skin
//   surface (no z-fighting, and rays leaving the skin enter the water cleanly).
// * Step 3 (tear head): over the last headLength of the grown path (x from 0 to 1), the thickness
//   factor g rises smoothly from 1 to 1 + headBulge over x in [0, 1/2] (smoothstep), then both g and
//   the width factor W(a)/width close like a quarter ellipse, sqrt(1 - (2x - 1)^2), floored at
//   tipFraction so the leading cap stays a small non-degenerate lens: a bulging, rounded head.
//   Elsewhere g = 1 and W = width. Optionally (tailLength > 0) the start of the strip tapers the
//   same way over its first tailLength (a quarter ellipse from tipFraction up to 1), so the tear
//   emerges from the skin at its source rather than starting with a blunt cap.
// * Step 4 (noise): each interior grid point is raised with probability noiseDensity by a random
//   bump in [noiseAmplitude / 2, noiseAmplitude] (a hash of seed and grid index, so the same seed
//   gives bitwise the same tear, and a grid point keeps its bump while the tear grows). The bump
//   field is smoothed by moving least squares (smoothHeightField, Lin & Cheng 2013 eqs. 8-14, in (arc
//   length, across) coordinates, epsilon = smoothingEpsilon), clamped at zero, and multiplied by
//   the across parabola so the edges stay on the skin. Noise only raises: the top never goes
//   below the un-noised top.
// * Step 5 (growth): only the path up to arc length h = start + speed * t (clamped to the path's
//   length) is built; grid rows sit at fixed arc lengths 0, sampleSpacing, 2 sampleSpacing, ...
//   plus one row at h, so a longer tear contains the rows of a shorter one. With h < minimum
//   length (sampleSpacing / 4) the tear is empty (no vertices).
//
// Limits: the thickness is in absolute units and does not stretch with the skin. Only the
// vertices are guaranteed above the skin (by baseOffset); a tear triangle spanning a convex crease
// of the skin mesh can dip below the crease by about (sample spacing) x (crease angle) / 4, which a
// strip finer than the face mesh and baseOffset keep small. Sampling is brute force over the skin's
// triangles (fine for the extracted area around a tear, slow for a whole face: extractSurfaceRegion
// and stripRegionRadius in surface_region.hpp extract that area and give bitwise the same strip).
// The across direction follows the path's polyline segments, so a path turning more sharply than a
// radius of width / 2 makes neighbouring rows cross (give smooth, finely spaced paths). The step 4
// MLS fit uses every grid point for every evaluation (its weight has no compact support), so its
// cost grows with the square of the number of grid points.
#include <cstdint>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {

struct SheddingTearParams {
  float width = 0.004f;         // metres across the path
  float thickness = 0.0008f;    // metres, in the middle of the strip (before head and noise)
  float baseOffset = 2e-5f;     // metres between skin and the tear's base surface (> 0)
  float sampleSpacing = 0.0005f;  // metres of arc length between grid rows
  int acrossSamples = 9;        // grid columns across the path (>= 3; both edges included)
  float start = 0.01f;          // s in h = s + c t (metres)
  float speed = 0.01f;          // c in h = s + c t (metres per second)
  float headLength = 0.003f;    // metres of the grown path shaped as the head (0: no head)
  float headBulge = 0.5f;       // extra thickness factor of the head (>= 0)
  float tipFraction = 0.2f;     // width and thickness factor kept at the leading cap, in (0, 1]
  float tailLength = 0.0f;      // metres at the start of the path over which the tear tapers (0: blunt start)
  float noiseDensity = 0.0f;    // probability that an interior grid point gets a bump, [0, 1]
  float noiseAmplitude = 0.0003f;  // metres, largest bump before smoothing (>= 0)
  float smoothingEpsilon = 0.0005f;  // MLS epsilon in metres (> 0)
  int smoothingDegree = 2;      // MLS polynomial degree, 0..15 (lower while the tear has <= degree rows)
  uint64_t seed = 1;
};

// The tear's grid in surface coordinates: rows along the path, columns across it (row-major).
struct SheddingTearStrip {
  int rows = 0;
  int columns = 0;
  std::vector<SurfacePoint> points;  // rows * columns
  std::vector<Vec2> coordinates;     // (arc length, across offset) on the rest skin, metres
  std::vector<float> thickness;      // top height above the base, metres (0 at both edges)
  float length = 0.0f;               // grown arc length h actually built (0 for an empty tear)
};

// Builds the strip on the rest skin for time t (steps 1, 3, 4 and 5 above). The path must have at
// least two points. Throws InputError for invalid parameters or path points, or a path running
// along the skin normal (no tangent direction).
SheddingTearStrip buildSheddingTearStrip(const TriangleMesh& restSkin, const std::vector<SurfacePoint>& path,
                                         const SheddingTearParams& params, float t);

// Places a strip on `skin` (the rest skin or any mesh of the same topology) as a closed,
// outward-oriented mesh with smooth normals (step 2 above). An empty strip gives an empty mesh.
TriangleMesh sheddingTearMesh(const TriangleMesh& skin, const SheddingTearStrip& strip, float baseOffset);

// Both steps on one skin.
TriangleMesh buildSheddingTear(const TriangleMesh& skin, const std::vector<SurfacePoint>& path,
                               const SheddingTearParams& params, float t);

}  // namespace lacrima
