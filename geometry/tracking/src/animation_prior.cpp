// The MPPCA animation prior; see animation_prior.hpp.
#include "lacrima/tracking/animation_prior.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "lacrima/base/hash.hpp"

namespace lacrima::tracking {

namespace {

double logSumExp(const std::vector<double>& values) {
  const double top = *std::max_element(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += std::exp(v - top);
  return top + std::log(sum);
}

// Every window [x_i; x_{i-1}; ...; x_{i-n}] of the sequences, one per row.
Eigen::MatrixXd windowsOf(const std::vector<WeightSequence>& sequences, int m, int n) {
  size_t rows = 0;
  for (const WeightSequence& s : sequences) rows += s.size();
  Eigen::MatrixXd y(long(rows), long(m) * (n + 1));
  long row = 0;
  for (const WeightSequence& s : sequences)
    for (size_t i = 0; i < s.size(); ++i, ++row)
      for (int j = 0; j <= n; ++j) y.block(row, long(j) * m, 1, m) = s[i >= size_t(j) ? i - size_t(j) : 0].transpose();
  return y;
}

// One analyser's covariance as the PPCA maximum-likelihood fit to its weighted covariance S (the
// M-step of Tipping & Bishop 1999): the q leading eigenvalues kept, the others replaced by their
// mean sigma^2 (at least `floor`).
Eigen::MatrixXd ppcaCovariance(const Eigen::MatrixXd& s, int q, double floor) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(s);
  const Eigen::VectorXd& values = eigen.eigenvalues();  // ascending
  const long l = values.size(), kept = std::min<long>(q, l);
  double discarded = 0.0;
  for (long i = 0; i < l - kept; ++i) discarded += values[i];
  const double sigma2 = std::max(floor, l > kept ? discarded / double(l - kept) : floor);
  Eigen::VectorXd model(l);
  for (long i = 0; i < l; ++i) model[i] = i < l - kept ? sigma2 : std::max(values[i], sigma2);
  return eigen.eigenvectors() * model.asDiagonal() * eigen.eigenvectors().transpose();
}

struct Mixture {
  std::vector<double> logWeights;
  std::vector<Eigen::VectorXd> means;
  std::vector<Eigen::MatrixXd> covariances;
  double logLikelihood = -std::numeric_limits<double>::infinity();  // mean per point
};

// Per point and analyser, ln pi_k + ln N(z; mu_k, C_k).
Eigen::MatrixXd logDensities(const Eigen::MatrixXd& z, const Mixture& mixture) {
  const long n = z.rows(), l = z.cols(), k = long(mixture.means.size());
  Eigen::MatrixXd out(n, k);
  for (long c = 0; c < k; ++c) {
    const Eigen::LLT<Eigen::MatrixXd> llt(mixture.covariances[size_t(c)]);
    const Eigen::MatrixXd diff = (z.rowwise() - mixture.means[size_t(c)].transpose()).transpose();
    const Eigen::MatrixXd whitened = llt.matrixL().solve(diff);
    const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    out.col(c) = (-0.5 * whitened.colwise().squaredNorm().array() - 0.5 * (logDet + double(l) * std::log(2.0 * std::numbers::pi)) +
                  mixture.logWeights[size_t(c)])
                     .transpose();
  }
  return out;
}

Mixture runEm(const Eigen::MatrixXd& z, int components, int q, double floor, int iterations, uint64_t seed) {
  const long n = z.rows(), l = z.cols();
  Mixture mixture;
  const Eigen::VectorXd globalMean = z.colwise().mean();
  const Eigen::MatrixXd centred = z.rowwise() - globalMean.transpose();
  const Eigen::MatrixXd globalCovariance = centred.transpose() * centred / double(n) + floor * Eigen::MatrixXd::Identity(l, l);
  // Start: K distinct training points as means (a seeded shuffle), the data's covariance each.
  std::vector<long> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  for (long i = n - 1; i > 0; --i) std::swap(order[size_t(i)], order[hashCombine(seed, uint64_t(i)) % uint64_t(i + 1)]);
  for (int c = 0; c < components; ++c) {
    mixture.logWeights.push_back(-std::log(double(components)));
    mixture.means.push_back(z.row(order[size_t(c) % size_t(n)]).transpose());
    mixture.covariances.push_back(globalCovariance);
  }
  for (int iteration = 0; iteration < iterations; ++iteration) {
    // E-step: responsibilities.
    Eigen::MatrixXd logs = logDensities(z, mixture);
    double total = 0.0;
    for (long i = 0; i < n; ++i) {
      const double top = logs.row(i).maxCoeff();
      const double norm = top + std::log((logs.row(i).array() - top).exp().sum());
      logs.row(i) = (logs.row(i).array() - norm).exp();
      total += norm;
    }
    const double previous = mixture.logLikelihood;
    mixture.logLikelihood = total / double(n);
    if (iteration > 0 && mixture.logLikelihood - previous < 1e-7 * std::abs(previous)) break;
    // M-step (Tipping & Bishop 1999, MPPCA: weights, means, then each analyser's PPCA fit).
    for (int c = 0; c < components; ++c) {
      const Eigen::VectorXd gamma = logs.col(c);
      const double count = gamma.sum();
      if (count < 1e-8 * double(n)) {  // an analyser nothing belongs to: restart it at a point
        mixture.means[size_t(c)] = z.row(order[size_t(c + iteration * components) % size_t(n)]).transpose();
        mixture.covariances[size_t(c)] = globalCovariance;
        mixture.logWeights[size_t(c)] = std::log(1.0 / double(n));
        continue;
      }
      mixture.logWeights[size_t(c)] = std::log(count / double(n));
      const Eigen::VectorXd mean = z.transpose() * gamma / count;
      const Eigen::MatrixXd diff = z.rowwise() - mean.transpose();
      const Eigen::MatrixXd s = diff.transpose() * gamma.asDiagonal() * diff / count;
      mixture.means[size_t(c)] = mean;
      mixture.covariances[size_t(c)] = ppcaCovariance(s, q, floor);
    }
  }
  return mixture;
}

}  // namespace

AnimationPrior AnimationPrior::train(const std::vector<WeightSequence>& sequences, const AnimationPriorParams& params) {
  if (sequences.empty() || sequences.front().empty()) throw std::invalid_argument("AnimationPrior::train: no frames");
  const int m = int(sequences.front().front().size());
  for (const WeightSequence& s : sequences)
    for (const Eigen::VectorXd& x : s)
      if (x.size() != m) throw std::invalid_argument("AnimationPrior::train: frames of different weight counts");
  AnimationPrior prior;
  prior.weights_ = m;
  prior.previous_ = params.previousFrames;
  const Eigen::MatrixXd y = windowsOf(sequences, m, params.previousFrames);
  const long d = y.cols();
  // The windows' PCA, keeping `keptVariance` of it; the rest is the isotropic residual.
  prior.mean_ = y.colwise().mean();
  const Eigen::MatrixXd centred = y.rowwise() - prior.mean_.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> pca(centred.transpose() * centred / double(y.rows()));
  const Eigen::VectorXd values = pca.eigenvalues().reverse();
  const double total = std::max(values.sum(), 1e-300);
  long kept = 0;
  for (double sum = 0.0; kept < d && sum < params.keptVariance * total; ++kept) sum += values[kept];
  kept = std::max<long>(kept, 1);
  prior.basis_ = pca.eigenvectors().rightCols(kept).rowwise().reverse();
  const double dropped = values.tail(d - kept).sum();
  // The variance no direction goes below: training weights are known to about `weightPrecision`;
  // without it a run of identical windows (a held neutral face) collapses an analyser onto a
  // point, and its spike holds the fit there.
  const double floor = std::max(params.weightPrecision * params.weightPrecision, 1e-12 * total);
  prior.residualVariance_ = std::max(floor, d > kept ? dropped / double(d - kept) : floor);
  // MPPCA in the latent space, the best of several starts.
  const Eigen::MatrixXd z = centred * prior.basis_;
  const int q = std::max(1, int(kept) / 3);
  Mixture best;
  for (int run = 0; run < params.restarts; ++run) {
    Mixture m0 = runEm(z, std::min<int>(params.components, int(z.rows())), q, floor, params.iterations,
                       hashCombine(params.seed, uint64_t(run)));
    if (m0.logLikelihood > best.logLikelihood) best = std::move(m0);
  }
  prior.trainingLogLikelihood_ = best.logLikelihood;
  for (size_t c = 0; c < best.means.size(); ++c) {
    const Eigen::LLT<Eigen::MatrixXd> llt(best.covariances[c]);
    Analyser a;
    a.logWeight = best.logWeights[c];
    a.mean = best.means[c];
    a.precision = llt.solve(Eigen::MatrixXd::Identity(kept, kept));
    a.logDeterminant = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
    prior.components_.push_back(std::move(a));
  }
  return prior;
}

Eigen::VectorXd AnimationPrior::window(const Eigen::VectorXd& x, const WeightSequence& previous) const {
  Eigen::VectorXd y(long(weights_) * (previous_ + 1));
  y.head(weights_) = x;
  for (int j = 1; j <= previous_; ++j) {
    const Eigen::VectorXd& p = previous.empty() ? x : previous[std::min(size_t(j - 1), previous.size() - 1)];
    y.segment(long(j) * weights_, weights_) = p;
  }
  return y;
}

double AnimationPrior::responsibilities(const Eigen::VectorXd& z, std::vector<double>& gamma) const {
  std::vector<double> logs;
  for (const Analyser& a : components_) {
    const Eigen::VectorXd diff = z - a.mean;
    logs.push_back(a.logWeight - 0.5 * (diff.dot(a.precision * diff) + a.logDeterminant));
  }
  const double norm = logSumExp(logs);
  gamma.resize(logs.size());
  for (size_t k = 0; k < logs.size(); ++k) gamma[k] = std::exp(logs[k] - norm);
  return -norm;
}

double AnimationPrior::energy(const Eigen::VectorXd& x, const WeightSequence& previous) const {
  const Eigen::VectorXd y = window(x, previous) - mean_;
  const Eigen::VectorXd z = basis_.transpose() * y;
  std::vector<double> gamma;
  return responsibilities(z, gamma) + (y - basis_ * z).squaredNorm() / (2.0 * residualVariance_);
}

void AnimationPrior::quadraticModel(const Eigen::VectorXd& x, const WeightSequence& previous, Eigen::MatrixXd& hessian,
                                    Eigen::VectorXd& gradient) const {
  const Eigen::VectorXd y = window(x, previous) - mean_;
  const Eigen::VectorXd z = basis_.transpose() * y;
  std::vector<double> gamma;
  responsibilities(z, gamma);
  const long l = z.size();
  Eigen::MatrixXd precision = Eigen::MatrixXd::Zero(l, l);
  Eigen::VectorXd latentGradient = Eigen::VectorXd::Zero(l);
  for (size_t k = 0; k < components_.size(); ++k) {
    precision += gamma[k] * components_[k].precision;
    latentGradient += gamma[k] * (components_[k].precision * (z - components_[k].mean));
  }
  const Eigen::MatrixXd px = basis_.topRows(weights_);  // the rows of P that x moves
  const Eigen::VectorXd residual = y - basis_ * z;
  gradient = px * latentGradient + residual.head(weights_) / residualVariance_;
  hessian = px * precision * px.transpose() +
            (Eigen::MatrixXd::Identity(weights_, weights_) - px * px.transpose()) / residualVariance_;
}

WeightSequence keyedPerformance(const std::vector<Eigen::VectorXd>& expressions, int frames, uint64_t seed) {
  if (expressions.empty()) throw std::invalid_argument("keyedPerformance: no expressions");
  const long weights = expressions.front().size();
  const auto uniform = [&](uint64_t a, uint64_t b) { return double(uint64ToUnitFloat(hashCombine(hashCombine(seed, a), b))); };
  std::vector<std::pair<int, Eigen::VectorXd>> keys;  // (frame, weights)
  for (int frame = 0, key = 0; frame < frames + 20; ++key) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(weights);
    if (key > 0 && uniform(uint64_t(key), 0) >= 0.25) {
      const int blended = uniform(uint64_t(key), 1) < 0.5 ? 1 : 2;
      for (int b = 0; b < blended; ++b) {
        const size_t e = size_t(uniform(uint64_t(key), uint64_t(2 + b)) * double(expressions.size())) % expressions.size();
        w += (0.3 + 0.7 * uniform(uint64_t(key), uint64_t(4 + b))) * expressions[e];
      }
    }
    keys.emplace_back(frame, w.cwiseMax(0.0).cwiseMin(1.0));
    frame += 6 + int(uniform(uint64_t(key), 99) * 15.0);
  }
  WeightSequence sequence;
  size_t k = 0;
  for (int frame = 0; frame < frames; ++frame) {
    while (k + 1 < keys.size() && keys[k + 1].first <= frame) ++k;
    const auto& [f0, w0] = keys[k];
    const auto& [f1, w1] = keys[std::min(k + 1, keys.size() - 1)];
    const double t = f1 > f0 ? double(frame - f0) / double(f1 - f0) : 0.0;
    sequence.push_back(w0 + t * t * (3.0 - 2.0 * t) * (w1 - w0));
  }
  return sequence;
}

