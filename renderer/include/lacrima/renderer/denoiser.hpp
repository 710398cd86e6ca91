#pragma once
// A feature-guided denoiser for path-traced frames: first-order regression on the first-hit
// features, weighted by non-local means on the colour, cross-filtered between two independent
// half buffers. After Bitterli, Rousselle, Moon, Iglesias-Guitian, Adler, Mitchell, Jarosz &
// Novak 2016, "Nonlinearly Weighted First-order Regression for Denoising Monte Carlo
// Renderings" (NFOR), sec. 4-5, with the non-local means weights of Rousselle, Knaus & Zwicker
// 2012, "Adaptive rendering with non-local means filtering", eq. 3-4 (after Buades, Coll & Morel
// 2005). What lacrima's version leaves out of NFOR: the feature prefiltering and the per-pixel
// selection among bandwidths (tried: no better on the default shot, docs/denoising.md).
//
// For each pixel p and each neighbour q in a (2r+1)^2 window, a weight from the patch distance
// between p and q in the guide buffer, normalised by the colour variance (so noise alone gives a
// distance near 0 and a weight near 1, and a real difference of a few standard deviations a
// weight near 0); then the colour of the filtered buffer over the window is fitted, by weighted
// least squares, as a linear function of the features' differences from p's (albedo, shading
// normal, inverse depth), and the fit at p is the output. A texture edge or a silhouette that
// the features show is kept by the regression even where the colour is too noisy to show it; a
// highlight, a refraction or a shadow that the features do not show is kept by the weights.
// Half A is filtered with weights from half B and B with weights from A (the weights' noise is
// then independent of the values they average, which removes most of the bias of a self-guided
// filter), and the output is their mean. Each fitted value is kept within the range of the
// values that carry weight in its window: a regression may extrapolate where a bright outlier
// (a catchlight, a firefly) sits at the window's edge with a large feature difference, and would
// draw a dark ring around it. Before all this, fireflies are scaled down: a pixel of one half
// more than twice as bright as the 75th percentile of its neighbourhood and as the same pixel of
// the other half (denoiser.cpp, suppressFireflies); else every window holding one would lift a
// square around it.
#include <vector>

namespace lacrima {


struct DenoiseInput {
  int width = 0, height = 0;
  // Two independent estimates of each pixel's colour (RGB, 3 floats a pixel), e.g. the means of
  // the first and second halves of its samples.
  std::vector<float> halfA, halfB;
  // The share of the pixel's samples in halfA (1 a pixel; optional, empty: 1/2 everywhere). The
  // halves need not be equal: the renderer's first half is the largest power of two below the
  // sample count, so 12 samples split 8 + 4. Each half's variance and its weight in the result
  // follow its share.
  std::vector<float> firstHalfShare;
  // The variance of one half's estimate (3 a pixel) from the samples, their variance over half
  // their count: optional, it bounds the estimate from the halves' difference (denoiser.cpp).
  std::vector<float> variance;
  std::vector<float> albedo;  // 3 a pixel
  std::vector<float> normal;  // 3 a pixel (zero where nothing was hit)
  std::vector<float> depth;   // 1 a pixel (infinite where nothing was hit)
  // Optional (empty: none): the subsurface light's part of halfA and halfB, and the variance of
  // its own half estimates. Given, it is filtered apart from the rest over the wider
  // DenoiseSettings::subsurfaceWindowRadius, and the two added: the diffusion profile makes that
  // light smooth over many more pixels than the rest (a 1.3 mm mean free path spans ~30 pixels of
  // the default shot's 1080p close-up; docs/denoising.md).
  std::vector<float> subsurfaceA, subsurfaceB, subsurfaceVariance;
};

struct DenoiseSettings {
  // Neighbours within this many pixels (a 13 x 13 window). On the default shot's close-up with
  // subsurface skin (FLIP against a 2048-spp reference, 16 / 64 spp, tear region): 9 x 9 0.0787 /
  // 0.0479, 13 x 13 0.0773 / 0.0470, 17 x 17 0.0788 / 0.0480 (docs/denoising.md). It costs 1.6x
  // the denoising time of 9 x 9.
  int windowRadius = 6;
  // The subsurface light's window (DenoiseInput::subsurfaceA). On the tear's 1:1 crop at 8 spp
  // (FLIP crop / trail / skin; a measuring build, docs/denoising.md): 13 x 13 0.0795 / 0.0859 /
  // 0.0529, 21 x 21 0.0643 / 0.0692 / 0.0461, 31 x 31 0.0557 / 0.0602 / 0.0424; a full 31 x 31
  // costs ~5x the 13 x 13 pass.
  int subsurfaceWindowRadius = 28;
  // One neighbour in each step x step cell of the window, at a fixed jittered place in the cell
  // (the pixel's own cell takes the pixel; 1: every neighbour). The subsurface light's: 4, over
  // 57 x 57, 225 neighbours. Same work, wider or denser, as lattices (every step-th pixel), on the
  // crop at 8 / 16 spp (FLIP crop, skin): 29 x 29 every 2nd 0.0541, 0.0286 / 0.0438, 0.0211;
  // 43 x 43 every 3rd 0.0498, 0.0261 / 0.0413, 0.0201; 57 x 57 every 4th 0.0488, 0.0252 / 0.0413,
  // 0.0200; 71 x 71 every 5th 0.0492, 0.0251 / 0.0422, 0.0199; 85 x 85 every 6th 0.0503, 0.0247 /
  // 0.0434, 0.0203 (61 x 61 every 3rd, twice the work: 0.0469, 0.0241 / 0.0405, 0.0196). A lattice
  // leaves a grid of its period in the denoised image; jittered, 57 x 57: 0.0500, 0.0255 / 0.0421,
  // 0.0200, no grid (docs/denoising.md, "A wider window, jittered").
  int windowStep = 1;
  int subsurfaceWindowStep = 4;
  int patchRadius = 3;   // 7 x 7 patches for the colour distance
  // Non-local means' bandwidth k (Rousselle et al. 2012): distances are in units of k^2 times
  // the variance; smaller keeps more detail and removes less noise.
  float bandwidth = 0.45f;
};

// The denoised colour, 3 floats a pixel. Throws std::invalid_argument for inconsistent sizes.
std::vector<float> denoise(const DenoiseInput& input, const DenoiseSettings& settings = {});

}  // namespace lacrima
