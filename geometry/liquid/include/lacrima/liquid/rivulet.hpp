#pragma once
// A rivulet: tear liquid running down the skin as one continuous stream, its
// cross-section and its flow rate.
//
// Duffy & Moffatt 1995 ("Flow of a viscous trickle on a slowly varying incline", Chem. Eng. J.
// 60:141) give the lubrication solution of a steady rivulet of half-width a and contact angle theta
// on a plane inclined at alpha to the horizontal. Where the rivulet is narrow against the capillary
// length (a << sqrt(gamma / (rho g)), 2.1 mm for tears; a tear rivulet is 0.2-0.5 mm wide), surface
// tension alone sets the cross-section, a parabola
//     h(y) = tan(theta) (a^2 - y^2) / (2 a),            |y| <= a          (their small-width limit)
// and the down-slope velocity is the half-Poiseuille profile of a film of local depth h, so the
// flux is
//     Q = integral of rho g sin(alpha) h^3 / (3 mu) dy = (4 / 105) (rho g sin(alpha) / mu) tan^3(theta) a^4.
// The cross-section's area is A = (2/3) tan(theta) a^2, so Q = k A^2 with
//     k = (3 / 35) (rho g sin(alpha) / mu) tan(theta).
// A rivulet whose flow rate changes along its length is then a kinematic wave, A_t + (k A^2)_s = 0
// (Lighthill & Whitham 1955, "On kinematic waves I", Proc. R. Soc. A 229:281); its disturbances
// travel at dQ/dA = 2 k A, twice the mean speed Q / A.
//
// Limits: the lubrication model is for small slopes of the free surface; at skin's contact angles
// (65-95 degrees) it is an approximation whose profile is taller than the circular arc a static
// rivulet takes (at 65 degrees the parabola holds 1.56 times the arc's area for the same width).
#include "lacrima/liquid/sessile_drop.hpp"

namespace lacrima {

struct RivuletFlow {
  TearFluid fluid;
  double viscosity = 1.5e-3;  // Pa s
  double contactAngle = 1.134;  // radians, in (0, pi/2): the angle at the rivulet's edges
  double slope = 1.5708;        // alpha, radians from the horizontal, in [0, pi]
};

// Throws InputError unless the fluid, viscosity, angle (0 < theta < pi/2) and slope are valid.
void validateRivuletFlow(const RivuletFlow& flow);

// The cross-section's area (m^2) at half-width a: (2/3) tan(theta) a^2.
double rivuletArea(const RivuletFlow& flow, double halfWidth);
// The half-width (m) of a cross-section of area A (the inverse of rivuletArea).
double rivuletHalfWidth(const RivuletFlow& flow, double area);
// The depth at the middle (m): tan(theta) a / 2.
double rivuletHeight(const RivuletFlow& flow, double halfWidth);
// k in Q = k A^2 (1 / (m s)): (3/35) (rho g sin(alpha) / mu) tan(theta); 0 on a level surface.
double rivuletFluxCoefficient(const RivuletFlow& flow);
// Q (m^3/s) of a cross-section of area A.
double rivuletFlux(const RivuletFlow& flow, double area);
// The half-width of the steady rivulet carrying Q: (105 mu Q / (4 rho g sin(alpha) tan^3(theta)))^(1/4).
double rivuletHalfWidthForFlux(const RivuletFlow& flow, double flux);

// Where a thinning rivulet breaks up, the spacing of the beads it leaves (m): the wavelength of the
// fastest-growing varicose mode of a liquid cylinder, 9.02 R (Rayleigh 1878, "On the instability
// of jets", Proc. London Math. Soc. 10:4), with R = a / sin(theta) the radius of the circular arc
// through the rivulet's edges at its contact angle. A modelling choice: Davis 1980 (J. Fluid Mech.
// 98:225) shows that the substrate and the contact lines' mobility shift the wavelength; the
// Rayleigh value is the scale, not a measured spacing for skin.
double rivuletBreakupSpacing(const RivuletFlow& flow, double halfWidth);

}  // namespace lacrima
