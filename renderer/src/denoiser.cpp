// The denoiser (denoiser.hpp): non-local means weights from one half buffer, a first-order
// regression of the other half on the features, in bands of rows processed in parallel (each band
// on its own, so the output does not depend on the thread count).
#include "lacrima/renderer/denoiser.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "lacrima/base/hash.hpp"

namespace lacrima {

namespace {

constexpr int kFeatures = 7;                 // albedo (3), normal (3), inverse depth (1)
constexpr int kUnknowns = 1 + kFeatures;     // the value at p and one slope per feature
constexpr int kBandRows = 16;                // rows of one parallel band
constexpr float kDistanceEpsilon = 1e-10f;   // against 0 / 0 where the variance is 0
constexpr double kRidge = 1e-3;              // relative to the sum of weights, on the slopes only

// Mean over the 2r+1 values around each of n values `stride` apart (over those inside), by a
// running sum.
void runningMean(const float* in, float* out, int n, size_t stride, int r) {
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i <= std::min(r, n - 1); ++i, ++count) sum += in[size_t(i) * stride];
  for (int i = 0; i < n; ++i) {
    out[size_t(i) * stride] = float(sum / count);
    const int add = i + r + 1, drop = i - r;
    if (add < n) sum += in[size_t(add) * stride], ++count;
    if (drop >= 0) sum -= in[size_t(drop) * stride], --count;
  }
}

// Mean over the (2r+1)^2 box around each pixel, over the pixels inside the plane (`rows` rows of
// `width` pixels, `channels` interleaved values a pixel): running means along x, then along y.
std::vector<float> boxMean(const std::vector<float>& values, int width, int rows, int channels, int r) {
  std::vector<float> horizontal(values.size()), out(values.size());
  const size_t rowStride = size_t(width) * channels;
  for (int y = 0; y < rows; ++y)
    for (int c = 0; c < channels; ++c)
      runningMean(&values[y * rowStride + c], &horizontal[y * rowStride + c], width, channels, r);
  for (int x = 0; x < width; ++x)
    for (int c = 0; c < channels; ++c)
      runningMean(&horizontal[size_t(x) * channels + c], &out[size_t(x) * channels + c], rows, rowStride, r);
  return out;
}

// A pixel's brightness for the firefly test: the mean of its channels.
float brightness(const float* rgb) { return (rgb[0] + rgb[1] + rgb[2]) / 3.0f; }

// The 75th percentile of the brightness of the mean of the halves over the 5 x 5 pixels around
// (x, y), the pixel itself left out (those inside the image).
float neighbourhoodUpperQuartile(const std::vector<float>& meanBrightness, int width, int height, int x, int y) {
  std::array<float, 24> values;
  int count = 0;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int qx = x + dx, qy = y + dy;
      if ((dx == 0 && dy == 0) || qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
      values[count++] = meanBrightness[size_t(qy) * width + qx];
    }
  if (count == 0) return std::numeric_limits<float>::infinity();  // a 1 x 1 image: nothing to compare
  const int rank = (3 * count) / 4;
  std::nth_element(values.begin(), values.begin() + rank, values.begin() + count);
  return values[rank];
}

// Fireflies: a pixel of one half that a rare path (a caustic, a light found by a glossy bounce)
// made far brighter than anything near it. Every window that holds it would average it in, and it
// would come out as a bright square the size of the window. The test is the outlier test of
// Cycles' non-local means denoiser (Blender 2.8, kernel_filter_detect_outliers: brighter than twice
// the 75th percentile of its 5 x 5 neighbourhood; see DeCoro, Weyrich & Rusinkiewicz 2010 on
// outlier rejection in Monte Carlo rendering), with the other half as a second witness: a pixel
// is only an outlier when it is also more than twice as bright as the same pixel of the other
// half, so a catchlight both halves see (a glint on a tear, one pixel wide) stays. An outlier is
// scaled down to that bound (hue kept); the energy above it is lost, as in Cycles.
// `partA`, `partB` (may be null): a part of each half (its subsurface light), scaled alike, so an
// outlier is judged on the whole pixel and the part's spiky but genuine samples are kept.
void suppressFireflies(int width, int height, std::vector<float>& halfA, std::vector<float>& halfB,
                       std::vector<float>* partA, std::vector<float>* partB) {
  const size_t n = size_t(width) * height;
  std::vector<float> meanBrightness(n);
  for (size_t p = 0; p < n; ++p) meanBrightness[p] = 0.5f * (brightness(&halfA[3 * p]) + brightness(&halfB[3 * p]));
  const auto scaleDown = [](float* rgb, float* part, float value, float limit) {
    if (!(value > limit)) return;
    for (int c = 0; c < 3; ++c) rgb[c] *= limit / value;
    if (part)
      for (int c = 0; c < 3; ++c) part[c] *= limit / value;
  };
  const auto partOf = [](std::vector<float>* part, size_t p) { return part ? &(*part)[3 * p] : nullptr; };
  for (size_t p = 0; p < n; ++p) {
    const float a = brightness(&halfA[3 * p]), b = brightness(&halfB[3 * p]);
    // Only a pixel more than twice the other half's can be an outlier: the neighbourhood's
    // percentile is sought for those alone.
    if (!(a > 2.0f * b) && !(b > 2.0f * a)) continue;
    const int x = int(p % size_t(width)), y = int(p / size_t(width));
    const float bound = 2.0f * neighbourhoodUpperQuartile(meanBrightness, width, height, x, y);
    if (a > 2.0f * b) scaleDown(&halfA[3 * p], partOf(partA, p), a, std::max(bound, 2.0f * b));
    else scaleDown(&halfB[3 * p], partOf(partB, p), b, std::max(bound, 2.0f * a));
  }
}

// The variance of each half buffer's estimate, per channel. Two independent estimates a and b of
// the same mean, over shares f and 1 - f of n samples, differ by (a - b)^2 = D on average, D =
// sigma^2 / n (1 / f + 1 / (1 - f)) = sigma^2 / (n f (1 - f)): so a's variance is D (1 - f) and b's
// D f (D / 2 each for equal halves). One degree of freedom a pixel, so D is averaged over a 5 x 5
// box. Under stratified sampling it is the right measure (each half is stratified), where the
// samples' own variance over their count overestimates the error many times and would let the
// filter blur what it takes for noise. The box spreads a catchlight's or a firefly's large
// difference onto its neighbours, though, which would then average the catchlight in: where the
// samples' variance (given per pixel, for halves of n / 2) is lower, it is taken instead.
struct HalfVariances {
  std::vector<float> a, b;
};

HalfVariances halfBufferVariances(const DenoiseInput& in, const std::vector<float>& halfA,
                                  const std::vector<float>& halfB, const std::vector<float>& samplesVariance) {
  std::vector<float> difference(halfA.size());
  for (size_t i = 0; i < difference.size(); ++i) {
    const float d = halfA[i] - halfB[i];
    difference[i] = d * d;
  }
  difference = boxMean(difference, in.width, in.height, 3, 2);
  HalfVariances v{std::vector<float>(halfA.size()), std::vector<float>(halfA.size())};
  for (size_t i = 0; i < difference.size(); ++i) {
    const float share = in.firstHalfShare.empty() ? 0.5f : in.firstHalfShare[i / 3];
    v.a[i] = difference[i] * (1.0f - share);
    v.b[i] = difference[i] * share;
    if (samplesVariance.empty()) continue;
    v.a[i] = std::min(v.a[i], samplesVariance[i] * (0.5f / share));
    v.b[i] = std::min(v.b[i], samplesVariance[i] * (0.5f / (1.0f - share)));
  }
  return v;
}

// The regression's features a pixel: albedo, normal, and inverse depth over its mean (0 where
// nothing was hit, so the background is far from every surface).
std::vector<float> regressionFeatures(const DenoiseInput& in) {
  const size_t n = size_t(in.width) * in.height;
  double inverseDepthSum = 0.0;
  size_t hits = 0;
  for (float z : in.depth)
    if (std::isfinite(z) && z > 0.0f) inverseDepthSum += 1.0 / z, ++hits;
  const double scale = hits > 0 ? double(hits) / inverseDepthSum : 1.0;
  std::vector<float> features(n * kFeatures);
  for (size_t p = 0; p < n; ++p) {
    float* f = &features[p * kFeatures];
    for (int c = 0; c < 3; ++c) f[c] = in.albedo[3 * p + c], f[3 + c] = in.normal[3 * p + c];
    const float z = in.depth[p];
    f[6] = std::isfinite(z) && z > 0.0f ? float(scale / z) : 0.0f;
  }
  return features;
}

// Weighted least squares sums of one pixel: X^T W X (upper triangle) and X^T W y.
struct NormalEquations {
  double xtx[kUnknowns * (kUnknowns + 1) / 2] = {};
  double xty[kUnknowns][3] = {};
  // The range of the values of weight at least kRangeWeight, per channel.
  float low[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(),
                  std::numeric_limits<float>::max()};
  float high[3] = {std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest(),
                   std::numeric_limits<float>::lowest()};
};

constexpr float kRangeWeight = 0.05f;

// The neighbours' offsets in a window of `radius` taking one of every step x step pixels: one
// offset in each step x step cell of a lattice centred on the pixel (the centre cell's is (0, 0):
// the pixel itself is always among them), at a fixed pseudo-random place in its cell (a jittered
// grid, Cook 1986). On a plain lattice (every step-th pixel) the pixels of one residue class
// modulo the step average the same neighbours' noise, which showed as a faint grid of period
// `step` in the denoised skin at 1:1; the jitter leaves no period.
std::vector<std::pair<int, int>> windowOffsets(int radius, int step) {
  std::vector<std::pair<int, int>> offsets;
  const int cells = radius / step;  // cells each side of the centre one
  const auto jitter = [&](int i, int j, int axis) {
    if (i == 0 && j == 0) return 0;
    const uint64_t h = hashCombine(hashCombine(uint64_t(i + 1024), uint64_t(j + 1024)), uint64_t(axis));
    return int(mix64(h) % uint64_t(step)) - step / 2;
  };
  for (int j = -cells; j <= cells; ++j)
    for (int i = -cells; i <= cells; ++i) {
      const int dx = std::clamp(i * step + jitter(i, j, 0), -radius, radius);
      const int dy = std::clamp(j * step + jitter(i, j, 1), -radius, radius);
      offsets.emplace_back(dx, dy);
    }
  return offsets;
}

class HalfFilter {
 public:
  HalfFilter(const DenoiseInput& in, const std::vector<float>& values, const std::vector<float>& guide,
             const std::vector<float>& variance, const std::vector<float>& features, const DenoiseSettings& s)
      : in_(in),
        values_(values),
        guide_(guide),
        variance_(variance),
        features_(features),
        s_(s),
        offsets_(windowOffsets(s.windowRadius, std::max(1, s.windowStep))) {}