void addSpontaneousBlinks(WeightSequence& performance, const Eigen::VectorXd& blink, double fps, uint64_t seed) {
  const auto uniform = [&](uint64_t a, uint64_t b) { return double(uint64ToUnitFloat(hashCombine(hashCombine(seed, a), b))); };
  const auto framesOf = [&](double seconds) { return std::max(1, int(std::lround(seconds * fps))); };
  double start = 0.0;
  for (uint64_t n = 0;; ++n) {
    start += (2.0 + 4.0 * uniform(n, 0)) * fps;  // frames to the next blink
    const int first = int(start);
    if (first >= int(performance.size())) return;
    const double closing = 0.07 + 0.03 * uniform(n, 1);
    const int close = framesOf(closing), shut = int(std::lround(0.07 * uniform(n, 2) * fps)), open = framesOf(2.0 * closing);
    for (int i = 0; i < close + shut + open && first + i < int(performance.size()); ++i) {
      const double closure = i < close ? double(i + 1) / double(close)
                             : i < close + shut ? 1.0
                                                : 1.0 - double(i - close - shut + 1) / double(open + 1);
      Eigen::VectorXd& w = performance[size_t(first + i)];
      w = w.cwiseMax(closure * blink).cwiseMin(1.0);
    }
  }
}

Eigen::VectorXd blinkExpression(const std::vector<std::string>& targetNames) {
  return archetypalExpressions(targetNames).at(7);  // the recipes' blink
}

