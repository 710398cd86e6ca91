// Evaporation of a tear's wet trail (film_evaporation.hpp): the vapour pressure and diffusivity
// fits against their published values, the flat-disk rate in closed form, and bad air rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/film_evaporation.hpp"

namespace lacrima {
namespace film_evaporation_test {

TEST(FilmEvaporation, SaturationVapourPressureMatchesTheSteamTables) {
  // Buck 1981 is fitted to the Wexler/Goff-Gratch values; within 0.1 % over -20 to 50 degrees C.
  // Reference: saturation pressure over water (Pa) from the steam tables (CRC Handbook).
  const struct { double celsius, pascal; } table[] = {{0.0, 611.2}, {10.0, 1228.1}, {20.0, 2339.2}, {30.0, 4246.0}, {40.0, 7384.9}};
  for (const auto& row : table) EXPECT_NEAR(saturationVapourPressure(row.celsius), row.pascal, 2e-3 * row.pascal) << row.celsius;
}

TEST(FilmEvaporation, SaturatedVapourDensityAndDiffusivity) {
  // 17.3 g/m^3 of water vapour in saturated air at 20 degrees C (ideal gas from 2339 Pa).
  EXPECT_NEAR(saturationVapourDensity(20.0), 0.01729, 5e-5);
  // Massman 1998: 0.2178 cm^2/s at 0 degrees C, (T / T0)^1.81.
  EXPECT_DOUBLE_EQ(waterVapourDiffusivity(0.0), 2.178e-5);
  EXPECT_NEAR(waterVapourDiffusivity(25.0), 2.178e-5 * std::pow(298.15 / 273.15, 1.81), 1e-12);
}

TEST(FilmEvaporation, ThinningSpeedIsTheFlatDisksRateOverItsArea) {
  const EvaporationAir air{33.0, 22.0, 0.5};
  const double dc = saturationVapourDensity(33.0) - 0.5 * saturationVapourDensity(22.0);
  EXPECT_NEAR(vapourDensityExcess(air), dc, 1e-15);
  const double width = 0.002, radius = 0.001;
  // Picknett & Bexon 1977: 4 D dc R kg/s over pi R^2 of water.
  const double expected = 4.0 * waterVapourDiffusivity(27.5) * dc * radius / (std::numbers::pi * radius * radius * 1000.0);
  EXPECT_NEAR(filmEvaporationSpeed(air, width, 1000.0), expected, 1e-15);
  // Narrower trails thin faster: the speed goes as 1 / w.
  EXPECT_NEAR(filmEvaporationSpeed(air, 0.5 * width, 1000.0), 2.0 * expected, 1e-15);
  // Drier air evaporates faster; air saturated at the skin's temperature not at all (no condensation).
  EXPECT_GT(filmEvaporationSpeed({33.0, 22.0, 0.2}, width, 1000.0), expected);
  EXPECT_EQ(filmEvaporationSpeed({30.0, 30.0, 1.0}, width, 1000.0), 0.0);
  EXPECT_EQ(filmEvaporationSpeed({20.0, 30.0, 1.0}, width, 1000.0), 0.0);
}

TEST(FilmEvaporation, RejectsBadAirWithAMessageNamingTheField) {
  const auto message = [](const EvaporationAir& air, double width) {
    try {
      filmEvaporationSpeed(air, width, 1000.0);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({33.0, 22.0, 1.5}, 0.002), "film evaporation: the relative humidity must be in [0, 1], got 1.5");
  EXPECT_EQ(message({80.0, 22.0, 0.5}, 0.002), "film evaporation: the skin temperature must be between -20 and 50 degrees C, got 80");
  EXPECT_EQ(message({33.0, NAN, 0.5}, 0.002), "film evaporation: the air temperature must be between -20 and 50 degrees C, got nan");
  EXPECT_EQ(message({33.0, 22.0, 0.5}, 0.0), "film evaporation: the film's width must be finite and positive, got 0");
}

}  // namespace film_evaporation_test
}  // namespace lacrima
