#pragma once
// Physics building blocks for tears sitting on, sliding over and hanging from skin: fluid
// constants, the exact axisymmetric sessile drop of the Young-Laplace equation, a spherical-cap
// bead model, the Furmidge stick/slide criterion and Tate's law for a hanging drop. Pure functions
// of SI values (metres, kg, seconds, radians); no meshes, no shots. Bad arguments (non-positive
// volume, contact angle outside (0, pi), ...) throw InputError naming the argument.
//
// Geometry convention (Bashforth & Adams 1883; Hoorfar & Neumann 2006, Adv. Colloid Interface
// Sci. 121:25, "Recent progress in ADSA", the Laplace equation section): the drop sits on a horizontal plane, its
// profile is described from the apex downwards by the arc length s, the radial distance x(s) and
// the depth below the apex z(s) (z grows towards the plane), and the tangent angle phi(s) from
// the horizontal. The plane is at z = height.
#include <numbers>
#include <optional>
#include <vector>

namespace lacrima {

inline constexpr double kMicrolitre = 1e-9;  // m^3

// Tear fluid constants; the defaults are the project's architecture-doc values for human tears.
struct TearFluid {
  double surfaceTension = 0.044;  // N/m: human tears 42-46 mN/m (Tiffany, Winter & Bliss 1989, Curr. Eye Res. 8:507)
  double density = 1000.0;        // kg/m^3: tears are ~98% water (water 998 kg/m^3 at 20 C)
  double gravity = 9.81;          // m/s^2: standard gravity 9.80665, rounded

  // lc = sqrt(gamma / (rho g)) (de Gennes, Brochard-Wyart & Quere 2004, "Capillarity and Wetting
  // Phenomena", ch. 2, the capillary length): ~2.12 mm for the defaults.
  double capillaryLength() const;
  // Bo = rho g R^2 / gamma = (R / lc)^2 for a drop of radius R (same reference).
  double bondNumber(double radius) const;
};

// Throws InputError unless every constant is finite and positive.
void validateTearFluid(const TearFluid& fluid);

// Radius of the sphere with this volume, R = (3 V / (4 pi))^(1/3): the length used for the Bond
// number of a drop throughout this file.
double equivalentSphereRadius(double volume);

// ---------------------------------------------------------------------------------------------
// Spherical cap (the zero-gravity sessile drop): a sphere of radius R cut by a plane so that the
// liquid meets it at contact angle theta. Closed forms (de Gennes et al. 2004, ch. 1):
//   base radius a = R sin(theta),  height h = R (1 - cos(theta)),
//   V = pi R^3 (1 - cos(theta))^2 (2 + cos(theta)) / 3.
struct SphericalCap {
  double sphereRadius = 0.0;
  double baseRadius = 0.0;
  double height = 0.0;
};
double sphericalCapVolume(double sphereRadius, double contactAngle);
SphericalCap sphericalCapFromVolume(double volume, double contactAngle);

// Height of a very large drop (a gravity puddle), h_inf = 2 lc sin(theta / 2)
// (de Gennes et al. 2004, ch. 2, "gravity puddles", from the horizontal force balance).
double puddleHeight(double capillaryLength, double contactAngle);

// ---------------------------------------------------------------------------------------------
// Axisymmetric sessile drop, Young-Laplace equation in Bashforth-Adams form (Hoorfar & Neumann
// 2006), with b the apex radius of curvature and lc the capillary length:
//   dx/ds = cos(phi),  dz/ds = sin(phi),  dphi/ds = 2/b + z/lc^2 - sin(phi)/x,
//   dV/ds = pi x^2 sin(phi)     (volume of the discs between apex and depth z),
// starting at x = z = phi = V = 0 where dphi/ds = 1/b (the limit sin(phi)/x -> dphi/ds). RK4 with
// a fixed step min(b, lc) / stepsPerLength; the last step is shortened (bisection on its length)
// so the profile ends exactly at phi = theta, the contact line. For theta > 90 degrees x grows
// to the equator (phi = 90 degrees) and then shrinks to the contact radius.
struct SessileProfilePoint {
  double s = 0.0;    // arc length from the apex
  double x = 0.0;    // radial distance from the axis
  double z = 0.0;    // depth below the apex
  double phi = 0.0;  // tangent angle from the horizontal, radians
};

struct SessileDrop {
  double apexRadius = 0.0;     // b
  double contactAngle = 0.0;   // theta, radians
  double contactRadius = 0.0;  // x at the contact line
  double maxRadius = 0.0;      // widest x (the equator when theta > 90 degrees, else contactRadius)
  double height = 0.0;         // z at the contact line
  double volume = 0.0;
  std::vector<SessileProfilePoint> profile;  // apex first, contact line last

