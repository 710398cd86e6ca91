// Chi-square goodness-of-fit machinery; see chi2_support.hpp.
#include "chi2_support.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "materials_support.hpp"

namespace lacrima::test {

namespace {

constexpr double kGammaEps = 1e-15;
constexpr double kFpMin = std::numeric_limits<double>::min() / kGammaEps;

// Series P(a, x) = e^-x x^a / Gamma(a) * sum_n x^n / (a (a+1) ... (a+n)) (Numerical Recipes 3rd ed. §6.2, gser).
double gammaPSeries(double a, double x) {
  double ap = a;
  double del = 1.0 / a;
  double sum = del;
  for (int n = 0; n < 100000; ++n) {
    ap += 1.0;
    del *= x / ap;
    sum += del;
    if (std::abs(del) < std::abs(sum) * kGammaEps) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Continued fraction for Q(a, x), modified Lentz (Numerical Recipes 3rd ed. §6.2, gcf; §5.2).
double gammaQContinuedFraction(double a, double x) {
  double b = x + 1.0 - a;
  double c = 1.0 / kFpMin;
  double d = 1.0 / b;
  double h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kFpMin) d = kFpMin;
    c = b + an / c;
    if (std::abs(c) < kFpMin) c = kFpMin;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) <= kGammaEps) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// Adaptive Simpson on [a, b] given f at a, (a+b)/2, b and the Simpson estimate `whole`
// (Lyness 1969, "Notes on the adaptive Simpson quadrature routine"; the absolute tolerance halves
// with each split, error estimate |left + right - whole| / 15, Richardson-corrected result).
template <class F>
double adaptiveSimpson(const F& f, double a, double b, double fa, double fm, double fb, double whole, double absTol,
                       double relTol, int depth) {
  const double m = 0.5 * (a + b);
  const double flm = f(0.5 * (a + m));
  const double frm = f(0.5 * (m + b));
  const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
  const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  const double refined = left + right;
  const double error = refined - whole;
  if (depth <= 0 || std::abs(error) <= 15.0 * std::max(absTol, relTol * std::abs(refined))) {
    return refined + error / 15.0;
  }
  return adaptiveSimpson(f, a, m, fa, flm, fm, left, 0.5 * absTol, relTol, depth - 1) +
         adaptiveSimpson(f, m, b, fm, frm, fb, right, 0.5 * absTol, relTol, depth - 1);
}

template <class F>
double integrate1D(const F& f, double a, double b, double absTol, double relTol, int maxDepth) {
  const double fa = f(a);
  const double fm = f(0.5 * (a + b));
  const double fb = f(b);
  const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
  return adaptiveSimpson(f, a, b, fa, fm, fb, whole, absTol, relTol, maxDepth);
}

}  // namespace

double regularizedGammaQ(double a, double x) {
  if (x < 0.0 || a <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0.0) return 1.0;
  if (x < a + 1.0) return 1.0 - gammaPSeries(a, x);
  return gammaQContinuedFraction(a, x);
}

double chiSquareSurvival(double statistic, int dof) {
  // Q(chi^2 | nu) = Q(nu / 2, chi^2 / 2) (Numerical Recipes 3rd ed. §6.2).
  return regularizedGammaQ(0.5 * dof, 0.5 * statistic);
}

double sidakSignificance(double alpha, int testCount) {
  // Sidak 1967: 1 - (1 - alpha)^(1/m).
  return 1.0 - std::pow(1.0 - alpha, 1.0 / testCount);
}

double integrate2D(const std::function<double(double, double)>& f, double a0, double a1, double b0, double b1,
                   int split, double absTol, double relTol, int maxDepth) {
  double total = 0.0;
  const double da = (a1 - a0) / split;
  const double db = (b1 - b0) / split;
  const double cellTol = absTol / (double(split) * split);
  for (int i = 0; i < split; ++i) {
    const double ca0 = a0 + i * da;
    const double ca1 = (i + 1 == split) ? a1 : ca0 + da;
    for (int j = 0; j < split; ++j) {
      const double cb0 = b0 + j * db;
      const double cb1 = (j + 1 == split) ? b1 : cb0 + db;
      // Nested: the outer integrand is itself an adaptive integral over the second variable.
      const auto inner = [&](double a) {
        return integrate1D([&](double b) { return f(a, b); }, cb0, cb1, cellTol / (ca1 - ca0), relTol, maxDepth);
      };
      total += integrate1D(inner, ca0, ca1, cellTol, relTol, maxDepth);
    }
  }
  return total;
}

std::vector<double> integrateSphereCells(const std::function<double(double, double)>& f, int cosThetaBins,
                                         int phiBins, int split, double absTol, double relTol) {
  std::vector<double> cells(size_t(cosThetaBins) * phiBins, 0.0);
  const double cellTol = absTol / double(cells.size());
  for (int ic = 0; ic < cosThetaBins; ++ic) {
    for (int ip = 0; ip < phiBins; ++ip) {
      const double c0 = -1.0 + 2.0 * ic / cosThetaBins;
      const double c1 = -1.0 + 2.0 * (ic + 1) / cosThetaBins;
      const double p0 = 2.0 * std::numbers::pi * ip / phiBins;
      const double p1 = 2.0 * std::numbers::pi * (ip + 1) / phiBins;
      cells[size_t(ic) * phiBins + ip] = integrate2D(f, c0, c1, p0, p1, split, cellTol, relTol);
    }
  }
  return cells;
}

Chi2Result runChi2Test(const DirectionSampler& sample, const DirectionPdf& pdf, const Chi2Options& options) {
  const int nCos = options.cosThetaBins;
  const int nPhi = options.phiBins;
  const int nCells = nCos * nPhi;
  const double N = double(options.sampleCount);
  Chi2Result result;
  result.threshold = sidakSignificance(options.significance, options.testCount);

  // 1. Histogram of sampled directions; cell index = cosBin * nPhi + phiBin, last cell = no sample.
  std::vector<double> observed(nCells + 1, 0.0);
  TestRng rng(options.seed);
  for (long long k = 0; k < options.sampleCount; ++k) {
    const float uLobe = rng.uniform();
    const Vec2 u = rng.uniform2();
    const auto w = sample(uLobe, u);
    if (!w) {
      observed[nCells] += 1.0;
      continue;
    }
    if (!w->allFinite() || std::abs(w->norm() - 1.0f) > 1e-3f) {
      result.message = fmt::format("sampler returned a non-unit direction ({}, {}, {})", w->x(), w->y(), w->z());
      return result;
    }
    const double cosTheta = std::clamp(double(w->z()), -1.0, 1.0);
    double phi = std::atan2(double(w->y()), double(w->x()));
    if (phi < 0.0) phi += 2.0 * std::numbers::pi;
    const int ic = std::clamp(int((cosTheta + 1.0) * 0.5 * nCos), 0, nCos - 1);
    const int ip = std::clamp(int(phi / (2.0 * std::numbers::pi) * nPhi), 0, nPhi - 1);
    observed[ic * nPhi + ip] += 1.0;
  }
  result.failedSamples = (long long)observed[nCells];

  // 2. Expected counts from the density integrated over each cell (dw = dcos(theta) dphi).
  std::vector<double> expected(nCells + 1, 0.0);
  const auto density = [&](double cosTheta, double phi) { return pdf(directionFromCosPhi(cosTheta, phi)); };
  const std::vector<double> probabilities = integrateSphereCells(density, nCos, nPhi);
  for (int i = 0; i < nCells; ++i) {
    result.pdfIntegral += probabilities[i];
    expected[i] = probabilities[i] * N;
  }
  if (result.pdfIntegral > 1.0 + 1e-3) {
    result.message = fmt::format("pdf integrates to {:.6f} > 1", result.pdfIntegral);
    return result;
  }
  expected[nCells] = std::max(0.0, 1.0 - result.pdfIntegral) * N;

  // 3. Pool cells with small expected counts (Mitsuba's chi2: sorted by expected count, the small
  // ones are merged until the pool itself reaches the minimum), then sum (O - E)^2 / E.
  std::vector<int> order(nCells + 1);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
  double pooledObserved = 0.0;
  double pooledExpected = 0.0;
  int pooledCells = 0;
  int cells = 0;
  for (const int i : order) {
    if (expected[i] <= 0.0 && observed[i] > 0.0) {
      result.message = fmt::format("{} samples in cell {} where the pdf integrates to zero", observed[i], i);
      return result;
    }
    if (expected[i] < options.minExpected || (pooledExpected > 0.0 && pooledExpected < options.minExpected)) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
      ++pooledCells;
      continue;
    }
    const double diff = observed[i] - expected[i];
    result.statistic += diff * diff / expected[i];
    ++cells;
  }
  if (pooledExpected > 0.0) {
    const double diff = pooledObserved - pooledExpected;
    result.statistic += diff * diff / pooledExpected;
    ++cells;
  } else if (pooledObserved > 0.0) {
    result.message = fmt::format("{} samples where the pdf integrates to zero", pooledObserved);
    return result;
  }
  // The cell counts sum to N by construction, so one degree of freedom is lost.
  result.dof = cells - 1;
  if (result.dof < 1) {
    result.message = "fewer than two usable cells";
    return result;
  }
  // 4. p-value and decision.
  result.pValue = chiSquareSurvival(result.statistic, result.dof);
  result.passed = result.pValue >= result.threshold;
  result.message = fmt::format("chi2 = {:.2f}, dof = {}, p = {:.4g} (reject below {:.3g}), pdf integral = {:.6f}, "
                               "failed samples = {}, pooled cells = {}",
                               result.statistic, result.dof, result.pValue, result.threshold, result.pdfIntegral,
                               result.failedSamples, pooledCells);
  return result;
}

}  // namespace lacrima::test
