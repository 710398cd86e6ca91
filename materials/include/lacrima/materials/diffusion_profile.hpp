#pragma once
// The diffusion reflectance profile of Christensen & Burley 2015 ("Approximate Reflectance
// Profiles for Efficient Subsurface Scattering", Pixar Technical Memo 15-04), the faster of
// lacrima's two subsurface methods: light that enters a flat semi-infinite medium at one point
// leaves at distance r with the radial profile (eq. 2)
//   R(r) = A (exp(-r/d) + exp(-r/(3d))) / (8 pi d r),
// whose integral over the plane is exactly A, the medium's total diffuse reflectance (here the
// skin's albedo). The shape d follows from the volume mean free path l and A by their fit for
// diffuse surface transmission (eq. 8, the cosine-distributed entry the random walk also uses):
//   d = l / s,  s = 1.9 - A + 3.5 (A - 0.8)^2.
// So the same skin parameters drive both methods, and with the same mean free path the profile
// approximates what the random walk (subsurface.hpp) produces on a slab.
//
// The profile is cut at maxRadius, the radius holding 99 % of its energy, and scaled by 1 / 0.99
// so that it still integrates to A: probe rays then stay short, and the rare far exits that would
// land in a differently lit place (the bright, coloured outliers of a render) are not sampled.
// Sampling the radius: 2 pi r R(r) / A = (1/4) (1/d) exp(-r/d) + (3/4) (1/(3d)) exp(-r/(3d)), a
// mixture of two exponentials, sampled exactly within maxRadius.
#include "lacrima/base/math.hpp"

namespace lacrima {

class DiffusionProfile {
 public:
  // albedo A and volume mean free path l (metres) per channel; A is clamped to [0, 1], l floored.
  DiffusionProfile(const Color& albedo, const Color& meanFreePath);

  const Color& albedo() const { return albedo_; }
  const Color& shape() const { return shape_; }  // d per channel, metres

  // R(r) per unit area, per channel (r > 0): zero from maxRadius on, scaled by 1 / 0.99 within.
  Color eval(float r) const;
  // Radius holding 99 % of channel c's untruncated energy: probes reach no further.
  float maxRadius(int channel) const { return maxRadius_[channel]; }
  // Density of sampleRadius's r for channel c (per unit length, truncated at maxRadius).
  float radiusPdf(int channel, float r) const;
  // A radius distributed as 2 pi r R_c(r) on [0, maxRadius(c)), u in [0, 1).
  float sampleRadius(int channel, float u) const;

 private:
  Color albedo_;
  Color shape_;
  Color maxRadius_;
};

// Christensen & Burley 2015, eq. 8: the scaling s between the volume mean free path and d.
float burleyDiffuseTransmissionScaling(float albedo);

}  // namespace lacrima
