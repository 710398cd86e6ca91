// extractSkinPatch (flesh_volume.hpp): selected triangles -> a patch with a clean border.
#include <unordered_map>

#include "lacrima/flesh/flesh_volume.hpp"

namespace lacrima::flesh {

namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) { return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a; }

// Leaves out, once, every kept triangle that touches a vertex where the border pinches (more than
// two border edges: two pieces meeting at a corner); true when any was.
bool dropBorderDefects(const std::vector<std::array<uint32_t, 3>>& triangles, std::vector<bool>& keep) {
  std::unordered_map<uint64_t, int> edgeUse;
  for (size_t t = 0; t < triangles.size(); ++t)
    if (keep[t])
      for (int e = 0; e < 3; ++e) ++edgeUse[edgeKey(triangles[t][e], triangles[t][(e + 1) % 3])];
  std::unordered_map<uint32_t, int> borderEdgesAt;
  for (const auto& [key, uses] : edgeUse)
    if (uses == 1) ++borderEdgesAt[uint32_t(key >> 32)], ++borderEdgesAt[uint32_t(key & 0xffffffffu)];
  std::vector<size_t> drop;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!keep[t]) continue;
    bool pinched = false;
    for (int e = 0; e < 3; ++e) {
      const auto it = borderEdgesAt.find(triangles[t][e]);
      pinched = pinched || (it != borderEdgesAt.end() && it->second > 2);
    }
    if (pinched) drop.push_back(t);
  }
  for (size_t t : drop) keep[t] = false;
  return !drop.empty();
}

}  // namespace

SkinPatch extractSkinPatch(const std::vector<Vec3d>& positions, const std::vector<Vec3d>& normals,
                           const std::vector<std::array<uint32_t, 3>>& triangles, const std::vector<bool>& selected) {
  std::vector<bool> keep = selected;
  keep.resize(triangles.size(), false);
  for (int pass = 0; pass < 64 && dropBorderDefects(triangles, keep); ++pass) {
  }
  SkinPatch patch;
  std::unordered_map<uint32_t, int> patchVertex;
  for (size_t t = 0; t < triangles.size(); ++t) {
    if (!keep[t]) continue;
    std::array<int, 3> corners{};
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = triangles[t][c];
      auto [it, added] = patchVertex.try_emplace(v, int(patch.positions.size()));
      if (added) {
        patch.positions.push_back(positions.at(v));
        patch.normals.push_back(normals.at(v).normalized());
        patch.skinVertex.push_back(v);
      }
      corners[c] = it->second;
    }
    patch.triangles.push_back(corners);
    patch.skinTriangle.push_back(uint32_t(t));
  }
  return patch;
}

}  // namespace lacrima::flesh
