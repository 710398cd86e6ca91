// Error against samples per pixel: the stratified (Owen-scrambled Sobol) sampler must converge
// faster than independent random numbers, whose RMSE falls as spp^-0.5. Measured on two small
// scenes whose pixels integrate discontinuous functions, where stratification is expected to
// give about spp^-0.75 (Owen 1997, "Scrambled net variance for integrals of smooth functions";
// for discontinuities, Mitchell 1996, "Consequences of stratified sampling in graphics"): a soft
// shadow under a rectangle light, and an out-of-focus sphere seen through a thin lens.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace sampler_convergence_test {

using test::lookAt;

// A diffuse floor and a diffuse ball lit by a 1 m square light 2 m up: the camera looks down at
// the ball's penumbra. Every pixel integrates over its area, the light and (for the light's
// BSDF-sampled hits) the hemisphere.
Frame softShadowScene() {
  Frame frame = test::softShadowFrame(30.0f);
  frame.settings = test::smallSettings(12, 1, 1);
  return frame;
}

// An emitting sphere 2 m from a thin lens focused at 6 m, on black: each pixel is the fraction of
// its (pixel x lens) rays that see the sphere, a 4D integral with a blurred edge.
Frame defocusedSphereScene() {
  Frame frame;
  frame.materials.push_back(Material{"glow", DiffuseParams{Color::Zero()}, Color::Ones()});
  frame.spheres.push_back(Sphere{Vec3(0, 0, 0), 0.5f, 0});
  frame.camera = lookAt(Vec3(0.35f, 0.2f, 2.0f), Vec3(0.35f, 0.2f, 0), 25.0f);  // the sphere's edge in view
  frame.camera.lensRadius = 0.1f;
  frame.camera.focusDistance = 6.0f;
  frame.settings = test::smallSettings(12, 1, 0);
  return frame;
}

Film render(Frame frame, SamplerKind kind, int spp, uint64_t seed) {
  frame.settings.sampler = kind;
  frame.settings.samplesPerPixel = spp;
  frame.settings.seed = seed;
  return renderFrame(frame);
}

double rmse(const Film& image, const Film& reference) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < image.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c, ++n) sum += std::pow(double(image.rgba[p + c]) - reference.rgba[p + c], 2);
  return std::sqrt(sum / double(n));
}

struct Convergence {
  double slope;       // least squares of log RMSE over log spp
  double finalError;  // RMSE at the largest spp
};

// The RMSE at 4, 16, 64 and 256 spp, each the mean over four seeds (one render's RMSE over 144
// pixels is itself noisy), against a 4096-spp Sobol reference with its own seed (its own error,
// about 0.2 of the 256-spp error, adds 2 % in quadrature).
Convergence measure(const Frame& frame, SamplerKind kind) {
  const Film reference = render(frame, SamplerKind::Sobol, 4096, 1000);
  std::vector<double> logSpp, logError;
  double finalError = 0.0;
  for (int spp : {4, 16, 64, 256}) {
    double error = 0.0;
    for (uint64_t seed = 1; seed <= 4; ++seed) error += rmse(render(frame, kind, spp, seed), reference) / 4.0;
    logSpp.push_back(std::log(double(spp)));
    logError.push_back(std::log(error));
    finalError = error;
  }
  const double n = double(logSpp.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < logSpp.size(); ++i) {
    sx += logSpp[i], sy += logError[i], sxx += logSpp[i] * logSpp[i], sxy += logSpp[i] * logError[i];
  }
  return {(n * sxy - sx * sy) / (n * sxx - sx * sx), finalError};
}

void expectStratificationPays(const Frame& frame) {
  const Convergence independent = measure(frame, SamplerKind::Independent);
  const Convergence sobol = measure(frame, SamplerKind::Sobol);
  ::testing::Test::RecordProperty("independent_slope", std::to_string(independent.slope));
  ::testing::Test::RecordProperty("sobol_slope", std::to_string(sobol.slope));
  std::printf("slopes: independent %.3f, sobol %.3f; RMSE at 256 spp: independent %.5f, sobol %.5f\n",
              independent.slope, sobol.slope, independent.finalError, sobol.finalError);
  EXPECT_NEAR(independent.slope, -0.5, 0.08);  // the baseline behaves as Monte Carlo theory says
  EXPECT_LT(sobol.slope, -0.58);  // measured -0.64 (soft shadow), -0.63 (defocus)
  EXPECT_LT(sobol.finalError, 0.5 * independent.finalError);
}

TEST(SamplerConvergence, SoftShadowUnderAnAreaLightConvergesFasterThanIndependentSamples) {
  expectStratificationPays(softShadowScene());
}

TEST(SamplerConvergence, DefocusedEdgeConvergesFasterThanIndependentSamples) {
  expectStratificationPays(defocusedSphereScene());
}

}  // namespace sampler_convergence_test
}  // namespace lacrima
