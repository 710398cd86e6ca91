// Sessile, sliding and hanging tear drops: see sessile_drop.hpp for the models and references.
#include "lacrima/liquid/sessile_drop.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lacrima/base/error.hpp"

namespace lacrima {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

void requirePositiveDropParameter(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0))
    throw InputError(fmt::format("{} must be a finite number > 0, got {}", what, value));
}

void requireContactAngle(double angle, const char* what) {
  if (!(angle > 0.0 && angle < std::numbers::pi))
    throw InputError(fmt::format("{} must be strictly between 0 and 180 degrees, got {:.6g} degrees", what,
                                 angle * kRadToDeg));
}

void requireCapillaryLength(double capillaryLength) {
  // +infinity is allowed: no gravity.
  if (!(capillaryLength > 0.0))
    throw InputError(fmt::format("capillary length must be > 0 (or +infinity), got {}", capillaryLength));
}

void requireHysteresis(const ContactAngleHysteresis& h) {
  requireContactAngle(h.advancing, "advancing contact angle");
  requireContactAngle(h.receding, "receding contact angle");
  if (h.receding > h.advancing)
    throw InputError(fmt::format("receding contact angle ({:.6g} degrees) must not exceed the advancing one ({:.6g} degrees)",
                                 h.receding * kRadToDeg, h.advancing * kRadToDeg));
}

// (1 - cos)^2 (2 + cos): V = pi R^3 capShape / 3 for a cap of sphere radius R.
double capShape(double contactAngle) {
  const double c = std::cos(contactAngle);
  return (1.0 - c) * (1.0 - c) * (2.0 + c);
}

// ---- Young-Laplace profile ------------------------------------------------------------------

struct ProfileState {
  double x = 0.0, z = 0.0, phi = 0.0, volume = 0.0;
};

ProfileState scaledSum(const ProfileState& a, const ProfileState& d, double h) {
  return {a.x + h * d.x, a.z + h * d.z, a.phi + h * d.phi, a.volume + h * d.volume};
}

// Bashforth-Adams right-hand side (Hoorfar & Neumann 2006), plus dV/ds.
ProfileState profileDerivative(const ProfileState& p, double twoOverB, double invLc2) {
  const double pressureCurvature = twoOverB + p.z * invLc2;
  // At the apex sin(phi)/x -> dphi/ds, so dphi/ds = pressureCurvature / 2 (= 1/b at z = 0).
  const double dphi = p.x > 0.0 ? pressureCurvature - std::sin(p.phi) / p.x : 0.5 * pressureCurvature;
  const double sinPhi = std::sin(p.phi);
  return {std::cos(p.phi), sinPhi, dphi, std::numbers::pi * p.x * p.x * sinPhi};
}

ProfileState rk4Step(const ProfileState& p, double h, double twoOverB, double invLc2) {
  const ProfileState k1 = profileDerivative(p, twoOverB, invLc2);
  const ProfileState k2 = profileDerivative(scaledSum(p, k1, 0.5 * h), twoOverB, invLc2);
  const ProfileState k3 = profileDerivative(scaledSum(p, k2, 0.5 * h), twoOverB, invLc2);
  const ProfileState k4 = profileDerivative(scaledSum(p, k3, h), twoOverB, invLc2);
  return {p.x + h / 6.0 * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x),
          p.z + h / 6.0 * (k1.z + 2.0 * k2.z + 2.0 * k3.z + k4.z),
          p.phi + h / 6.0 * (k1.phi + 2.0 * k2.phi + 2.0 * k3.phi + k4.phi),
          p.volume + h / 6.0 * (k1.volume + 2.0 * k2.volume + 2.0 * k3.volume + k4.volume)};
}

// Length in (0, fullStep] of the RK4 step from `from` that ends at phi = target (phi grows along
// the step, the full step reaches the target): bisection to double precision.
double stepLengthToAngle(const ProfileState& from, double fullStep, double target, double twoOverB, double invLc2) {
  double shortStep = 0.0, longStep = fullStep;
  for (int i = 0; i < 64 && longStep - shortStep > 0.0; ++i) {
    const double mid = 0.5 * (shortStep + longStep);
    if (rk4Step(from, mid, twoOverB, invLc2).phi >= target) longStep = mid;
    else shortStep = mid;
  }
  return longStep;
}

