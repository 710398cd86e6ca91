// The `priority` key of dielectric materials (nested dielectrics, docs/shot-format.md).
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace material_priority_test {

using test::expectSingleError;
using test::writeShot;

std::string shotWithMaterials(const std::string& materials) {
  return "{\n  \"version\": 1,\n  \"frames\": {\"start\": 1, \"end\": 1, \"fps\": 24},\n"
         "  \"output\": \"out.####.exr\",\n  \"render\": {\"width\": 8, \"height\": 8, \"spp\": 1},\n"
         "  \"camera\": {\"position\": [0, 0, 3], \"lookAt\": [0, 0, 0], \"fov\": 30},\n"
         "  \"materials\": {" + materials + "},\n"
         "  \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 0.5, \"material\": \"cornea\"}]\n}\n";
}

TEST(MaterialPriority, IsReadForWaterAndRoughDielectricsAndDefaultsToZero) {
  const Shot shot = loadShot(writeShot("priority.json", shotWithMaterials(
      R"("cornea": {"type": "water", "ior": 1.376, "priority": 2}, "film": {"type": "rough_dielectric", "priority": 1},)"
      R"( "drop": {"type": "water"})")));
  ASSERT_EQ(shot.materials.size(), 3u);
  EXPECT_EQ(std::get<SmoothDielectricParams>(shot.materials[0].params).priority, 2);
  EXPECT_EQ(std::get<RoughDielectricParams>(shot.materials[1].params).priority, 1);
  EXPECT_EQ(std::get<SmoothDielectricParams>(shot.materials[2].params).priority, 0);
}

TEST(MaterialPriority, MustBeANonNegativeInteger) {
  expectSingleError("priority_negative.json", shotWithMaterials(R"("cornea": {"type": "water", "priority": -1})"),
                    "/materials/cornea/priority: expected an integer in [0, 1000], found -1");
  expectSingleError("priority_fraction.json", shotWithMaterials(R"("cornea": {"type": "water", "priority": 1.5})"),
                    "/materials/cornea/priority: expected an integer in [0, 1000], found 1.5");
}

TEST(MaterialPriority, IsNotAKeyOfOpaqueMaterials) {
  expectSingleError("priority_diffuse.json", shotWithMaterials(R"("cornea": {"type": "diffuse", "priority": 1})"),
                    "/materials/cornea/priority: unknown key 'priority' (allowed here: type, albedo, emission, textures)");
}

}  // namespace material_priority_test
}  // namespace lacrima
