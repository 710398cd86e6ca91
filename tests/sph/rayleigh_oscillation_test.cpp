// A free drop rings at Rayleigh's frequency: the l = 2 mode of a drop of radius R and surface
// tension sigma has omega^2 = 8 sigma / (rho R^3) (Rayleigh 1879, "On the capillary phenomena of
// jets", eq. for n = 2). A drop released at rest as a prolate ellipsoid (axes stretched 15 %,
// volume kept) in zero gravity swings through oblate and back; the time of its next prolate
// extreme is one period. gamma comes from sigma through akinciGammaForSigma (surface_tension.hpp),
// whose constant was measured on the 2 mm drop below, so the first test pins that calibration;
// the others check what a calibration cannot make true: the period grows as 1 / sqrt(sigma), and a
// drop of half the size at half the particle radius rings as Rayleigh says (the law's r^2 and
// Rayleigh's R^(3/2) together). Each simulates ~4,200 particles for ~700 steps (4 s in Release).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "lacrima/sph/dfsph.hpp"
#include "lacrima/sph/surface_tension.hpp"

namespace lacrima::sph {
namespace rayleigh_oscillation_test {

constexpr double kWaterSigma = 0.072;  // N/m at 25 C
constexpr double kWaterDensity = 1000.0;

double rayleighPeriod(double sigma, double dropRadius) {
  return 2.0 * std::numbers::pi / std::sqrt(8.0 * sigma / (kWaterDensity * std::pow(dropRadius, 3)));
}

// Lattice points inside the prolate ellipsoid x^2/a^2 + (y^2 + z^2)/b^2 <= 1 with a = R (1 + stretch)
// and b = R / sqrt(1 + stretch) (the ball's volume), centred on their centroid.
std::vector<Vec3d> prolateDrop(double dropRadius, double stretch, double spacing) {
  const double a = dropRadius * (1.0 + stretch), b = dropRadius / std::sqrt(1.0 + stretch);
  std::vector<Vec3d> drop;
  for (const Vec3d& p : latticeBlock(Vec3d::Constant(-a), Vec3d::Constant(a), spacing))
    if (p.x() * p.x() / (a * a) + (p.y() * p.y() + p.z() * p.z()) / (b * b) <= 1.0) drop.push_back(p);
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3d& p : drop) centroid += p / double(drop.size());
  for (Vec3d& p : drop) p -= centroid;
  return drop;
}

// The drop's quadrupole moment: mean of x^2 - (y^2 + z^2) / 2 about the centroid (positive when
// prolate along x, negative when oblate).
double quadrupole(const std::vector<Vec3d>& x) {
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3d& p : x) centroid += p / double(x.size());
  double q = 0.0;
  for (const Vec3d& p : x) {
    const Vec3d d = p - centroid;
    q += d.x() * d.x() - 0.5 * (d.y() * d.y() + d.z() * d.z());
  }
  return q / double(x.size());
}

// Simulates the drop, sampling the quadrupole 50 times per `expectedPeriod` for up to `periods` of
// them, and returns the time of its second extreme after release (the first is the oblate one): one
// period. Extremes are refined by a parabola through three samples. nullopt if it never came back.
std::optional<double> firstPeriod(double sigma, double dropRadius, double particleRadius, double expectedPeriod,
                                  double periods = 2.0) {
  FluidParams params;
  params.particleRadius = particleRadius;
  params.gravity = Vec3d::Zero();
  params.xsphViscosity = 0.0;  // water's own damping of a 2 mm drop takes ~0.8 s; the solver's is enough
  params.surfaceTension = akinciGammaForSigma(sigma, kWaterDensity, particleRadius);
  DfsphSolver solver(params, prolateDrop(dropRadius, 0.15, 2.0 * particleRadius), BoundaryParticles{});
  const double dt = expectedPeriod / 50.0;
  std::vector<double> q{quadrupole(solver.positions())};
  int extremes = 0;
  for (int k = 1; k <= int(periods * 50.0); ++k) {
    solver.advanceTo(k * dt);
    q.push_back(quadrupole(solver.positions()));
    if (k < 2) continue;
    const double before = q[k - 2], at = q[k - 1], after = q[k];
    if ((at - before) * (after - at) >= 0.0) continue;
    if (++extremes == 2) return dt * (k - 1 + 0.5 * (before - after) / (before - 2.0 * at + after));
  }
  return std::nullopt;
}

// A water drop of `dropRadius` resolved by particles of `particleRadius` rings within 10 % of
// Rayleigh's period.
void expectRayleighsPeriod(double dropRadius, double particleRadius) {
  const double expected = rayleighPeriod(kWaterSigma, dropRadius);
  const std::optional<double> period = firstPeriod(kWaterSigma, dropRadius, particleRadius, expected);
  ASSERT_TRUE(period) << "the drop did not swing back within two of Rayleigh's periods";
  std::printf("%.0f mm drop, %.2f mm particles, sigma 0.072: period %.2f ms, Rayleigh %.2f ms\n", dropRadius * 1e3,
              particleRadius * 1e3, *period * 1e3, expected * 1e3);
  EXPECT_NEAR(*period / expected, 1.0, 0.1);
}

TEST(RayleighOscillation, WaterDropOfTwoMillimetresRingsAtRayleighsPeriod) {
  expectRayleighsPeriod(0.002, 1e-4);  // Rayleigh: 23.4 ms
}

TEST(RayleighOscillation, PeriodGrowsAsOneOverTheSquareRootOfSigma) {
  const double water = rayleighPeriod(kWaterSigma, 0.002);
  const std::optional<double> strong = firstPeriod(kWaterSigma, 0.002, 1e-4, water);
  const std::optional<double> weak = firstPeriod(kWaterSigma / 4.0, 0.002, 1e-4, water, 2.6);
  ASSERT_TRUE(strong && weak);
  std::printf("2 mm drop: period %.2f ms at sigma 0.072, %.2f ms at 0.018 (ratio %.3f, Rayleigh 2)\n", *strong * 1e3,
              *weak * 1e3, *weak / *strong);
  EXPECT_NEAR(*weak / *strong, 2.0, 0.2);
}

TEST(RayleighOscillation, HalfTheDropAtHalfTheParticleRadiusRingsAsRayleighSays) {
  expectRayleighsPeriod(0.001, 5e-5);  // Rayleigh: 8.3 ms
}

TEST(RayleighOscillation, GammaAndSigmaConvertBothWays) {
  // 0.1 mm particles of water: sigma 0.072 N/m is gamma 51.4, about the 50 the demo shots were set to by look.
  EXPECT_NEAR(akinciGammaForSigma(0.072, 1000.0, 1e-4), 0.072 / (kSigmaPerGamma * 1e-2), 1e-9);
  EXPECT_NEAR(sigmaForAkinciGamma(akinciGammaForSigma(0.05, 998.0, 7e-5), 998.0, 7e-5), 0.05, 1e-15);
  // Half the particle radius needs four times the gamma for the same sigma.
  EXPECT_NEAR(akinciGammaForSigma(0.072, 1000.0, 5e-5) / akinciGammaForSigma(0.072, 1000.0, 1e-4), 4.0, 1e-12);
}

}  // namespace rayleigh_oscillation_test
}  // namespace lacrima::sph
