// The animation prior (lacrima/tracking/animation_prior.hpp): synthetic keyed performances; an
// MPPCA learned from them finds held-out windows likelier than jittered or jumping ones; its
// gradient is the energy's; and, on the ICT face seen by a noisy depth sensor, fitting with it
// recovers the weights better than without.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "lacrima/base/hash.hpp"
#include "lacrima/tracking/animation_prior.hpp"
#include "tracking/tracking_support.hpp"

namespace lacrima::tracking {
namespace animation_prior_test {

// n expressions over `weights` targets, each two or three of them (a hash of the seed).
std::vector<Eigen::VectorXd> someExpressions(int weights, int n, uint64_t seed) {
  std::vector<Eigen::VectorXd> out;
  for (int e = 0; e < n; ++e) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(weights);
    for (int t = 0; t < 2 + e % 2; ++t)
      w[long(hashCombine(hashCombine(seed, uint64_t(e)), uint64_t(t)) % uint64_t(weights))] = 0.5 + 0.1 * t;
    out.push_back(w);
  }
  return out;
}

std::vector<WeightSequence> keyedSequences(const std::vector<Eigen::VectorXd>& expressions, int count, int frames, uint64_t seed) {
  std::vector<WeightSequence> out;
  for (int s = 0; s < count; ++s) out.push_back(keyedPerformance(expressions, frames, hashCombine(seed, uint64_t(s))));
  return out;
}

TEST(KeyedPerformance, IsDeterministicBoundedAndSmooth) {
  const std::vector<Eigen::VectorXd> expressions = someExpressions(10, 4, 1);
  const WeightSequence a = keyedPerformance(expressions, 200, 5), b = keyedPerformance(expressions, 200, 5);
  ASSERT_EQ(a.size(), 200u);
  double largestStep = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i] == b[i]);
    EXPECT_GE(a[i].minCoeff(), 0.0);
    EXPECT_LE(a[i].maxCoeff(), 1.0);
    if (i > 0) largestStep = std::max(largestStep, (a[i] - a[i - 1]).cwiseAbs().maxCoeff());
  }
  // Keys at least 6 frames apart, eased by smoothstep (slope at most 1.5 / 6 per unit change).
  EXPECT_LE(largestStep, 0.25 + 1e-12);
  EXPECT_FALSE(keyedPerformance(expressions, 200, 6)[50] == a[50]) << "another seed, another performance";
}

TEST(SpontaneousBlinks, AFaceBlinksEveryTwoToSixSecondsEachBlinkShortAndFull) {
  // Two targets: the lid (the blink's) and another the blinks leave alone.
  Eigen::VectorXd shut = Eigen::VectorXd::Zero(2);
  shut[0] = 1.0;
  const double fps = 30.0;
  WeightSequence minute(size_t(60.0 * fps), Eigen::Vector2d(0.2, 0.7));
  addSpontaneousBlinks(minute, shut, fps, 9);
  WeightSequence again(minute.size(), Eigen::Vector2d(0.2, 0.7));
  addSpontaneousBlinks(again, shut, fps, 9);
  int blinks = 0, longest = 0, run = 0;
  for (size_t i = 0; i < minute.size(); ++i) {
    EXPECT_TRUE(minute[i] == again[i]) << "deterministic";
    EXPECT_EQ(minute[i][1], 0.7) << "the other target untouched";
    EXPECT_GE(minute[i][0], 0.2) << "a blink closes over the expression, never opens it";
    const bool closing = minute[i][0] > 0.2;
    if (closing && run == 0) ++blinks;
    run = closing ? run + 1 : 0;
    longest = std::max(longest, run);
    if (minute[i][0] == 1.0) {
      EXPECT_GT(minute[i - 1][0], 0.2) << "the lids shut over a frame or more, not at once";
    }
  }
  const double shutFrames = double(std::count_if(minute.begin(), minute.end(), [](const Eigen::VectorXd& w) { return w[0] == 1.0; }));
  std::printf("[ blinks ] %d in a minute, the longest %d frames at %g fps, %g frames shut\n", blinks, longest, fps, shutFrames);
  EXPECT_GE(blinks, 10);  // one every 2-6 s: 10 to 30 a minute
  EXPECT_LE(blinks, 30);
  EXPECT_LE(longest, 12) << "a blink lasts under 400 ms";
  EXPECT_GE(shutFrames, double(blinks)) << "every blink shuts the lids";
}

AnimationPriorParams smallPrior() {
  AnimationPriorParams p;
  p.components = 6;
  p.restarts = 2;
  p.iterations = 40;
  return p;
}