// Upper bound on RK4 steps per profile: a drop profile is a few b or a few lc (times log(b/lc)
// for puddles) long, far below this; reaching it means the profile never turned to theta.
constexpr long kMaxProfileSteps = 20'000'000;

}  // namespace

// ---- Fluid --------------------------------------------------------------------------------------

double TearFluid::capillaryLength() const { return std::sqrt(surfaceTension / (density * gravity)); }

double TearFluid::bondNumber(double radius) const { return density * gravity * radius * radius / surfaceTension; }

void validateTearFluid(const TearFluid& fluid) {
  requirePositiveDropParameter(fluid.surfaceTension, "tear fluid surface tension (N/m)");
  requirePositiveDropParameter(fluid.density, "tear fluid density (kg/m^3)");
  requirePositiveDropParameter(fluid.gravity, "gravity (m/s^2)");
}

double equivalentSphereRadius(double volume) {
  requirePositiveDropParameter(volume, "drop volume");
  return std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));
}

// ---- Spherical cap and puddle ---------------------------------------------------------------------

double sphericalCapVolume(double sphereRadius, double contactAngle) {
  requirePositiveDropParameter(sphereRadius, "sphere radius");
  requireContactAngle(contactAngle, "contact angle");
  return std::numbers::pi * sphereRadius * sphereRadius * sphereRadius * capShape(contactAngle) / 3.0;
}

SphericalCap sphericalCapFromVolume(double volume, double contactAngle) {
  requirePositiveDropParameter(volume, "drop volume");
  requireContactAngle(contactAngle, "contact angle");
  SphericalCap cap;
  cap.sphereRadius = std::cbrt(3.0 * volume / (std::numbers::pi * capShape(contactAngle)));
  cap.baseRadius = cap.sphereRadius * std::sin(contactAngle);
  cap.height = cap.sphereRadius * (1.0 - std::cos(contactAngle));
  return cap;
}

double puddleHeight(double capillaryLength, double contactAngle) {
  requirePositiveDropParameter(capillaryLength, "capillary length");
  requireContactAngle(contactAngle, "contact angle");
  return 2.0 * capillaryLength * std::sin(0.5 * contactAngle);
}

// ---- Young-Laplace sessile drop ------------------------------------------------------------------

SessileDrop integrateSessileDrop(double apexRadius, double contactAngle, double capillaryLength,
                                 const SessileSolveOptions& options) {
  requirePositiveDropParameter(apexRadius, "apex radius of curvature");
  requireContactAngle(contactAngle, "contact angle");
  requireCapillaryLength(capillaryLength);
  if (options.stepsPerLength < 4)
    throw InputError(fmt::format("stepsPerLength must be >= 4, got {}", options.stepsPerLength));

  const double twoOverB = 2.0 / apexRadius;
  const double invLc2 = std::isinf(capillaryLength) ? 0.0 : 1.0 / (capillaryLength * capillaryLength);
  const double step = std::min(apexRadius, capillaryLength) / options.stepsPerLength;

  SessileDrop drop;
  drop.apexRadius = apexRadius;
  drop.contactAngle = contactAngle;
  ProfileState state;
  double s = 0.0;
  if (options.keepProfile) drop.profile.push_back({0.0, 0.0, 0.0, 0.0});

  // Land exactly on the equator (phi = 90 degrees, the widest point) when the drop has one, then on
  // the contact line.
  std::array<double, 2> targets = {contactAngle, contactAngle};
  const bool hasEquator = contactAngle > 0.5 * std::numbers::pi;
  if (hasEquator) targets[0] = 0.5 * std::numbers::pi;
  long steps = 0;
  for (size_t t = hasEquator ? 0 : 1; t < targets.size(); ++t) {
    while (state.phi < targets[t]) {
      if (++steps > kMaxProfileSteps)
        throw std::runtime_error(fmt::format("sessile drop profile (b = {}, lc = {}) did not reach the contact angle",
                                             apexRadius, capillaryLength));
      double h = step;
      ProfileState next = rk4Step(state, h, twoOverB, invLc2);
      if (next.phi >= targets[t]) {
        h = stepLengthToAngle(state, step, targets[t], twoOverB, invLc2);
        next = rk4Step(state, h, twoOverB, invLc2);
        next.phi = std::max(next.phi, targets[t]);  // bisection leaves it within rounding of the target
      }
      state = next;
      s += h;
      if (options.keepProfile) drop.profile.push_back({s, state.x, state.z, state.phi});
    }
    if (hasEquator && t == 0) drop.maxRadius = state.x;
  }
  drop.contactRadius = state.x;
  if (!hasEquator) drop.maxRadius = state.x;
  drop.height = state.z;
  drop.volume = state.volume;
  return drop;
}

