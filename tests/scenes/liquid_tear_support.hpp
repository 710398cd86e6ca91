#pragma once
// Shared by the liquid-tear shot tests: the bead meshes of a frame and the skin its tear lies on.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lacrima/scenes/shot.hpp"

namespace lacrima::test {

// The frame's "liquid bead" meshes, in frame order.
inline std::vector<const MeshInstance*> beadsOf(const Frame& frame) {
  std::vector<const MeshInstance*> beads;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == "liquid bead") beads.push_back(&m);
  return beads;
}

// The skin the shot's first liquid tear lies on, as rendered in the frame.
inline const TriangleMesh& skinOf(const Frame& frame, const Shot& shot) {
  const std::string name = "face/" + shot.assets[0].gltf->primitives[shot.liquidTears[0].sourcePoint.primitive].name;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == name) return m.mesh;
  ADD_FAILURE() << "no mesh " << name;
  return frame.meshes.front().mesh;
}

}  // namespace lacrima::test
