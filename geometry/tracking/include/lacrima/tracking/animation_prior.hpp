#pragma once
// The dynamic expression prior of Weise, Bouaziz, Li & Pauly 2011 (section 3.1, eqs. 6-11):
// the density of the current blendshape weights x together with the n previous frames' X_n,
// p(x, X_n), as a mixture of probabilistic principal component analysers (MPPCA, Tipping & Bishop
// 1999) learned by EM from existing animations, in a PCA latent space of the windows that keeps 99 %
// of their variance (Weise et al.: "a more stable learning phase"), each analyser of a third of the
// latent dimension (Weise et al.'s choice), the EM run from several random starts (Weise et al.: 50) and
// the most likely kept.
// The latent model is singular in the full space of windows; lacrima gives the directions PCA
// dropped an isotropic Gaussian of their mean variance, so that -ln p is finite everywhere:
//   y = [x; x_{i-1}; ...; x_{i-n}],  z = P^T (y - mean),  r = (I - P P^T)(y - mean),
//   -ln p(y) = -ln sum_k pi_k N(z; mu_k, C_k) + |r|^2 / (2 sigma_r^2) + const,
//   C_k = W_k W_k^T + sigma_k^2 I (eq. 7, in the latent space: eq. 10).
// For the fit, the energy's gradient in x (Weise et al.'s eqs. 19-21) and a Gauss-Newton Hessian (the
// mixture's responsibilities held at the current x).
#include <cstdint>
#include <string>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima::tracking {

// A weight sequence: one vector of m weights per frame.
using WeightSequence = std::vector<Eigen::VectorXd>;

struct AnimationPriorParams {
  int previousFrames = 3;         // n (Weise et al. found 3 <= n <= 5 good)
  int components = 20;            // K analysers (Weise et al.'s 20)
  double keptVariance = 0.99;     // of the windows' PCA
  int restarts = 8;               // EM runs from random starts (Weise et al.'s 50)
  int iterations = 60;            // EM iterations per run
  uint64_t seed = 1;
  // The training weights' precision: no variance of the model falls below its square (a held
  // pose repeated over many frames would otherwise make a spike the fit cannot leave).
  double weightPrecision = 0.01;
};

class AnimationPrior {
 public:
  // Learns the prior from sequences (each at least one frame; a window reaching before a
  // sequence's start repeats its first frame). Throws std::invalid_argument without data or with
  // sequences of different weight counts.
  static AnimationPrior train(const std::vector<WeightSequence>& sequences, const AnimationPriorParams& params = {});

  int weightCount() const { return weights_; }
  int previousFrames() const { return previous_; }
  int latentDimension() const { return int(basis_.cols()); }
  int componentCount() const { return int(components_.size()); }
  // The mean log-likelihood per window of the training data, as EM left it.
  double trainingLogLikelihood() const { return trainingLogLikelihood_; }

  // -ln p(x, X_n) up to a constant; `previous` holds x_{i-1}, x_{i-2}, ... (missing ones repeat
  // the last given, or x itself when none is given).
  double energy(const Eigen::VectorXd& x, const WeightSequence& previous) const;
  // The energy's gradient in x, and its Gauss-Newton Hessian in x (positive definite).
  void quadraticModel(const Eigen::VectorXd& x, const WeightSequence& previous, Eigen::MatrixXd& hessian,
                      Eigen::VectorXd& gradient) const;

 private:
  struct Analyser {
    double logWeight = 0.0;       // ln pi_k
    Eigen::VectorXd mean;         // mu_k, latent
    Eigen::MatrixXd precision;    // C_k^{-1}
    double logDeterminant = 0.0;  // ln det C_k
  };
  Eigen::VectorXd window(const Eigen::VectorXd& x, const WeightSequence& previous) const;
  // Per analyser, its responsibility for latent point z; and -ln sum_k pi_k N(z; mu_k, C_k).
  double responsibilities(const Eigen::VectorXd& z, std::vector<double>& gamma) const;

  int weights_ = 0, previous_ = 0;
  Eigen::VectorXd mean_;   // of the windows
  Eigen::MatrixXd basis_;  // P: orthonormal columns, the kept principal directions
  double residualVariance_ = 1.0;  // sigma_r^2
  std::vector<Analyser> components_;
  double trainingLogLikelihood_ = 0.0;
};

// Synthetic performances to train and test on when no captured ones are at hand: keys every 6-20
// frames, the first the neutral face (a take starts from it), each later one the neutral face (one
// key in four) or a blend of one or two of `expressions` at intensities in [0.3, 1], eased between
// keys by smoothstep, clamped to [0, 1]. Deterministic in `seed`.
WeightSequence keyedPerformance(const std::vector<Eigen::VectorXd>& expressions, int frames, uint64_t seed);

// Spontaneous blinks laid over a performance, as a face blinks whatever its expression: one every
// 2-6 s (a resting adult's 15-20 a minute, Bentivoglio et al. 1997), the lids closing in 70-100 ms,
// held shut for up to 70 ms and opening in twice the closing time (VanderWerf et al. 2003).
// The lids close over whatever the face does: each weight is raised to at least the closure times
// its `blink` weight (the eyes-shut weights), the others kept. Deterministic in `seed`.
void addSpontaneousBlinks(WeightSequence& performance, const Eigen::VectorXd& blink, double fps, uint64_t seed);

// Archetypal expressions over ARKit-style target names (the ICT face's), as FACS-style
// combinations of action units (Ekman & Friesen 1978): smile, sadness (the default shot's), sob,
// surprise, anger, disgust, fear, a blink, a pucker, jaw open, and a left and right smirk. Targets
// the names do not have are left out.
std::vector<Eigen::VectorXd> archetypalExpressions(const std::vector<std::string>& targetNames);

// The eyes-shut weights: the archetypal blink's.
Eigen::VectorXd blinkExpression(const std::vector<std::string>& targetNames);

// The prior lacrima trains when a production gives no animations: 30 keyed performances of 120
// frames at 30 fps blending the archetypal expressions, with spontaneous blinks, 10 analysers, one EM start of 30 iterations (about
// 0.1 s for the ICT face's 57 targets; docs/tracking.md, "Training data"); or with other EM
// settings (`lacrima bench --tracking` trains it at Weise et al.'s size too).
AnimationPriorParams archetypalPriorParams();
AnimationPrior archetypalPrior(const std::vector<std::string>& targetNames,
                               const AnimationPriorParams& params = archetypalPriorParams());

}  // namespace lacrima::tracking