  // Height over contact diameter, h / (2 a).
  double aspectRatio() const { return height / (2.0 * contactRadius); }
};

struct SessileSolveOptions {
  int stepsPerLength = 400;           // RK4 steps per min(b, lc) of arc length
  double volumeTolerance = 1e-12;     // relative tolerance on the volume when solving for b
  bool keepProfile = true;            // store the profile of the returned drop
};

// One shot of the profile for a given apex radius b (> 0). capillaryLength may be +infinity
// (no gravity: the exact spherical cap of radius b).
SessileDrop integrateSessileDrop(double apexRadius, double contactAngle, double capillaryLength,
                                 const SessileSolveOptions& options = {});

// The drop of the given volume: bisection on log(b) (the volume grows monotonically with b),
// starting from the spherical cap's radius and widening the bracket by factors of 2.
SessileDrop solveSessileDrop(double volume, double contactAngle, double capillaryLength,
                             const SessileSolveOptions& options = {});

// ---------------------------------------------------------------------------------------------
// Bead on a tilted surface (the "cross-section is a spherical cap"). The model, kept
// deliberately simple:
// * Start from the spherical cap of the bead's volume and contact angle (a0, h0).
// * Flattening by the gravity component normal to the surface, g cos(tilt): the height becomes
//   that of the axisymmetric Young-Laplace drop of the same volume and angle under g cos(tilt),
//   flattening = h_YL / h0 <= 1. The cap is scaled by flattening along the normal and by
//   1 / sqrt(flattening) in the surface plane, which keeps its volume (a cap scaled by (s, s, t)
//   has volume s^2 t V0).
// * Head elongation by the component along the surface, g sin(tilt): by analogy with the
//   flattening (the same Young-Laplace deformation, now driven along the slope), the footprint is
//   stretched along the fall line by elongation = 1 / sqrt(flattening under g sin(tilt)) and
//   narrowed across it by 1 / elongation, again volume-preserving. This is a modelling choice,
//   not a solution of the 3-D problem; ElSherbini & Jacobi 2004 (J. Colloid Interface Sci.
//   273:556, "Liquid drops on vertical and inclined surfaces I") measured such elongated
//   footprints (length / width above 1, growing with Bond number) on inclined plates.
// tilt is the angle of the surface from the horizontal in [0, pi/2] (0 = floor, pi/2 = wall).
struct BeadShape {
  SphericalCap cap;           // undeformed spherical cap of the bead's volume and angle
  double flattening = 1.0;    // height multiplier from g cos(tilt), in (0, 1]
  double elongation = 1.0;    // footprint stretch along the fall line from g sin(tilt), >= 1
  double height = 0.0;        // cap.height * flattening
  double halfLength = 0.0;    // footprint semi-axis along the fall line
  double halfWidth = 0.0;     // footprint semi-axis across it
};
BeadShape beadShape(const TearFluid& fluid, double volume, double contactAngle, double tilt);

// h_YL / h_cap: height of the Young-Laplace drop of this volume and angle under gravity g over
// the spherical cap's height (g may be 0: returns 1).
double gravityFlattening(const TearFluid& fluid, double volume, double contactAngle, double gravity);

// ---------------------------------------------------------------------------------------------
// Stick and slide: contact-angle hysteresis (Furmidge 1962, J. Colloid Sci. 17:309, "Studies at
// phase interfaces I. The sliding of liquid drops on solid surfaces"). A drop on a plane tilted by
// alpha stays pinned while its weight along the plane is below the retention force:
//   rho V g sin(alpha) < k gamma w (cos(theta_R) - cos(theta_A)),
// w the base width across the fall line, k a shape factor: Furmidge k = 1; ElSherbini & Jacobi
// 2006 (J. Colloid Interface Sci. 299:841, "Retention forces and contact angles for critical
// liquid drops on non-horizontal surfaces") k = 24 / pi^3 ~ 0.774, the default here.
// w is the base diameter 2 a of the spherical cap of the drop's volume at the mean angle
// (theta_A + theta_R) / 2 (a modelling choice; it makes w proportional to V^(1/3)).
struct ContactAngleHysteresis {
  double advancing = 0.0;  // theta_A, radians
  double receding = 0.0;   // theta_R, radians, 0 < theta_R <= theta_A < pi
};

inline constexpr double kElSherbiniJacobiRetentionFactor = 24.0 / (std::numbers::pi * std::numbers::pi * std::numbers::pi);
inline constexpr double kFurmidgeRetentionFactor = 1.0;

struct SlidingModel {
  TearFluid fluid;
  ContactAngleHysteresis hysteresis;
  double retentionFactor = kElSherbiniJacobiRetentionFactor;  // k
};

// w: base diameter of the spherical cap of this volume at the mean contact angle.
double slidingBaseWidth(const SlidingModel& model, double volume);
// k gamma w (cos(theta_R) - cos(theta_A)), newtons.
double retentionForce(const SlidingModel& model, double volume);
// rho V g sin(tilt) >= retention force; tilt in [0, pi] from the horizontal.
bool dropSlides(const SlidingModel& model, double volume, double tilt);
// Smallest tilt in [0, pi/2] at which the drop slides; nullopt when even a vertical wall holds it.
std::optional<double> criticalTiltAngle(const SlidingModel& model, double volume);
// Smallest volume that slides at this tilt in (0, pi) (closed form, see the .cpp).
double criticalSlidingVolume(const SlidingModel& model, double tilt);
// The criterion as a critical Bond number, Bo_c sin(alpha) with Bo = (R / lc)^2 and R the
// equivalent sphere radius: depends on the contact angles and k only (algebra in the .cpp).
double criticalBondSinTilt(const SlidingModel& model);

// ---------------------------------------------------------------------------------------------
// Hanging drop pinned on a circle of radius r under a downward-facing surface (chin, jaw).
// Tate's law (Tate 1864, Phil. Mag. 27:176): the weight surface tension can hold is the
// tension along the pinned circle, rho g V = 2 pi r gamma, so V_max = 2 pi r gamma / (rho g).
// With the Harkins-Brown correction (Harkins & Brown 1919, J. Am. Chem. Soc. 41:499) the volume
// that actually detaches is V = psi(r / V^(1/3)) V_max, psi read from their empirical table
// (0.3 <= r / V^(1/3) <= 1.2; outside it InputError).
enum class DetachmentCorrection { None, HarkinsBrown };
double hangingDropMaxVolume(const TearFluid& fluid, double pinnedRadius,
                            DetachmentCorrection correction = DetachmentCorrection::None);
// psi of the Harkins-Brown table, linearly interpolated in r / V^(1/3).
double harkinsBrownFactor(double radiusOverCubeRootVolume);

}  // namespace lacrima
