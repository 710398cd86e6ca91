#pragma once
// A procedural iris: per-channel factors on a material's albedo over the iris's disc uvs
// (face/eye.hpp: the pupil margin on the circle of radius 0.5 kIrisUvPupilRadius about
// (0.5, 0.5), the root on the circle of radius 0.5). It is built in layers, as an ocularist paints
// an iris for a prosthetic eye and as Lefohn, Budge, Shirley, Caruso & Reinhard 2003 synthesise
// irises from such layers; the layers and their sizes are modelling choices after the iris's
// visible anatomy:
// - radial fibres (the stroma's trabeculae): brightness noise that varies fast around the iris
//   and slowly along its radius, so it streaks from the pupil to the root;
// - the collarette, a lighter, warmer, wavy ridge about a third of the way from the pupil margin
//   to the root, dividing a slightly darker pupillary zone from the ciliary zone;
// - crypts, dark openings in the stroma, elongated along the fibres, just outside the collarette;
// - the pupillary ruff, a thin dark fringe at the pupil margin;
// - the limbal ring, a darkening over the outer sixth to the root.
// The factors are normalised to a mean of 1 per channel over the iris's area, so the material's
// albedo stays the iris's mean colour. Deterministic in (uv, seed).
#include <cstdint>

#include "lacrima/base/math.hpp"

namespace lacrima {

class IrisPattern {
 public:
  explicit IrisPattern(uint64_t seed);
  // The albedo factors at uv; inside the pupil and outside the root, those of the nearest edge.
  Color factorAt(const Vec2& uv) const;
  uint64_t seed() const { return seed_; }

 private:
  Color rawFactorAt(const Vec2& uv) const;
  uint64_t seed_;
  Color normalisation_ = Color(1.0f, 1.0f, 1.0f);
};

}  // namespace lacrima