  // The filtered rows [y0, y1) into out (3 floats a pixel, whole image).
  void filterBand(int y0, int y1, std::vector<float>& out) const {
    const int w = in_.width, f = s_.patchRadius;
    const int top = std::max(0, y0 - f), bottom = std::min(in_.height, y1 + f);  // rows with patch halo
    const float k2 = s_.bandwidth * s_.bandwidth;
    std::vector<NormalEquations> sums(size_t(y1 - y0) * w);
    std::vector<float> term(size_t(bottom - top) * w);
    for (const auto& [dx, dy] : offsets_) {
      distanceTerms(top, bottom, dx, dy, term);
      const std::vector<float> distance = boxMean(term, w, bottom - top, 1, f);
      for (int y = y0; y < y1; ++y)
        for (int x = 0; x < w; ++x) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= w || qy >= in_.height) continue;
          const float weight = std::exp(-std::max(0.0f, distance[size_t(y - top) * w + x]) / k2);
          if (weight >= 1e-6f) accumulate(sums[size_t(y - y0) * w + x], x, y, qx, qy, weight);
        }
    }
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < w; ++x) solve(sums[size_t(y - y0) * w + x], &out[3 * (size_t(y) * w + x)]);
  }

 private:
  // Rousselle et al. 2012, eq. 3: the squared difference of the guide at p and q = p + (dx, dy),
  // less the variance it is expected to have from noise alone, over that variance (k^2 times it:
  // the caller divides by k^2); averaged over the channels. Pairs whose q is outside the image get 0
  // (they are not used).
  void distanceTerms(int top, int bottom, int dx, int dy, std::vector<float>& term) const {
    const int w = in_.width;
    for (int y = top; y < bottom; ++y)
      for (int x = 0; x < w; ++x) {
        const int qx = x + dx, qy = y + dy;
        float sum = 0.0f;
        if (qx >= 0 && qy >= 0 && qx < w && qy < in_.height) {
          const size_t p = 3 * (size_t(y) * w + x), q = 3 * (size_t(qy) * w + qx);
          for (int c = 0; c < 3; ++c) {
            const float vp = variance_[p + c], vq = variance_[q + c];
            const float d = guide_[p + c] - guide_[q + c];
            sum += (d * d - (vp + std::min(vp, vq))) / (kDistanceEpsilon + vp + vq);
          }
        }
        term[size_t(y - top) * w + x] = sum / 3.0f;
      }
  }

  void accumulate(NormalEquations& e, int x, int y, int qx, int qy, float weight) const {
    double row[kUnknowns];
    row[0] = 1.0;
    const float* fp = &features_[(size_t(y) * in_.width + x) * kFeatures];
    const float* fq = &features_[(size_t(qy) * in_.width + qx) * kFeatures];
    for (int i = 0; i < kFeatures; ++i) row[1 + i] = double(fq[i] - fp[i]);
    const float* value = &values_[3 * (size_t(qy) * in_.width + qx)];
    if (weight >= kRangeWeight)
      for (int c = 0; c < 3; ++c) e.low[c] = std::min(e.low[c], value[c]), e.high[c] = std::max(e.high[c], value[c]);
    int k = 0;
    for (int i = 0; i < kUnknowns; ++i) {
      const double wi = weight * row[i];
      for (int j = i; j < kUnknowns; ++j) e.xtx[k++] += wi * row[j];
      for (int c = 0; c < 3; ++c) e.xty[i][c] += wi * double(value[c]);
    }
  }

  // The fitted value at p (the constant term). A small ridge on the slopes keeps the system
  // solvable where a feature does not vary in the window (flat albedo, one normal); should it
  // still fail, the weighted mean.
  static void solve(const NormalEquations& e, float* out) {
    Eigen::Matrix<double, kUnknowns, kUnknowns> a;
    int k = 0;
    for (int i = 0; i < kUnknowns; ++i)
      for (int j = i; j < kUnknowns; ++j) a(i, j) = a(j, i) = e.xtx[k++];
    const double weightSum = a(0, 0);
    for (int i = 1; i < kUnknowns; ++i) a(i, i) += kRidge * weightSum;
    Eigen::Matrix<double, kUnknowns, 3> b;
    for (int i = 0; i < kUnknowns; ++i)
      for (int c = 0; c < 3; ++c) b(i, c) = e.xty[i][c];
    const Eigen::LDLT<Eigen::Matrix<double, kUnknowns, kUnknowns>> ldlt(a);
    const Eigen::Matrix<double, kUnknowns, 3> beta = ldlt.solve(b);
    for (int c = 0; c < 3; ++c) {
      const bool ok = ldlt.info() == Eigen::Success && std::isfinite(beta(0, c));
      const float fitted = float(ok ? beta(0, c) : (weightSum > 0.0 ? e.xty[0][c] / weightSum : 0.0));
      out[c] = e.low[c] <= e.high[c] ? std::clamp(fitted, e.low[c], e.high[c]) : fitted;
    }
  }

  const DenoiseInput& in_;
  const std::vector<float>& values_;
  const std::vector<float>& guide_;
  const std::vector<float>& variance_;
  const std::vector<float>& features_;
  const DenoiseSettings& s_;
  const std::vector<std::pair<int, int>> offsets_;  // the window's neighbours (windowOffsets), once for every band
};

