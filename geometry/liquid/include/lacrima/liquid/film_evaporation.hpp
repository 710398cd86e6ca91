#pragma once
// How fast a thin water film on the skin (a tear's wet trail) evaporates into still air: the
// vapour diffuses away from the wet surface, at saturation there, into air of a given humidity.
//
// * Saturation vapour pressure over water: Buck 1981 (J. Appl. Meteorol. 20:1527, the fit for
//   -20 to 50 degrees C, without the enhancement factor of moist air, about 1.004 at 1 atm):
//   e_s(T) = 611.21 exp(17.502 T / (240.97 + T)) Pa, T in degrees C. Vapour density from the ideal
//   gas law, rho_v = e M_w / (R T_K).
// * Diffusivity of water vapour in air at 1 atm: Massman 1998 (Atmos. Environ. 32:1111, table 2):
//   D = 2.178e-5 (T_K / 273.15)^1.81 m^2/s, taken at the mean of the skin's and the air's temperature.
// * Diffusion-limited evaporation of a flat wet disk of radius R into still air: 4 D dc R kg/s
//   (Picknett & Bexon 1977, J. Colloid Interface Sci. 61:336, the contact-angle-0 limit; Hu &
//   Larson 2002, J. Phys. Chem. B 106:1334, fit the same within 2 % at theta = 0), dc = rho_v,s(T_skin) -
//   h rho_v,s(T_air), spread over the disk's area: a mean thinning speed 4 D dc / (pi rho_w R).
//   A wet trail of width w is taken as the disk of its half width (modelling choice: a strip
//   loses a little less per area than a disk of its half width, its far field being
//   two-dimensional; moving air, a breeze or a breath, evaporates faster than still air).
// No condensation: where the air holds more vapour than saturation at the skin, nothing evaporates.

namespace lacrima {

struct EvaporationAir {
  double skinTemperature = 33.0;  // degrees C at the wet surface (facial skin: 32-34)
  double airTemperature = 22.0;   // degrees C
  double relativeHumidity = 0.5;  // of the air, [0, 1]
};

// Buck 1981: saturation vapour pressure (Pa) over liquid water at `celsius`.
double saturationVapourPressure(double celsius);
// Saturated water vapour density (kg/m^3) at `celsius`.
double saturationVapourDensity(double celsius);
// Massman 1998: diffusivity of water vapour in air (m^2/s) at `celsius`, 1 atm.
double waterVapourDiffusivity(double celsius);
// dc (kg/m^3): the vapour density at the wet skin minus that of the air, at least 0.
double vapourDensityExcess(const EvaporationAir& air);
// The mean thinning speed (m/s) of a water film of `width` (m, > 0) and density `waterDensity`
// (kg/m^3) evaporating into still air: 8 D dc / (pi rho_w w). Throws InputError for a bad air
// (humidity outside [0, 1], temperatures outside [-20, 50] degrees C) or width.
double filmEvaporationSpeed(const EvaporationAir& air, double width, double waterDensity);
// Throws InputError naming the field for an air filmEvaporationSpeed rejects.
void validateEvaporationAir(const EvaporationAir& air);

}  // namespace lacrima