SessileDrop solveSessileDrop(double volume, double contactAngle, double capillaryLength,
                             const SessileSolveOptions& options) {
  requirePositiveDropParameter(volume, "drop volume");
  requireContactAngle(contactAngle, "contact angle");
  requireCapillaryLength(capillaryLength);
  SessileSolveOptions shooting = options;
  shooting.keepProfile = false;
  const auto volumeFor = [&](double b) { return integrateSessileDrop(b, contactAngle, capillaryLength, shooting).volume; };

  // Gravity only sharpens the profile below the apex, so the cap's radius is a good starting point
  // (usually already a lower bound). Widen until the volume is bracketed; upwards by growing
  // factors 2, 4, 8, ... because a puddle's apex radius grows exponentially with its size
  // (b ~ 1e37 lc for a puddle 87 lc wide).
  const double capRadius = sphericalCapFromVolume(volume, contactAngle).sphereRadius;
  double low = capRadius, high = capRadius;
  for (int i = 0; volumeFor(low) > volume; ++i) {
    if (i > 200) throw std::runtime_error("sessile drop: could not bracket the apex radius from below");
    low *= 0.5;
  }
  double factor = 2.0;
  for (int i = 0; volumeFor(high) < volume; ++i) {
    if (i > 30) throw std::runtime_error("sessile drop: could not bracket the apex radius from above");
    low = std::max(low, high);
    high *= factor;
    factor *= 2.0;
  }
  // Bisection on log(b): for puddles b grows exponentially with the radius.
  double b = std::sqrt(low * high);
  for (int i = 0; i < 200; ++i) {
    b = std::sqrt(low * high);
    const double v = volumeFor(b);
    if (std::abs(v - volume) <= options.volumeTolerance * volume || high / low - 1.0 < 1e-15) break;
    if (v < volume) low = b;
    else high = b;
  }
  return integrateSessileDrop(b, contactAngle, capillaryLength, options);
}

// ---- Bead on a tilted surface ---------------------------------------------------------------------

double gravityFlattening(const TearFluid& fluid, double volume, double contactAngle, double gravity) {
  validateTearFluid(fluid);
  if (!(std::isfinite(gravity) && gravity >= 0.0))
    throw InputError(fmt::format("gravity component must be finite and >= 0, got {}", gravity));
  const SphericalCap cap = sphericalCapFromVolume(volume, contactAngle);
  if (gravity == 0.0) return 1.0;
  TearFluid scaled = fluid;
  scaled.gravity = gravity;
  const SessileSolveOptions noProfile{.keepProfile = false};
  const SessileDrop drop = solveSessileDrop(volume, contactAngle, scaled.capillaryLength(), noProfile);
  return std::min(1.0, drop.height / cap.height);
}

BeadShape beadShape(const TearFluid& fluid, double volume, double contactAngle, double tilt) {
  if (!(tilt >= 0.0 && tilt <= 0.5 * std::numbers::pi))
    throw InputError(fmt::format("surface tilt must be between 0 and 90 degrees, got {:.6g} degrees", tilt * kRadToDeg));
  BeadShape bead;
  bead.cap = sphericalCapFromVolume(volume, contactAngle);
  // Clamp the cosine/sine so the floor and the wall get exactly zero components.
  const double normalGravity = tilt == 0.5 * std::numbers::pi ? 0.0 : fluid.gravity * std::cos(tilt);
  const double slopeGravity = tilt == 0.0 ? 0.0 : fluid.gravity * std::sin(tilt);
  bead.flattening = gravityFlattening(fluid, volume, contactAngle, normalGravity);
  bead.elongation = 1.0 / std::sqrt(gravityFlattening(fluid, volume, contactAngle, slopeGravity));
  bead.height = bead.cap.height * bead.flattening;
  const double inPlaneRadius = bead.cap.baseRadius / std::sqrt(bead.flattening);  // keeps the volume
  bead.halfLength = inPlaneRadius * bead.elongation;
  bead.halfWidth = inPlaneRadius / bead.elongation;
  return bead;
}

