#pragma once
// Time to quality (`lacrima bench --quality`): the error of renders at growing sample counts
// against a converged reference, the slope of log RMSE against log spp, and the samples and
// seconds needed to reach an RMSE target. A Monte Carlo estimator with independent samples has
// RMSE proportional to spp^-0.5; stratified sampling makes the slope steeper.
#include <optional>
#include <vector>

namespace lacrima::cli {

// One measured render: its samples per pixel, seconds spent path tracing, RMSE to the reference.
struct QualityPoint {
  int spp = 0;
  double seconds = 0.0;
  double rmse = 0.0;
};

// Root mean square difference over every value of two equally long arrays (0 when empty).
double rootMeanSquareError(const std::vector<float>& a, const std::vector<float>& b);

// Least-squares slope of log(rmse) over log(spp) (NaN with fewer than two usable points: an RMSE
// of 0 has no logarithm).
double rmseSlope(const std::vector<QualityPoint>& points);

// Samples and seconds to reach an RMSE target.
struct TimeToQuality {
  double spp = 0.0, seconds = 0.0;
  bool extrapolated = false;  // beyond the largest measured count, along the fitted slope
};

// Interpolates log-linearly between the two measured points around `target` (points sorted by
// spp), samples and seconds alike (under adaptive sampling the seconds do not grow in proportion
// to the maximum spp); beyond the curve, seconds grow at the largest render's rate. A target
// below every measured RMSE is extrapolated along the fitted slope; nothing when the slope does not
// fall (the error does not shrink with more samples).
std::optional<TimeToQuality> timeToReach(const std::vector<QualityPoint>& points, double target);

}  // namespace lacrima::cli
