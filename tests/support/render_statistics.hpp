#pragma once
// Helpers for statistical render tests: mean and standard error of pixel values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lacrima/renderer/film.hpp"

namespace lacrima::test {

// The film's RGB layer whose channels are "<name>.R/G/B" (a light path's, a light group's layer).
inline const FilmLayer& rgbLayer(const Film& film, const std::string& name) {
  for (const FilmLayer& layer : film.layers)
    if (layer.channels.front() == name + ".R") return layer;
  ADD_FAILURE() << "no layer " << name;
  return film.layers.front();
}

// Mean of one channel of an RGB layer over its pixels.
inline double rgbLayerMean(const FilmLayer& layer, int channel) {
  double sum = 0.0;
  for (size_t i = size_t(channel); i < layer.data.size(); i += 3) sum += layer.data[i];
  return sum / double(layer.data.size() / 3);
}

struct MeanEstimate {
  double mean = 0.0;
  double standardError = 0.0;
  size_t count = 0;
};

// Mean of one channel over the pixels of `film`; pixels are independent estimates (each an
// average of spp samples), so the standard error is the pixel standard deviation / sqrt(n).
inline MeanEstimate channelMean(const Film& film, int channel) {
  MeanEstimate e;
  const size_t n = size_t(film.width) * film.height;
  double sum = 0.0, sum2 = 0.0;
  for (size_t p = 0; p < n; ++p) {
    const double v = film.rgba[4 * p + channel];
    sum += v;
    sum2 += v * v;
  }
  e.count = n;
  e.mean = sum / double(n);
  const double variance = std::max(0.0, sum2 / double(n) - e.mean * e.mean) * double(n) / double(n - 1);
  e.standardError = std::sqrt(variance / double(n));
  return e;
}

}  // namespace lacrima::test