void checkInput(const DenoiseInput& in) {
  const size_t n = size_t(std::max(in.width, 0)) * size_t(std::max(in.height, 0));
  if (in.width < 1 || in.height < 1 || in.halfA.size() != 3 * n || in.halfB.size() != 3 * n ||
      !(in.variance.empty() || in.variance.size() == 3 * n) ||
      !(in.subsurfaceA.empty() || (in.subsurfaceA.size() == 3 * n && in.subsurfaceB.size() == 3 * n &&
                                   in.subsurfaceVariance.size() == 3 * n)) ||
      !(in.firstHalfShare.empty() || in.firstHalfShare.size() == n) || in.albedo.size() != 3 * n ||
      in.normal.size() != 3 * n || in.depth.size() != n)
    throw std::invalid_argument("denoise: the half buffers and features do not match the image size");
  for (const float share : in.firstHalfShare)
    if (!(share > 0.0f && share < 1.0f))
      throw std::invalid_argument("denoise: a half buffer's share of the samples must lie strictly between 0 and 1");
}

// Both halves filtered, each with the other's weights (cross-filtering), and averaged, each in
// proportion to its share of the samples (the inverse of its variance).
std::vector<float> filterHalves(const DenoiseInput& in, const std::vector<float>& halfA, const std::vector<float>& halfB,
                                const std::vector<float>& samplesVariance, const std::vector<float>& features,
                                const DenoiseSettings& settings) {
  const HalfVariances variance = halfBufferVariances(in, halfA, halfB, samplesVariance);
  // A with B's weights, B with A's: the weights' distances are the guide's, so its variance.
  const HalfFilter filterA(in, halfA, halfB, variance.b, features, settings);
  const HalfFilter filterB(in, halfB, halfA, variance.a, features, settings);
  std::vector<float> a(halfA.size()), b(halfB.size());
  const int bands = (in.height + kBandRows - 1) / kBandRows;
  tbb::parallel_for(tbb::blocked_range<int>(0, 2 * bands, 1), [&](const tbb::blocked_range<int>& range) {
    for (int i = range.begin(); i != range.end(); ++i) {
      const int band = i % bands;
      const int y0 = band * kBandRows, y1 = std::min(in.height, y0 + kBandRows);
      if (i < bands) filterA.filterBand(y0, y1, a);
      else filterB.filterBand(y0, y1, b);
    }
  });
  for (size_t i = 0; i < a.size(); ++i) {
    const float share = in.firstHalfShare.empty() ? 0.5f : in.firstHalfShare[i / 3];
    a[i] = share * a[i] + (1.0f - share) * b[i];
  }
  return a;
}

}  // namespace