// ---- Stick and slide -------------------------------------------------------------------------------

namespace {

double meanContactAngle(const ContactAngleHysteresis& h) { return 0.5 * (h.advancing + h.receding); }

double cosineHysteresis(const ContactAngleHysteresis& h) { return std::cos(h.receding) - std::cos(h.advancing); }

void validateSlidingModel(const SlidingModel& model) {
  validateTearFluid(model.fluid);
  requireHysteresis(model.hysteresis);
  requirePositiveDropParameter(model.retentionFactor, "retention factor k");
}

// w = widthPerCubeRootVolume * V^(1/3): the cap at angle theta has a = R sin(theta) with
// R = (3 V / (pi capShape))^(1/3), so w = 2 sin(theta) (3 / (pi capShape))^(1/3) V^(1/3).
double widthPerCubeRootVolume(const ContactAngleHysteresis& h) {
  const double theta = meanContactAngle(h);
  return 2.0 * std::sin(theta) * std::cbrt(3.0 / (std::numbers::pi * capShape(theta)));
}

}  // namespace

double slidingBaseWidth(const SlidingModel& model, double volume) {
  validateSlidingModel(model);
  return 2.0 * sphericalCapFromVolume(volume, meanContactAngle(model.hysteresis)).baseRadius;
}

double retentionForce(const SlidingModel& model, double volume) {
  // Furmidge 1962 (k = 1) / ElSherbini & Jacobi 2006 (k = 24 / pi^3): F = k gamma w (cos theta_R - cos theta_A).
  return model.retentionFactor * model.fluid.surfaceTension * slidingBaseWidth(model, volume) *
         cosineHysteresis(model.hysteresis);
}

bool dropSlides(const SlidingModel& model, double volume, double tilt) {
  if (!(tilt >= 0.0 && tilt <= std::numbers::pi))
    throw InputError(fmt::format("surface tilt must be between 0 and 180 degrees, got {:.6g} degrees", tilt * kRadToDeg));
  const double weightAlongSlope = model.fluid.density * volume * model.fluid.gravity * std::sin(tilt);
  const double retention = retentionForce(model, volume);
  return weightAlongSlope > 0.0 && weightAlongSlope >= retention;
}

std::optional<double> criticalTiltAngle(const SlidingModel& model, double volume) {
  // sin(alpha_c) = F_retention / (rho V g).
  const double sinTilt = retentionForce(model, volume) / (model.fluid.density * volume * model.fluid.gravity);
  if (sinTilt > 1.0) return std::nullopt;
  return std::asin(sinTilt);
}

// rho g sin(alpha) V = k gamma c_w V^(1/3) dcos  (w = c_w V^(1/3), dcos = cos theta_R - cos theta_A)
//   => V^(2/3) = k c_w dcos gamma / (rho g sin(alpha)) = k c_w dcos lc^2 / sin(alpha)
//   => V_c = (k c_w dcos lc^2 / sin(alpha))^(3/2).
double criticalSlidingVolume(const SlidingModel& model, double tilt) {
  validateSlidingModel(model);
  if (!(tilt > 0.0 && tilt < std::numbers::pi))
    throw InputError(fmt::format("surface tilt for a critical volume must be strictly between 0 and 180 degrees, got {:.6g} degrees",
                                 tilt * kRadToDeg));
  const double lc = model.fluid.capillaryLength();
  const double area = model.retentionFactor * widthPerCubeRootVolume(model.hysteresis) *
                      cosineHysteresis(model.hysteresis) * lc * lc / std::sin(tilt);
  return area * std::sqrt(area);
}

