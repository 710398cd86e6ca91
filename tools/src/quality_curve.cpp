#include "quality_curve.hpp"

#include <cmath>
#include <limits>

namespace lacrima::cli {

double rootMeanSquareError(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.empty() || a.size() != b.size()) return 0.0;
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double d = double(a[i]) - double(b[i]);
    sum += d * d;
  }
  return std::sqrt(sum / double(a.size()));
}

double rmseSlope(const std::vector<QualityPoint>& points) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const QualityPoint& p : points) {
    if (p.spp <= 0 || !(p.rmse > 0.0)) continue;
    const double x = std::log(double(p.spp)), y = std::log(p.rmse);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 2 || denominator <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / denominator;
}

std::optional<TimeToQuality> timeToReach(const std::vector<QualityPoint>& points, double target) {
  if (points.empty() || !(target > 0.0)) return std::nullopt;
  for (size_t i = 0; i < points.size(); ++i) {
    if (points[i].rmse > target) continue;
    if (i == 0) return TimeToQuality{double(points[0].spp), points[0].seconds, false};
    // Between points i-1 (above the target) and i (at or below it), linear in log-log; the seconds
    // between the two measured ones the same way (under adaptive sampling they are not in
    // proportion to the maximum spp).
    const QualityPoint &a = points[i - 1], &b = points[i];
    const double t = (std::log(target) - std::log(a.rmse)) / (std::log(b.rmse) - std::log(a.rmse));
    const auto between = [t](double x, double y) { return std::exp(std::log(x) + t * (std::log(y) - std::log(x))); };
    return TimeToQuality{between(double(a.spp), double(b.spp)), between(a.seconds, b.seconds), false};
  }
  const double slope = rmseSlope(points);
  const QualityPoint& last = points.back();
  if (!(slope < 0.0) || !(last.rmse > 0.0)) return std::nullopt;
  const double spp = double(last.spp) * std::pow(target / last.rmse, 1.0 / slope);
  // Beyond the curve, at the largest render's seconds per sample.
  return TimeToQuality{spp, last.seconds * spp / double(last.spp), true};
}

}  // namespace lacrima::cli
