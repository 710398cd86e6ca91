#pragma once
// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic.
//
// Parameters: `alpha` is the GGX width (slope-space standard deviation / sqrt(2)); materials expose
// a perceptual `roughness` and use alpha = roughness^2 (Burley 2012, "Physically-Based Shading at
// Disney", "Specular D"), clamped to alpha >= kMinAlpha so that the distribution stays representable in
// float (a truly smooth surface is the SmoothDielectricBsdf's job).
// Directions are in the local shading frame (z = macro normal). Microfacet normals wm are always
// in the upper hemisphere; functions of a direction w accept w on either side and use |cos|.
//
// Sources: D and G1 from Walter et al. 2007, "Microfacet Models for Refraction through Rough
// Surfaces" (EGSR), eqs. 33-34; Smith Lambda and the *height-correlated* masking-shadowing
// G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) from Heitz 2014, "Understanding the Masking-Shadowing
// Function in Microfacet-Based BRDFs" (JCGT 3(2)), eqs. 43, 72, 99; visible normals and their
// sampling from Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)).
#include "lacrima/base/math.hpp"

namespace lacrima {

inline constexpr float kMinAlpha = 1e-3f;

// alpha = roughness^2 (Burley 2012, "Specular D"), clamped to [kMinAlpha, 1].
float roughnessToAlpha(float roughness);

class GgxDistribution {
 public:
  explicit GgxDistribution(float alpha);

  float alpha() const { return alpha_; }

  // Normal distribution D(wm), normalised so that integral D(wm) cos(theta_m) dwm = 1
  // (Walter 2007 eq. 33). Zero for wm below the horizon.
  float D(const Vec3& wm) const;

  // Smith auxiliary function Lambda(w) (Heitz 2014 eq. 72).
  float lambda(const Vec3& w) const;

  // Smith masking G1(w) = 1 / (1 + Lambda(w)) (Heitz 2014 eq. 43; equals Walter 2007 eq. 34).
  float G1(const Vec3& w) const;

  // Height-correlated masking-shadowing G2(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi))
  // (Heitz 2014 eq. 99). Used for transmission too, as pbrt-v4 does (the exact height-correlated
  // transmission term is a Beta function, Heitz 2014 §6; the difference is small).
  float G(const Vec3& wo, const Vec3& wi) const;

  // Distribution of normals visible from w: D_w(wm) = G1(w) max(0, w.wm) D(wm) / cos(theta_w)
  // (Heitz 2018 eq. 1). A density over wm (solid angle), integrates to 1 over the upper hemisphere.
  // For w below the surface it is the distribution visible from the mirrored direction -w, which
  // is the set of facets whose back side faces w.
  float visibleD(const Vec3& w, const Vec3& wm) const;

  // Sample wm from visibleD(w, .) with u in [0,1)^2 (Heitz 2018, Appendix A / Listing 1).
  Vec3 sampleVisibleNormal(const Vec3& w, const Vec2& u) const;

 private:
  float alpha_;
};

}  // namespace lacrima