std::vector<float> denoise(const DenoiseInput& in, const DenoiseSettings& settings) {
  checkInput(in);
  std::vector<float> halfA = in.halfA, halfB = in.halfB;
  const bool split = !in.subsurfaceA.empty();
  std::vector<float> subsurfaceA = in.subsurfaceA, subsurfaceB = in.subsurfaceB;
  suppressFireflies(in.width, in.height, halfA, halfB, split ? &subsurfaceA : nullptr, split ? &subsurfaceB : nullptr);
  const std::vector<float> features = regressionFeatures(in);
  if (!split) return filterHalves(in, halfA, halfB, in.variance, features, settings);
  // The rest (specular light, water, the iris) as the whole image would be; its samples' variance
  // is not kept, the whole pixel's bounds it instead.
  for (size_t i = 0; i < halfA.size(); ++i) halfA[i] -= subsurfaceA[i], halfB[i] -= subsurfaceB[i];
  std::vector<float> out = filterHalves(in, halfA, halfB, in.variance, features, settings);
  DenoiseSettings wide = settings;
  wide.windowRadius = settings.subsurfaceWindowRadius;
  wide.windowStep = settings.subsurfaceWindowStep;
  const std::vector<float> subsurface = filterHalves(in, subsurfaceA, subsurfaceB, in.subsurfaceVariance, features, wide);
  for (size_t i = 0; i < out.size(); ++i) out[i] += subsurface[i];
  return out;
}

}  // namespace lacrima
