#pragma once
// Resolving a shot's eyes at load: the eyeball shell and lash cards analysed on the asset posed at
// the shot's first frame; the shell and cards are then hidden (the eye and lashes replace them).
#include <string>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// A problem with an eye found while resolving it, at a JSON pointer of the shot file.
struct EyeProblem {
  std::string pointer;
  std::string message;
};

// Lash strips belong to an eye when their centroid lies within this many eyeball radii of its centre.
inline constexpr float kLashReachInEyeRadii = 2.0f;

std::vector<EyeProblem> resolveEyes(Shot& shot);

}  // namespace lacrima::shotfile
