#pragma once
// Eyelashes as fine geometry: thin tapered curved tubes grown along the strips of a lash-card mesh
// (the ICT face's M_EyeLashes: per lid a few strips, each a grid of columns along the lid margin
// by rows from root to tip). Alpha cards without a texture would render as opaque bands; tubes
// need no texture and cast real shadows on the lid and eye. A lash lives in the strip's grid
// coordinates, so on every frame it is rebuilt on the posed strips and follows the lid exactly.
#include <cstdint>
#include <string>
#include <vector>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

// One strip of a card mesh: vertices[row * columns + column], row 0 at the root (the end nearer
// the eye), columns along the lid.
struct LashStrip {
  int columns = 0, rows = 0;
  std::vector<uint32_t> vertices;
  Vec3 restCentroid = Vec3::Zero();
};

// The strips of a card mesh: its connected pieces, each a grid by its texture coordinates (distinct
// u = columns, distinct v = rows). The root row is the end nearer to `eyeCenter` for each strip.
// Throws InputError naming `what` when the mesh has no uvs or a piece is not such a grid.
std::vector<LashStrip> findLashStrips(const TriangleMesh& cards, const Vec3& eyeCenter, const std::string& what);

struct LashParams {
  int upper = 100, lower = 50;      // lashes per lid
  float rootRadius = 50e-6f;        // metres (human lashes 40-60 um at the root)
  float tipRadius = 8e-6f;          // metres
  float minLength = 0.75f;          // each lash is its strip's length times a random factor in [minLength, 1]
  float spread = 0.4e-3f;           // metres: random sideways drift of the tip along the lid
  int sides = 5;                    // of the tube's cross-section
  uint64_t seed = 1;
};

// A lash on a strip: its fractional column, length factor and tip drift (metres, along the lid).
struct Lash {
  uint32_t strip = 0;
  float column = 0.0f;
  float lengthFactor = 1.0f;
  float drift = 0.0f;
  bool upper = true;
};

// Places params.upper lashes on the strips above the eye centre (along `up`) and params.lower on
// those below, spread evenly over each lid's strips, deterministic for params.seed. Only strips
// whose rest centroid lies within `reach` of eyeCenter belong to this eye.
std::vector<Lash> placeLashes(const std::vector<LashStrip>& strips, const Vec3& eyeCenter, const Vec3& up, float reach,
                              const LashParams& params);

// The lash's centreline on posed cards (same topology as the rest cards), root first.
std::vector<Vec3> lashCentreline(const LashStrip& strip, const Lash& lash, const TriangleMesh& posedCards);

// All lashes as closed tapered tubes on the posed cards.
TriangleMesh buildLashes(const std::vector<LashStrip>& strips, const std::vector<Lash>& lashes,
                         const TriangleMesh& posedCards, const LashParams& params);

}  // namespace lacrima
