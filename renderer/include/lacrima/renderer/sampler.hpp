#pragma once
// Deterministic random numbers for pixel samples: stratified (Owen-scrambled Sobol) or
// independent hashes, each value a pure function of its key, so images do not depend on thread count.
#include <array>
#include <cstdint>

#include "lacrima/base/hash.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/renderer/sobol.hpp"

namespace lacrima {

// How a pixel's samples are spread (RenderSettings::sampler).
enum class SamplerKind {
  // Owen-scrambled Sobol points (sobol.hpp) in blocks of 1, 2 or 4 dimensions: each block of a
  // pixel's samples is stratified over its samples (a 2D block is a (0,m,2)-net for 2^m samples),
  // each block's sample order shuffled and its points scrambled per pixel. The default.
  Sobol,
  // Independent hashes of (seed, frame, pixel, sample, dimension): no stratification, error
  // falling as spp^-0.5. Kept as the baseline the stratified sampler is measured against.
  Independent,
};

// Which Sobol point each sample index of a pixel takes (SamplerKind::Sobol; per block of dimensions).
enum class SampleOrder {
  // A random permutation of [0, spp) (Kensler 2013): the spp samples together are the first spp
  // points; a prefix of them is a random subset. For a fixed sample count, the default.
  Shuffled,
  // A nested scramble of the index over [0, 2^ceil(log2 spp)) (sobol.hpp, progressiveElement):
  // every prefix of 2^k samples is an aligned block of points, stratified on its own. Adaptive
  // sampling's order, where a pixel may stop after any multiple of its check step.
  Progressive,
};

// The random numbers of one pixel sample: a pure function of (kind, seed, frame, pixel, sample
// index, samples per pixel, dimension), so images depend neither on the thread count nor on the
// order of tiles or frames. Each call draws one block of dimensions (get1D one, get2D two, get4D
// four); setDimension jumps to a given dimension, so that a decision always reads the same
// dimensions whatever branches the path took before it (renderer/src/sample_dimensions.hpp),
// which stratification needs.
class PixelSampler {
 public:
  PixelSampler(SamplerKind kind, uint64_t seed, int frame, int pixelX, int pixelY, int sampleIndex,
               int samplesPerPixel, SampleOrder order = SampleOrder::Shuffled)
      : kind_(kind),
        order_(order),
        pixelKey_(hashCombine(hashCombine(hashCombine(mix64(seed), uint64_t(uint32_t(frame))), uint64_t(uint32_t(pixelX))),
                              uint64_t(uint32_t(pixelY)))),
        sampleKey_(hashCombine(pixelKey_, uint64_t(uint32_t(sampleIndex)))),
        sampleIndex_(uint32_t(sampleIndex)),
        samplesPerPixel_(uint32_t(samplesPerPixel)) {}

  // The independent sampler of the older signature (tests, raw ray benchmarks).
  PixelSampler(uint64_t seed, int frame, int pixelX, int pixelY, int sampleIndex)
      : PixelSampler(SamplerKind::Independent, seed, frame, pixelX, pixelY, sampleIndex, 1) {}

  float get1D() {
    float u;
    draw(1, &u);
    return u;
  }

  Vec2 get2D() {
    float u[2];
    draw(2, u);
    return Vec2(u[0], u[1]);
  }

  // Four dimensions stratified together (Sobol dimensions 0-3 of one shuffled index, Burley
  // 2020's 4D padding): for decisions that act jointly, like the point in the pixel and the
  // point on the lens, whose combination decides what a defocused pixel sees.
  std::array<float, 4> get4D() {
    std::array<float, 4> u;
    draw(4, u.data());
    return u;
  }

  uint32_t dimension() const { return dimension_; }
  void setDimension(uint32_t dimension) { dimension_ = dimension; }

  // An independent stream for a variable number of draws (a subsurface random walk), keyed by
  // this sample and tag: not stratified, and it leaves this sampler's dimension unchanged.
  PixelSampler independentStream(uint32_t tag) const {
    PixelSampler stream = *this;
    stream.kind_ = SamplerKind::Independent;
    stream.sampleKey_ = hashCombine(sampleKey_, 0x5eed0000ull + tag);
    stream.dimension_ = 0;
    return stream;
  }

 private:
  // The next `count` (1, 2 or 4) dimensions as one block.
  void draw(int count, float* u) {
    const uint32_t first = dimension_;
    dimension_ += uint32_t(count);
    if (kind_ == SamplerKind::Independent) {
      for (int i = 0; i < count; ++i) u[i] = uint64ToUnitFloat(hashCombine(sampleKey_, first + uint32_t(i)));
      return;
    }
    // One hash per block: its low half shuffles the index, mixes of it scramble each dimension.
    const uint64_t hash = hashCombine(pixelKey_, first);
    const uint32_t index = order_ == SampleOrder::Progressive
                               ? progressiveElement(sampleIndex_, samplesPerPixel_, uint32_t(hash))
                               : permutationElement(sampleIndex_, samplesPerPixel_, uint32_t(hash));
    uint64_t scramble = hash;
    for (int i = 0; i < count; ++i) {
      scramble = mix64(scramble);
      // owenScramble(sobolSample(index, i), seed) with the first reversal folded into the table.
      const uint32_t scrambled = owenScrambleReversed(sobolSampleReversed(index, i), uint32_t(scramble >> 32));
      u[i] = fractionBitsToUnitFloat(reverseBits32(scrambled));
    }
  }

  SamplerKind kind_;
  SampleOrder order_;
  uint64_t pixelKey_;
  uint64_t sampleKey_;
  uint32_t sampleIndex_;
  uint32_t samplesPerPixel_;
  uint32_t dimension_ = 0;
};

}  // namespace lacrima
