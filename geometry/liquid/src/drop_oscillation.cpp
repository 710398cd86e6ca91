// Shape oscillation of falling drops; see drop_oscillation.hpp.
#include "lacrima/liquid/drop_oscillation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {

namespace {

void requirePositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) throw InputError(fmt::format("{} must be positive and finite, got {}", name, value));
}

void requireMode(int mode) {
  if (mode < 2) throw InputError(fmt::format("the oscillation mode must be at least 2, got {}", mode));
}

// (4 pi / 3 / V1)^(1/3) for the unit sphere of this tessellation (V1 its polyhedral volume).
double volumeMatchingScale(const FallingDropResolution& resolution) {
  const TriangleMesh unit = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), resolution.rings, resolution.segments);
  return std::cbrt(4.0 * std::numbers::pi / 3.0 / signedVolume(unit));
}

}  // namespace

double rayleighAngularFrequency(const TearFluid& fluid, double radius, int mode) {
  validateTearFluid(fluid);
  requirePositive(radius, "radius");
  requireMode(mode);
  const double n = mode;
  // Rayleigh 1879: omega_n^2 = n (n - 1)(n + 2) sigma / (rho R^3).
  return std::sqrt(n * (n - 1.0) * (n + 2.0) * fluid.surfaceTension / (fluid.density * radius * radius * radius));
}

double lambDampingTime(double radius, double kinematicViscosity, int mode) {
  requirePositive(radius, "radius");
  requirePositive(kinematicViscosity, "kinematic viscosity");
  requireMode(mode);
  const double n = mode;
  // Lamb 1932, art. 355: tau = R^2 / ((n - 1)(2n + 1) nu).
  return radius * radius / ((n - 1.0) * (2.0 * n + 1.0) * kinematicViscosity);
}

SpheroidAxes modeTwoSpheroid(double radius, double amplitude) {
  requirePositive(radius, "radius");
  if (!(amplitude > -1.0 && amplitude < 2.0))
    throw InputError(fmt::format("the mode-2 amplitude must lie in (-1, 2), got {}", amplitude));
  const double polar = 1.0 + amplitude, equatorial = 1.0 - 0.5 * amplitude;
  const double scale = radius / std::cbrt(equatorial * equatorial * polar);  // a^2 c = R^3
  return {equatorial * scale, polar * scale};
}

double modeTwoAmplitudeFromAspect(double aspect) {
  requirePositive(aspect, "aspect ratio");
  return 2.0 * (aspect - 1.0) / (aspect + 2.0);
}

double DropOscillation::amplitudeAt(double t) const {
  if (t <= 0.0) return initialAmplitude;
  return initialAmplitude * std::cos(angularFrequency * t) * std::exp(-t / dampingTime);
}

double DropOscillation::envelopeAt(double t) const {
  return t <= 0.0 ? initialAmplitude : initialAmplitude * std::exp(-t / dampingTime);
}

DropOscillation dropOscillation(const TearFluid& fluid, double viscosity, double volume, double initialAmplitude) {
  requirePositive(viscosity, "viscosity");
  const double radius = equivalentSphereRadius(volume);
  DropOscillation oscillation;
  oscillation.initialAmplitude = initialAmplitude;
  oscillation.angularFrequency = rayleighAngularFrequency(fluid, radius);
  oscillation.dampingTime = lambDampingTime(radius, viscosity / fluid.density);
  return oscillation;
}

TriangleMesh makeFallingDropMesh(const Vec3d& centre, const Vec3d& axis, const SpheroidAxes& axes,
                                 const FallingDropResolution& resolution) {
  requirePositive(axes.equatorial, "equatorial semi-axis");
  requirePositive(axes.polar, "polar semi-axis");
  if (!(axis.squaredNorm() > 0.0)) throw InputError("falling drop: the axis must not be zero");
  const Vec3d pole = axis.normalized();
  // Any unit vector across the axis; the drop is axisymmetric, so which one does not matter.
  const Vec3d across = pole.unitOrthogonal();
  const double scale = volumeMatchingScale(resolution);
  Eigen::Matrix3d frame;
  frame.col(0) = across * axes.equatorial * scale;
  frame.col(1) = pole.cross(across) * axes.equatorial * scale;
  frame.col(2) = pole * axes.polar * scale;
  TriangleMesh mesh = makeEllipsoid(centre.cast<float>(), frame.cast<float>(), resolution.rings, resolution.segments);
  mesh.name = "falling drop";
  return mesh;
}

}  // namespace lacrima
