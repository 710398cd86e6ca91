#pragma once
// Dielectric Fresnel reflectance and the ideal reflection/refraction directions.
//
// Parameters: `eta` is always the relative index of refraction of the interface,
// eta = n_inside / n_outside, where "inside" is the side the normal points away from
// (for a water drop in air, eta = 1.337). A cosine cosThetaI > 0 means the incident direction is
// on the outside (normal side); cosThetaI < 0 means it is inside, and the functions then use 1/eta.
// Directions point away from the surface (pbrt-v4 convention).
//
// Sources: Fresnel equations for unpolarised light between two dielectrics, Hecht, "Optics"
// (5th ed.) §4.6.2, in the form of pbrt-v4 FrDielectric; Snell's law and the vector
// form of the refracted direction from pbrt-v4 Refract.
#include <optional>

#include "lacrima/base/math.hpp"

namespace lacrima {

// Unpolarised reflectance R = (r_par^2 + r_perp^2) / 2 for light arriving at angle acos(|cosThetaI|)
// on the side given by the sign of cosThetaI. Returns 1 under total internal reflection.
float fresnelDielectric(float cosThetaI, float eta);

// Mirror direction of w about the unit normal n (both pointing away from the surface).
Vec3 reflect(const Vec3& w, const Vec3& n);

struct Refraction {
  Vec3 wt;     // refracted direction, pointing away from the surface on the other side
  float etap;  // relative IOR actually crossed: n_(side of wt) / n_(side of wi)
};

// Direction of the ray refracted from wi through an interface with normal n and relative IOR
// eta = n_(side n points away from) / n_(side of n). wi may be on either side of n.
// Returns nothing under total internal reflection.
std::optional<Refraction> refract(const Vec3& wi, const Vec3& n, float eta);

}  // namespace lacrima
