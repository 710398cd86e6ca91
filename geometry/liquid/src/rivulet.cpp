// A rivulet's cross-section and flow rate; see rivulet.hpp.
#include "lacrima/liquid/rivulet.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {
// The fastest-growing wavelength of a liquid cylinder over its radius (Rayleigh 1878): 2 pi / 0.697.
constexpr double kRayleighWavelengthOverRadius = 9.02;
}  // namespace

void validateRivuletFlow(const RivuletFlow& flow) {
  validateTearFluid(flow.fluid);
  if (!(std::isfinite(flow.viscosity) && flow.viscosity > 0.0))
    throw InputError(fmt::format("rivulet: viscosity must be finite and positive, got {}", flow.viscosity));
  if (!(flow.contactAngle > 0.0 && flow.contactAngle < 0.5 * std::numbers::pi))
    throw InputError(fmt::format("rivulet: the contact angle must be in (0, 90) degrees, got {} degrees",
                                 flow.contactAngle * 180.0 / std::numbers::pi));
  if (!(flow.slope >= 0.0 && flow.slope <= std::numbers::pi))
    throw InputError(fmt::format("rivulet: the slope must be in [0, 180] degrees, got {}", flow.slope));
}

double rivuletArea(const RivuletFlow& flow, double halfWidth) {
  return (2.0 / 3.0) * std::tan(flow.contactAngle) * halfWidth * halfWidth;
}

double rivuletHalfWidth(const RivuletFlow& flow, double area) {
  return area > 0.0 ? std::sqrt(1.5 * area / std::tan(flow.contactAngle)) : 0.0;
}

double rivuletHeight(const RivuletFlow& flow, double halfWidth) { return 0.5 * std::tan(flow.contactAngle) * halfWidth; }

double rivuletFluxCoefficient(const RivuletFlow& flow) {
  const double drive = flow.fluid.density * flow.fluid.gravity * std::max(0.0, std::sin(flow.slope));
  return (3.0 / 35.0) * drive / flow.viscosity * std::tan(flow.contactAngle);
}

double rivuletFlux(const RivuletFlow& flow, double area) { return rivuletFluxCoefficient(flow) * area * area; }

double rivuletHalfWidthForFlux(const RivuletFlow& flow, double flux) {
  const double drive = flow.fluid.density * flow.fluid.gravity * std::max(0.0, std::sin(flow.slope));
  if (!(flux > 0.0) || !(drive > 0.0)) return 0.0;
  const double tanTheta = std::tan(flow.contactAngle);
  return std::pow(105.0 * flow.viscosity * flux / (4.0 * drive * tanTheta * tanTheta * tanTheta), 0.25);
}

double rivuletBreakupSpacing(const RivuletFlow& flow, double halfWidth) {
  return kRayleighWavelengthOverRadius * halfWidth / std::sin(flow.contactAngle);
}

}  // namespace lacrima
