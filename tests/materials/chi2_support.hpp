#pragma once
// Chi-square goodness-of-fit test of a direction sampler against its claimed density, in the
// manner of Mitsuba's and Nori's BSDF tests (Jakob, Nori "warptest"/"chi2test"):
//   1. draw N directions with the sampler and histogram them over the sphere in (cos theta, phi);
//      draws that fail (sampler returns nothing) go into one extra "no sample" cell;
//   2. integrate the density over each cell numerically (adaptive Simpson on a pre-split grid),
//      expected count = N * integral; the "no sample" cell expects N * (1 - total integral);
//   3. pool cells whose expected count is below 5, sum (O - E)^2 / E, and turn the statistic into
//      a p-value with the chi-square survival function;
//   4. reject at significance 0.01 with the Sidak correction for the number of tests run.
// A nonzero count in a cell whose density integrates to zero is an immediate failure.
//
// kChi2TestCount is the number of chi-square tests of real samplers in this executable (the
// family for the Sidak correction); bsdf_chi2_test.cpp checks that it matches its case list.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima::test {

inline constexpr int kChi2TestCount = 36;

// Regularised upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a)
// (Press et al., "Numerical Recipes", 3rd ed., §6.2: series for x < a + 1, continued fraction
// by the modified Lentz method otherwise).
double regularizedGammaQ(double a, double x);

// P(X >= statistic) for X ~ chi-square with dof degrees of freedom: Q(dof/2, statistic/2)
// (Numerical Recipes 3rd ed. §6.2, the chi-square probability function).
double chiSquareSurvival(double statistic, int dof);

// Per-test significance that keeps the family-wise rate at alpha over testCount independent
// tests: 1 - (1 - alpha)^(1/testCount) (Sidak 1967).
double sidakSignificance(double alpha, int testCount);

// Nested adaptive Simpson integral of f over [a0,a1] x [b0,b1], pre-split into `split` x `split` cells
// so that narrow peaks are not stepped over. Relative tolerance relTol (per cell), absolute absTol.
// maxDepth bounds the bisections per pre-split cell and axis: it caps the work along lines where
// the integrand jumps (total internal reflection, the horizon), which no tolerance can resolve;
// raise it only for very narrow peaks.
double integrate2D(const std::function<double(double, double)>& f, double a0, double a1, double b0,
                   double b1, int split = 4, double absTol = 1e-8, double relTol = 1e-5, int maxDepth = 9);

// Integral of f(cos theta, phi) over each cell of a cosThetaBins x phiBins grid of the sphere
// (cell index = cosBin * phiBins + phiBin), each cell by integrate2D with a split x split pre-split.
// Since dw = dcos(theta) dphi, a density's cell integrals are cell probabilities.
std::vector<double> integrateSphereCells(const std::function<double(double, double)>& f, int cosThetaBins,
                                         int phiBins, int split = 8, double absTol = 1e-8,
                                         double relTol = 1e-6);

struct Chi2Options {
  int cosThetaBins = 10;
  int phiBins = 20;
  long long sampleCount = 1'000'000;
  double minExpected = 5.0;
  double significance = 0.01;  // family-wise
  int testCount = 1;           // for the Sidak correction
  uint64_t seed = 1;
};

struct Chi2Result {
  double statistic = 0.0;
  int dof = 0;
  double pValue = 0.0;
  double threshold = 0.0;       // per-test significance after Sidak
  double pdfIntegral = 0.0;     // integral of the density over the sphere
  long long failedSamples = 0;  // sampler returned nothing
  bool passed = false;
  std::string message;  // why it failed, or a one-line summary
};

// sample(uLobe, u) returns a unit direction or nothing; pdf(direction) is its claimed density
// with respect to solid angle.
using DirectionSampler = std::function<std::optional<Vec3>(float uLobe, const Vec2& u)>;
using DirectionPdf = std::function<double(const Vec3&)>;

Chi2Result runChi2Test(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options);

}  // namespace lacrima::test
