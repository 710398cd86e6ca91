// The wandering edge of a liquid tear's wet trail; see film_edge_variation.hpp.
#include "resolve/film_edge_variation.hpp"

#include <algorithm>
#include <cstdint>

#include "lacrima/base/gradient_noise.hpp"

namespace lacrima::shotfile {

std::vector<float> filmEdgeVariation(const TriangleMesh& skinAtFirstFrame) {
  std::vector<float> variation(skinAtFirstFrame.positions.size());
  // A fixed seed: the pattern is a property of the skin, the same in every shot.
  constexpr uint64_t kSeed = 0x7ea5f11e;
  for (size_t v = 0; v < variation.size(); ++v)
    variation[v] = std::clamp(
        kFilmEdgeContrast * fractalGradientNoise(skinAtFirstFrame.positions[v] / kFilmEdgeFeatureSize, kFilmEdgeOctaves, kSeed),
        -1.0f, 1.0f);
  return variation;
}

}  // namespace lacrima::shotfile
