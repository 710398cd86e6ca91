#pragma once
// Resolving a shot's shedding tears at load: snapping the written path to the skin and
// extracting the rest skin's region around it (see ShotSheddingTear).
#include <string>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// A problem with a shedding tear found while resolving it, at a JSON pointer of the shot file.
struct SheddingTearProblem {
  std::string pointer;
  std::string message;
};

// Farthest a written path point may be from the skin: farther is taken for a typo.
inline constexpr float kMaxPathPointDistance = 0.01f;  // metres
// Most grid points a tear may have at its full length (its noise smoothing costs their square).
inline constexpr double kMaxSheddingTearGridPoints = 50000.0;

// For every shedding tear: the part is posed at the shot's first frame (the rest skin), each path
// point snapped to its nearest surface point, all on one primitive; the region of that primitive
// within reach of the strip is extracted and the path expressed on it; the strip is then built once
// at its full length to check that the path runs over the skin. Returns the problems found.
std::vector<SheddingTearProblem> resolveSheddingTears(Shot& shot);

}  // namespace lacrima::shotfile
