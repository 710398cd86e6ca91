#pragma once
// Flood scenarios: Schaffer et al. 2020's river-crossing experiments (crowd/flood.hpp) as JSON
// files (docs/crowd.md "Scenario files"): the field, the river, the coupling and the crowds with
// their agents, goals and endurance over time. `lacrima flood` runs them; scenes/floods/ holds the
// experiments of Schaffer et al. 2020.
#include <filesystem>
#include <string>
#include <vector>

#include "lacrima/crowd/flood.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

struct FloodScenario {
  std::string name;               // the file's stem: its outputs are named after it
  crowd::FloodParams params;
  double duration = 300.0;        // simulated seconds at most
  std::vector<std::string> labels;  // per crowd, how the table names its run
  // Per crowd, the figure its agents are drawn as in rendered scenes: the crowd's `figure` glTF
  // file, all its primitives in one mesh (feet at y = 0, facing +z, metres), or no triangles for
  // the built-in articulated figure (crowd/figure.hpp).
  std::vector<TriangleMesh> figures;
};

// Reads and checks a flood scenario file. Throws ShotError (lacrima/scenes/shot.hpp) listing every
// problem at its JSON path, with line and column.
FloodScenario loadFloodScenario(const std::filesystem::path& path);

}  // namespace lacrima
