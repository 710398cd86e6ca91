#pragma once
// Shape oscillation of a free-falling tear drop: a drop that
// leaves the skin stretched along gravity rings in its fundamental Rayleigh/Lamb mode n = 2
// (prolate <-> oblate about its axis) while it falls, and viscosity damps the ringing.
//
// Laws (SI units):
// * Frequency: omega_n^2 = n (n - 1) (n + 2) sigma / (rho R^3) (Rayleigh 1879, Proc. R. Soc. 29:71,
//   "On the capillary phenomena of jets", free drop modes); n = 2: omega^2 = 8 sigma / (rho R^3).
// * Damping: the amplitude decays as exp(-t / tau), tau = R^2 / ((n - 1)(2n + 1) nu) (Lamb 1932,
//   "Hydrodynamics", 6th ed., art. 355, weak viscosity); n = 2: tau = R^2 / (5 nu), nu = mu / rho.
//   Weak damping (omega tau ~ 100 for tear drops) leaves the frequency unchanged to first order, so
//   the amplitude is eps(t) = eps0 cos(omega t) exp(-t / tau) (released at rest at its largest
//   deformation, t = 0 at detachment).
// * Shape: the n = 2 mode r = R (1 + eps P2(cos theta)) gives, to first order, the semi-axes
//   c = R (1 + eps) along the axis and a = R (1 - eps / 2) across it. Drawn as the axisymmetric
//   ellipsoid (a, a, c) with exactly that axis ratio c / a = (1 + eps) / (1 - eps / 2), scaled so
//   that a^2 c = R^3 (the volume is kept at every amplitude, not just to first order). eps > 0 is
//   prolate (stretched along the axis), eps < 0 oblate. The inverse, eps = 2 (k - 1) / (k + 2) for
//   k = c / a, recovers the amplitude from a drawn shape.
#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/liquid/sessile_drop.hpp"

namespace lacrima {

// omega of mode n >= 2 of a free drop of radius R (rad/s). Throws InputError for bad arguments.
double rayleighAngularFrequency(const TearFluid& fluid, double radius, int mode = 2);
// tau of mode n >= 2 (s): the amplitude's e-folding time; kinematicViscosity = mu / rho (m^2/s).
double lambDampingTime(double radius, double kinematicViscosity, int mode = 2);

// Semi-axes of the axisymmetric ellipsoid of the n = 2 mode.
struct SpheroidAxes {
  double equatorial = 0.0;  // a, across the axis
  double polar = 0.0;       // c, along the axis
};
// The ellipsoid of amplitude eps in (-1, 2) with a^2 c = R^3 (see the top). Throws InputError otherwise.
SpheroidAxes modeTwoSpheroid(double radius, double amplitude);
// eps of a spheroid of axis ratio k = c / a > 0: 2 (k - 1) / (k + 2).
double modeTwoAmplitudeFromAspect(double aspect);

// The ringing of one drop after it detached.
struct DropOscillation {
  double initialAmplitude = 0.0;  // eps0 at detachment
  double angularFrequency = 0.0;  // omega
  double dampingTime = 0.0;       // tau

  // eps(t) = eps0 cos(omega t) exp(-t / tau), t seconds since detachment (t < 0: eps0).
  double amplitudeAt(double t) const;
  // eps0 exp(-t / tau) (t < 0: eps0).
  double envelopeAt(double t) const;
};

// The oscillation of a drop of this volume released with amplitude eps0, tear fluid of this
// dynamic viscosity (Pa s).
DropOscillation dropOscillation(const TearFluid& fluid, double viscosity, double volume, double initialAmplitude);

// The drawn drop: a closed, outward-oriented UV ellipsoid (makeEllipsoid, `rings` x `segments`,
// analytic normals, named "falling drop") with semi-axes (a, a, c), c along `axis` (normalised
// here; non-zero), centred at `centre`. Its axes are scaled by the constant (4 pi / 3 / V1)^(1/3),
// V1 the volume of the unit sphere of that tessellation, so the polyhedron holds exactly the volume
// 4/3 pi a^2 c of the ellipsoid (an inscribed tessellation would hold ~1% less). The vertex layout
// depends on rings and segments only: two drops of one tessellation correspond vertex by vertex
// (deformation blur). Throws InputError for non-positive axes or a zero axis.
struct FallingDropResolution {
  int rings = 24;
  int segments = 48;
};
TriangleMesh makeFallingDropMesh(const Vec3d& centre, const Vec3d& axis, const SpheroidAxes& axes,
                                 const FallingDropResolution& resolution = {});

}  // namespace lacrima
