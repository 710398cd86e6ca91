// Evaporation of a thin water film into still air; see film_evaporation.hpp.
#include "lacrima/liquid/film_evaporation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

constexpr double kWaterMolarMass = 0.018015;  // kg/mol
constexpr double kGasConstant = 8.314462618;  // J/(mol K)
constexpr double kZeroCelsius = 273.15;       // K

void requireTemperature(double celsius, const char* what) {
  if (!(std::isfinite(celsius) && celsius >= -20.0 && celsius <= 50.0))
    throw InputError(fmt::format("film evaporation: the {} must be between -20 and 50 degrees C, got {}", what, celsius));
}

}  // namespace

double saturationVapourPressure(double celsius) {
  return 611.21 * std::exp(17.502 * celsius / (240.97 + celsius));
}

double saturationVapourDensity(double celsius) {
  return saturationVapourPressure(celsius) * kWaterMolarMass / (kGasConstant * (celsius + kZeroCelsius));
}

double waterVapourDiffusivity(double celsius) {
  return 2.178e-5 * std::pow((celsius + kZeroCelsius) / kZeroCelsius, 1.81);
}

void validateEvaporationAir(const EvaporationAir& air) {
  requireTemperature(air.skinTemperature, "skin temperature");
  requireTemperature(air.airTemperature, "air temperature");
  if (!(air.relativeHumidity >= 0.0 && air.relativeHumidity <= 1.0))
    throw InputError(fmt::format("film evaporation: the relative humidity must be in [0, 1], got {}", air.relativeHumidity));
}

double vapourDensityExcess(const EvaporationAir& air) {
  validateEvaporationAir(air);
  const double excess =
      saturationVapourDensity(air.skinTemperature) - air.relativeHumidity * saturationVapourDensity(air.airTemperature);
  return std::max(0.0, excess);
}

double filmEvaporationSpeed(const EvaporationAir& air, double width, double waterDensity) {
  if (!(std::isfinite(width) && width > 0.0))
    throw InputError(fmt::format("film evaporation: the film's width must be finite and positive, got {}", width));
  if (!(std::isfinite(waterDensity) && waterDensity > 0.0))
    throw InputError(fmt::format("film evaporation: the water density must be finite and positive, got {}", waterDensity));
  const double diffusivity = waterVapourDiffusivity(0.5 * (air.skinTemperature + air.airTemperature));
  // Picknett & Bexon 1977: a disk of radius R = w / 2 loses 4 D dc R kg/s over pi R^2.
  const double radius = 0.5 * width;
  return 4.0 * diffusivity * vapourDensityExcess(air) / (std::numbers::pi * waterDensity * radius);
}

}  // namespace lacrima
