#pragma once
// The meshes and spheres of a shot's liquid tears in a frame (buildFrame's part; see ShotLiquidTear).
#include <vector>

#include "lacrima/scenes/shot.hpp"

namespace lacrima::shotfile {

// Gap between the skin and a bead's flat side: keeps the water off the skin it rides on.
inline constexpr float kLiquidBeadBaseOffset = 2e-5f;  // metres
// A falling drop whose mode-2 envelope |eps0| exp(-t / tau) is below this is drawn as an exact
// sphere: its axes then differ by under 1.5% (about 20 um on a 1.5 mm drop, below a pixel).
inline constexpr double kVisibleDropAmplitude = 0.01;

// Adds the tear's beads ("liquid bead" meshes on the posed skin `open`, and on `close` at shutter
// close when given) and its falling drops ("falling drop" spheroid meshes ringing in mode 2, their
// shape and place at shutter close as positionsAtClose; spheres with centerAtClose once the
// ringing is below kVisibleDropAmplitude) at the frame
// whose shutter opens at frame `open` and closes at `close` (fractional frames; equal: no blur).
// openSkin / closeSkin: the asset's posed primitives (closeSkin null or empty: as at open).
// skinMesh: the index in frame.meshes of the primitive the tear runs over (-1: not rendered); its
// wetness gets the tear's wet trail at shutter open (liquid_tear_film.hpp).
void addLiquidTear(const Shot& shot, const ShotLiquidTear& tear, double shutterOpen, double shutterClose,
                   const std::vector<TriangleMesh>& openSkin, const std::vector<TriangleMesh>* closeSkin, int skinMesh,
                   Frame& frame);

// Thickens the tear's lacrimal fluid strip (tear.meniscusPrimitive of `posed`, the asset's primitives
// posed at `frame`) by the meniscus volume simulated at that (fractional) frame (swellMeniscus with
// tear.meniscusWeights). Nothing happens without a strip, without posed primitives, or at volume 0.
void swellLiquidTearMeniscus(const Shot& shot, const ShotLiquidTear& tear, double frame,
                             std::vector<TriangleMesh>& posed);

}  // namespace lacrima::shotfile
