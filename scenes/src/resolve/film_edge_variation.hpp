#pragma once
// The wandering edge of a liquid tear's wet trail (frame/liquid_tear_film.hpp, kFilmEdgeWander): a
// fixed value per skin vertex, laid down when the tear is resolved.
#include <vector>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima::shotfile {

inline constexpr float kFilmEdgeFeatureSize = 0.0025f;  // metres
inline constexpr int kFilmEdgeOctaves = 3;
// Gradient noise clusters around 0 (a standard deviation near 0.2): stretched by this and clamped
// to [-1, 1], the edge spends much of its length near either extreme, as a pinned contact line does.
inline constexpr float kFilmEdgeContrast = 3.0f;

// v per vertex of the skin the film is laid on, as posed on the shot's first frame: a
// kFilmEdgeOctaves-octave gradient noise (gradient_noise.hpp) of the position there, so the pattern rides with the skin
// as it deforms instead of swimming over it.
std::vector<float> filmEdgeVariation(const TriangleMesh& skinAtFirstFrame);

}  // namespace lacrima::shotfile