// With R the equivalent sphere radius, V = 4/3 pi R^3 and Bo = rho g R^2 / gamma, divide the
// Furmidge balance rho g V sin(alpha) = k gamma w dcos by gamma R 4/3 pi:
//   Bo sin(alpha) = 3 k (w / R) dcos / (4 pi),
// and w / R = c_w V^(1/3) / R = c_w (4 pi / 3)^(1/3), a function of the angles only.
double criticalBondSinTilt(const SlidingModel& model) {
  validateSlidingModel(model);
  const double widthOverRadius = widthPerCubeRootVolume(model.hysteresis) * std::cbrt(4.0 * std::numbers::pi / 3.0);
  return 3.0 * model.retentionFactor * widthOverRadius * cosineHysteresis(model.hysteresis) / (4.0 * std::numbers::pi);
}

// ---- Hanging drop --------------------------------------------------------------------------------

namespace {

// Harkins & Brown 1919 correction psi = V_detached / V_Tate against r / V^(1/3), at steps of 0.1
// as reproduced in Adamson & Gast, "Physical Chemistry of Surfaces" (6th ed. 1997, ch. II, the
// drop-weight method); not re-checked against the 1919 original.
constexpr double kHarkinsBrownFirst = 0.3;
constexpr double kHarkinsBrownStep = 0.1;
constexpr std::array<double, 10> kHarkinsBrownPsi = {0.7256, 0.6828, 0.6515, 0.6250, 0.6093,
                                                     0.6000, 0.5998, 0.6098, 0.6280, 0.6535};
constexpr double kHarkinsBrownLast = kHarkinsBrownFirst + kHarkinsBrownStep * (kHarkinsBrownPsi.size() - 1);

}  // namespace

double harkinsBrownFactor(double radiusOverCubeRootVolume) {
  const double phi = radiusOverCubeRootVolume;
  if (!(phi >= kHarkinsBrownFirst - 1e-12 && phi <= kHarkinsBrownLast + 1e-12))
    throw InputError(fmt::format("r / V^(1/3) = {} is outside the Harkins-Brown table [{}, {}]", phi,
                                 kHarkinsBrownFirst, kHarkinsBrownLast));
  const double position = std::clamp((phi - kHarkinsBrownFirst) / kHarkinsBrownStep, 0.0,
                                     double(kHarkinsBrownPsi.size() - 1));
  const size_t i = std::min(size_t(position), kHarkinsBrownPsi.size() - 2);
  const double f = position - double(i);
  return (1.0 - f) * kHarkinsBrownPsi[i] + f * kHarkinsBrownPsi[i + 1];
}

double hangingDropMaxVolume(const TearFluid& fluid, double pinnedRadius, DetachmentCorrection correction) {
  validateTearFluid(fluid);
  requirePositiveDropParameter(pinnedRadius, "pinned radius of the hanging drop");
  // Tate 1864: rho g V = 2 pi r gamma.
  const double tate = 2.0 * std::numbers::pi * pinnedRadius * fluid.surfaceTension / (fluid.density * fluid.gravity);
  if (correction == DetachmentCorrection::None) return tate;

  // Solve V = psi(r / V^(1/3)) V_Tate for V over the table's range of r / V^(1/3). The residual
  // V - psi V_Tate grows with V (psi changes slowly: |dpsi/dV| V_Tate < 1 over the table), so
  // bisection finds the one root.
  const auto residual = [&](double v) { return v - harkinsBrownFactor(pinnedRadius / std::cbrt(v)) * tate; };
  double low = std::pow(pinnedRadius / kHarkinsBrownLast, 3.0);
  double high = std::pow(pinnedRadius / kHarkinsBrownFirst, 3.0);
  if (residual(low) > 0.0 || residual(high) < 0.0)
    throw InputError(fmt::format("a hanging drop pinned on radius {} m falls outside the Harkins-Brown table "
                                 "(r / V^(1/3) in [{}, {}])",
                                 pinnedRadius, kHarkinsBrownFirst, kHarkinsBrownLast));
  for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i) {
    const double mid = 0.5 * (low + high);
    if (residual(mid) < 0.0) low = mid;
    else high = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace lacrima
