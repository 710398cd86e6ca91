#pragma once
// Reference values for a semi-infinite, index-matched medium with isotropic scattering of
// single-scattering albedo a, from Chandrasekhar's H-function (Chandrasekhar 1950, "Radiative
// Transfer", ch. V; van de Hulst 1980, "Multiple Light Scattering", vol. 1):
//   1 / H(mu) = sqrt(1 - a) + (a / 2) integral_0^1 mu' H(mu') / (mu + mu') dmu'
// (the form that converges by plain fixed-point iteration for a < 1; at a = 1 it crawls). Plane albedo for
// incidence mu0: A(mu0) = 1 - sqrt(1 - a) H(mu0); white-sky (spherical) albedo under uniform
// illumination: A_diffuse = 2 integral_0^1 A(mu) mu dmu = 1 - 2 sqrt(1 - a) integral_0^1 H(mu) mu dmu.
#include <cmath>
#include <vector>

namespace lacrima::test {

// Gauss-Legendre nodes and weights on [0, 1] (Newton on P_n, as in Numerical Recipes gauleg).
struct Quadrature {
  std::vector<double> nodes, weights;
};

inline Quadrature gaussLegendreUnit(int n) {
  Quadrature q;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(M_PI * (i + 0.75) / (n + 0.5)), derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p2) / k;
      }
      derivative = n * (x * p0 - p1) / (x * x - 1.0);
      const double step = p0 / derivative;
      x -= step;
      if (std::abs(step) < 1e-15) break;
    }
    q.nodes.push_back(0.5 * (x + 1.0));
    q.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));  // 2/(...) halved for [0, 1]
  }
  return q;
}

// H at the quadrature nodes for single-scattering albedo a in [0, 1).
inline std::vector<double> chandrasekharH(double a, const Quadrature& q) {
  const size_t n = q.nodes.size();
  std::vector<double> h(n, 1.0), next(n);
  for (int iteration = 0; iteration < 20000; ++iteration) {
    double change = 0.0;
    for (size_t i = 0; i < n; ++i) {
      double integral = 0.0;
      for (size_t j = 0; j < n; ++j) integral += q.weights[j] * q.nodes[j] * h[j] / (q.nodes[i] + q.nodes[j]);
      next[i] = 1.0 / (std::sqrt(1.0 - a) + 0.5 * a * integral);
      change = std::max(change, std::abs(next[i] - h[i]));
    }
    h.swap(next);
    if (change < 1e-13) break;
  }
  return h;
}

// The n-th moment integral_0^1 H(mu) mu^n dmu.
inline double hMoment(double a, int n, int nodes = 96) {
  const Quadrature q = gaussLegendreUnit(nodes);
  const std::vector<double> h = chandrasekharH(a, q);
  double sum = 0.0;
  for (size_t i = 0; i < h.size(); ++i) sum += q.weights[i] * h[i] * std::pow(q.nodes[i], n);
  return sum;
}

// White-sky albedo of the semi-infinite medium: 1 - 2 sqrt(1 - a) integral_0^1 H(mu) mu dmu.
inline double semiInfiniteWhiteSkyAlbedo(double a) { return 1.0 - 2.0 * std::sqrt(1.0 - a) * hMoment(a, 1); }

}  // namespace lacrima::test
