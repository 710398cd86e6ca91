#pragma once
// A small skinned glTF for tests (spec 3.7.3): a two-bone chain and a strip weighted between them.
//   node 0 "hip"   translation (1, 0, 0), children [1]            joint 0, IBM T(0, 1, 0)
//   node 1 "knee"  translation (0, 2, 0) (rest world T(1, 2, 0))  joint 1, IBM T(0, -2, 0)
//   node 2 "strip" translation (5, 5, 5) (ignored: skinned), mesh 0, skin 0
// Mesh "Strip", mesh space: rows y = 0, 2, 4 of x = 0, 1 (vertices 0-5, row by row); row 0 is
// weighted fully to the hip, row 1 half/half, row 2 fully to the knee. Target "lift" moves
// vertex 4 by (1, 0, 0) in mesh space.
// Rest joint matrices: hip T(1,0,0) T(0,1,0) = T(1,1,0); knee T(1,2,0) T(0,-2,0) = T(1,0,0); so
// the rest positions are row 0 + (1,1,0), row 1 + (1,0.5,0), row 2 + (1,0,0).
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/gltf_builder_support.hpp"

namespace lacrima::test {

struct SkinnedStripOptions {
  std::vector<uint8_t> joints = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  // Weights as written (not normalized: row 1 is 1/1, normalized by the loader to 0.5/0.5).
  std::vector<float> weights = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  size_t inverseBindMatrices = 2;  // how many to write (the skin has 2 joints)
  bool withAnimation = true;
  bool mirrorX = false;  // both inverse bind matrices also mirror x (scale (-1, 1, 1) applied first)
};

inline GltfBuilder skinnedStrip(const SkinnedStripOptions& o = {}) {
  GltfBuilder b;
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 2, 0, 1, 2, 0, 0, 4, 0, 1, 4, 0};
  std::vector<float> lift(18, 0.0f);
  lift[12] = 1.0f;  // vertex 4: +x
  const int mesh = b.addMesh("Strip", positions, {"lift"}, {lift});
  nlohmann::json& primitive = b.json()["meshes"][size_t(mesh)]["primitives"][0];
  primitive["indices"] = b.addAccessorOf(std::vector<uint16_t>{0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4}, 5123, "SCALAR");
  primitive["attributes"]["JOINTS_0"] = b.addAccessorOf(o.joints, 5121, "VEC4");
  primitive["attributes"]["WEIGHTS_0"] = b.addAccessor(o.weights, "VEC4");
  // Column-major 4x4 translations.
  const float sx = o.mirrorX ? -1.0f : 1.0f;
  const auto translation = [sx](float x, float y, float z) {
    return std::vector<float>{sx, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1};
  };
  std::vector<float> ibm = translation(0, 1, 0);
  const std::vector<float> knee = translation(0, -2, 0);
  ibm.insert(ibm.end(), knee.begin(), knee.end());
  ibm.resize(16 * o.inverseBindMatrices, 0.0f);
  b.json()["skins"] = {{{"name", "legs"}, {"joints", {0, 1}}, {"inverseBindMatrices", b.addAccessorOf(ibm, 5126, "MAT4")}}};
  b.json()["scenes"] = {{{"nodes", {0, 2}}}};
  b.json()["nodes"] = {{{"name", "hip"}, {"translation", {1, 0, 0}}, {"children", {1}}},
                       {{"name", "knee"}, {"translation", {0, 2, 0}}},
                       {{"name", "strip"}, {"translation", {5, 5, 5}}, {"mesh", mesh}, {"skin", 0}}};
  if (o.withAnimation) {
    // "bend": over 1 s the knee turns 0 -> 90 degrees about +Z, "lift" goes 0 -> 1, and the
    // strip's own node slides (ignored: a skinned mesh does not follow its node).
    const float s = 0.70710678f;
    const int bend = b.addAnimation("bend");
    b.addChannel(bend, 1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, s, s}, "VEC4");
    b.addChannel(bend, 2, "translation", {0, 1}, {5, 5, 5, 9, 9, 9}, "VEC3");
    const int lift = b.addAnimation("lift");
    b.addChannel(lift, 1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, s, s}, "VEC4");
    b.addChannel(lift, 2, "weights", {0, 1}, {0, 1}, "SCALAR");
  }
  return b;
}

}  // namespace lacrima::test