TEST(AnimationPrior, HeldOutWindowsAreLikelierThanJitteredOrJumpingOnes) {
  const std::vector<Eigen::VectorXd> expressions = someExpressions(8, 4, 2);
  const AnimationPrior prior = AnimationPrior::train(keyedSequences(expressions, 40, 120, 1), smallPrior());
  EXPECT_EQ(prior.weightCount(), 8);
  EXPECT_GT(prior.latentDimension(), 0);
  EXPECT_LE(prior.latentDimension(), 32);
  const WeightSequence held = keyedPerformance(expressions, 120, 999);
  int likelierThanJitter = 0, likelierThanJump = 0, trials = 0;
  for (size_t i = 10; i < held.size(); i += 7, ++trials) {
    const WeightSequence previous{held[i - 1], held[i - 2], held[i - 3]};
    Eigen::VectorXd jittered = held[i];
    for (long k = 0; k < jittered.size(); ++k)
      jittered[k] = std::clamp(jittered[k] + 0.2 * (double(uint64ToUnitFloat(hashCombine(uint64_t(i), uint64_t(k)))) - 0.5), 0.0, 1.0);
    Eigen::VectorXd jump = held[i];
    jump[long(i % 8)] = 1.0 - jump[long(i % 8)];
    likelierThanJitter += prior.energy(held[i], previous) < prior.energy(jittered, previous);
    likelierThanJump += prior.energy(held[i], previous) < prior.energy(jump, previous);
  }
  std::printf("[ prior ] latent dimension %d; held-out frames likelier than jittered in %d of %d, than a jump in %d\n",
              prior.latentDimension(), likelierThanJitter, trials, likelierThanJump);
  EXPECT_GE(likelierThanJitter, trials * 9 / 10);
  EXPECT_GE(likelierThanJump, trials * 9 / 10);
}

TEST(AnimationPrior, TheGradientIsTheEnergysAndTheHessianIsPositiveDefinite) {
  const std::vector<Eigen::VectorXd> expressions = someExpressions(6, 3, 3);
  const AnimationPrior prior = AnimationPrior::train(keyedSequences(expressions, 20, 80, 2), smallPrior());
  const WeightSequence held = keyedPerformance(expressions, 40, 77);
  const WeightSequence previous{held[19], held[18], held[17]};
  const Eigen::VectorXd x = held[20];
  Eigen::MatrixXd hessian;
  Eigen::VectorXd gradient;
  prior.quadraticModel(x, previous, hessian, gradient);
  for (long k = 0; k < x.size(); ++k) {
    const double h = 1e-6;
    Eigen::VectorXd up = x, down = x;
    up[k] += h, down[k] -= h;
    const double numeric = (prior.energy(up, previous) - prior.energy(down, previous)) / (2 * h);
    EXPECT_NEAR(gradient[k], numeric, 1e-4 * (1.0 + std::abs(numeric))) << "weight " << k;
  }
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(hessian).eigenvalues().minCoeff(), 0.0);
}

TEST(AnimationPrior, FittingWithThePriorRecoversANoisyPerformanceBetter) {
  const BlendshapeModel& model = test::ictModel();
  const int m = model.targetCount();
  // Trained on 30 keyed performances of 120 frames blending the archetypal expressions; tested on
  // another.
  const std::vector<Eigen::VectorXd> expressions = archetypalExpressions(model.targetNames);
  const auto start = std::chrono::steady_clock::now();
  AnimationPriorParams params;
  params.components = 10;
  params.restarts = 1;
  params.iterations = 30;
  const AnimationPrior prior = AnimationPrior::train(keyedSequences(expressions, 30, 120, 3), params);
  const double trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const WeightSequence truth = keyedPerformance(expressions, 40, 4242);
  const Eigen::Isometry3d pose = test::headPose(0.7);
  double withoutSquares = 0.0, withSquares = 0.0, withoutMm = 0.0, withMm = 0.0;
  WeightSequence trackedWithout{truth[0]}, trackedWith{truth[0]};
  for (size_t i = 1; i < truth.size(); ++i) {
    const DepthFrame frame = test::capture(model, truth[i], pose, 1.0, 0.0, i).depth;
    const BlendshapeFitResult without = fitBlendshapes(model, frame, {}, pose, trackedWithout.back());
    PriorTerm term{&prior, {}};
    for (int j = 1; j <= prior.previousFrames(); ++j) term.previous.push_back(trackedWith[trackedWith.size() >= size_t(j) ? trackedWith.size() - size_t(j) : 0]);
    const BlendshapeFitResult with = fitBlendshapes(model, frame, {}, pose, trackedWith.back(), {}, term);
    trackedWithout.push_back(without.weights);
    trackedWith.push_back(with.weights);
    withoutSquares += (without.weights - truth[i]).squaredNorm() / m;
    withSquares += (with.weights - truth[i]).squaredNorm() / m;
    withoutMm += test::vertexRmsMm(model, without.weights, truth[i]) / double(truth.size() - 1);
    withMm += test::vertexRmsMm(model, with.weights, truth[i]) / double(truth.size() - 1);
  }
  const double frames = double(truth.size() - 1);
  std::printf("[ prior ] trained in %.1f s (latent dimension %d, %d analysers); over %d noisy frames, weight RMSE "
              "%.4f without the prior, %.4f with it; mean vertex error %.3f and %.3f mm\n",
              trainSeconds, prior.latentDimension(), prior.componentCount(), int(frames), std::sqrt(withoutSquares / frames),
              std::sqrt(withSquares / frames), withoutMm, withMm);
  // Measured: 0.071 without, 0.029 with (Weise et al.'s figure 8: without the prior, noise becomes
  // implausible expressions).
  EXPECT_LT(std::sqrt(withSquares / frames), 0.05);
  EXPECT_LT(withSquares, 0.25 * withoutSquares);
  EXPECT_LT(withMm, withoutMm);
}

}  // namespace animation_prior_test
}  // namespace lacrima::tracking