std::vector<Eigen::VectorXd> archetypalExpressions(const std::vector<std::string>& targetNames) {
  using Recipe = std::vector<std::pair<const char*, double>>;
  // "_LR" stands for both sides.
  const std::vector<Recipe> recipes = {
      {{"mouthSmile_LR", 0.8}, {"cheekRaiser_LR", 0.5}, {"eyeSquint_LR", 0.3}},                                 // smile
      {{"browInnerUp_LR", 0.9}, {"browDown_LR", 0.3}, {"mouthFrown_LR", 0.75}, {"mouthShrugLower", 0.3},
       {"eyeSquint_LR", 0.35}, {"cheekRaiser_LR", 0.3}},                                                         // sadness
      {{"mouthStretch_LR", 0.3}, {"mouthShrugLower", 0.25}, {"cheekRaiser_LR", 0.2}, {"eyeSquint_LR", 0.2},
       {"mouthLowerDown_LR", 0.3}},                                                                              // sob
      {{"browInnerUp_LR", 0.8}, {"browOuterUp_LR", 0.8}, {"eyeWide_LR", 0.7}, {"jawOpen", 0.4}},                 // surprise
      {{"browDown_LR", 0.8}, {"eyeSquint_LR", 0.4}, {"mouthPress_LR", 0.5}, {"noseSneer_LR", 0.4}},              // anger
      {{"noseSneer_LR", 0.8}, {"mouthUpperUp_LR", 0.6}, {"browDown_LR", 0.4}, {"cheekSquint_LR", 0.3}},          // disgust
      {{"browInnerUp_LR", 0.7}, {"eyeWide_LR", 0.8}, {"mouthStretch_LR", 0.6}, {"jawOpen", 0.2}},                // fear
      {{"eyeBlink_LR", 1.0}},                                                                                    // blink
      {{"mouthPucker", 0.8}, {"mouthFunnel", 0.3}},                                                              // pucker
      {{"jawOpen", 0.8}, {"mouthLowerDown_LR", 0.3}},                                                            // jaw open
      {{"mouthSmile_L", 0.7}, {"cheekRaiser_L", 0.3}, {"mouthDimple_L", 0.3}},                                   // smirk left
      {{"mouthSmile_R", 0.7}, {"cheekRaiser_R", 0.3}, {"mouthDimple_R", 0.3}},                                   // smirk right
  };
  const auto set = [&](Eigen::VectorXd& w, const std::string& name, double value) {
    const auto it = std::find(targetNames.begin(), targetNames.end(), name);
    if (it != targetNames.end()) w[it - targetNames.begin()] = value;
  };
  std::vector<Eigen::VectorXd> out;
  for (const Recipe& recipe : recipes) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(long(targetNames.size()));
    for (const auto& [name, value] : recipe) {
      const std::string n = name;
      if (n.size() > 3 && n.ends_with("_LR")) {
        set(w, n.substr(0, n.size() - 3) + "_L", value);
        set(w, n.substr(0, n.size() - 3) + "_R", value);
      } else {
        set(w, n, value);
      }
    }
    out.push_back(w);
  }
  return out;
}

AnimationPriorParams archetypalPriorParams() {
  AnimationPriorParams params;
  params.components = 10;
  params.restarts = 1;
  params.iterations = 30;
  params.keptVariance = 0.999;
  return params;
}

AnimationPrior archetypalPrior(const std::vector<std::string>& targetNames, const AnimationPriorParams& params) {
  const std::vector<Eigen::VectorXd> expressions = archetypalExpressions(targetNames);
  std::vector<WeightSequence> training;
  for (uint64_t s = 0; s < 30; ++s) {
    training.push_back(keyedPerformance(expressions, 120, 1000 + s));
    addSpontaneousBlinks(training.back(), blinkExpression(targetNames), 30.0, 2000 + s);
  }
  return AnimationPrior::train(training, params);
}

}  // namespace lacrima::tracking
