#pragma once
// The meshes and spheres of a shot's liquid tears in a frame (buildFrame's part; see ShotLiquidTear).
#include <vector>

#include "lacrima/scenes/shot.hpp"

namespace lacrima::shotfile {

// Gap between the skin and a bead's flat side: keeps the water off the skin it rides on.
inline constexpr float kLiquidBeadBaseOffset = 2e-5f;  // metres

// Adds the tear's beads ("liquid bead" meshes on the posed skin `open`, and on `close` at shutter
// close when given) and its falling drops (spheres, centerAtClose at shutter close) at the frame
// whose shutter opens at frame `open` and closes at `close` (fractional frames; equal: no blur).
// openSkin / closeSkin: the asset's posed primitives (closeSkin null or empty: as at open).
// skinMesh: the index in frame.meshes of the primitive the tear runs over (-1: not rendered); its
// wetness gets the tear's wet trail at shutter open (liquid_tear_film.hpp).
void addLiquidTear(const Shot& shot, const ShotLiquidTear& tear, double shutterOpen, double shutterClose,
                   const std::vector<TriangleMesh>& openSkin, const std::vector<TriangleMesh>* closeSkin, int skinMesh,
                   Frame& frame);

}  // namespace lacrima::shotfile
