// Eyes in shots ("eyes", issue "Skin and eyes that hold up in a close-up"): the eyeball shell and
// lash cards replaced by cornea, sclera, iris, pupil and lash tubes that follow the posed face
// (a blink, motion blur), and exact messages for bad input.
#include <gtest/gtest.h>

#include "lacrima/mesh/surface_point.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace eye_shot_test {

using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;

const std::string kMaterials =
    R"("cornea": {"type": "water", "ior": 1.376}, "sclera": {"type": "skin", "albedo": [0.8, 0.76, 0.72]},
       "iris": {"type": "diffuse", "albedo": [0.13, 0.075, 0.04]}, "pupil": {"type": "diffuse", "albedo": [0.01, 0.01, 0.01]},
       "lash": {"type": "skin", "albedo": [0.02, 0.015, 0.012]})";
const std::string kEye =
    R"("eyes": [{"asset": "face", "part": "M_ScleraRight", "cornea": "cornea", "sclera": "sclera", "iris": "iris",
       "pupil": "pupil", "limbusRadius": 5.9, "pupilRadius": 2, "irisDepth": 2.6,
       "lashes": {"part": "M_EyeLashes", "material": "lash", "upper": 80, "lower": 40, "seed": 3}}])";
// The right eye blinks shut at frame 3.
const std::string kBlink = R"("rig": {"preset": "ict"}, "blendshapes": {"eyeBlink_R": {"keys": [[1, 0], [3, 1]]}})";

std::string eyeShot(const std::string& from = "", const std::string& to = "", const std::string& asset = kBlink) {
  std::string text = ictFaceShot(from.empty() ? kEye : test::replaced(kEye, from, to), "", asset);
  return test::replaced(text, R"("water": {"type": "water"})", R"("water": {"type": "water"}, )" + kMaterials);
}

using test::findMesh;

TEST(EyeShot, ReplacesTheShellAndCardsWithCorneaScleraIrisPupilAndLashes) {
  const Shot shot = loadShot(writeShot("eye.json", eyeShot()));
  ASSERT_EQ(shot.eyes.size(), 1u);
  const ShotEye& eye = shot.eyes[0];
  EXPECT_FLOAT_EQ(eye.params.limbusRadius, 5.9e-3f);
  EXPECT_FLOAT_EQ(eye.params.irisDepth, 2.6e-3f);
  ASSERT_TRUE(eye.lashes);
  EXPECT_EQ(eye.lashes->lashes.size(), 120u);
  EXPECT_EQ(shot.assets[0].primitiveMaterials[eye.primitive], -1);
  EXPECT_EQ(shot.assets[0].primitiveMaterials[eye.lashes->primitive], -1);
  const Frame frame = buildFrame(shot, 1);
  for (const char* piece : {"cornea", "sclera", "iris", "pupil", "lashes"}) {
    const MeshInstance* mesh = findMesh(frame, std::string("face/M_ScleraRight/") + piece);
    ASSERT_NE(mesh, nullptr) << piece;
    EXPECT_EQ(findMeshDefect(mesh->mesh), "") << piece;
  }
  EXPECT_EQ(findClosedMeshDefect(findMesh(frame, "face/M_ScleraRight/cornea")->mesh), "");
  EXPECT_EQ(findMesh(frame, "face/M_ScleraRight/cornea")->materialId, uint32_t(shot.findMaterial("cornea")));
  EXPECT_EQ(findMesh(frame, "face/M_ScleraRight/lashes")->materialId, uint32_t(shot.findMaterial("lash")));
  EXPECT_EQ(findMesh(frame, "face/M_ScleraRight"), nullptr);  // the shell itself is not rendered
  EXPECT_EQ(findMesh(frame, "face/M_EyeLashes"), nullptr);
}

TEST(EyeShot, LashesFollowTheBlinkAndBlurWithIt) {
  std::string text = eyeShot();
  text = test::replaced(text, R"("fov": 30)", R"("fov": 30, "shutter": {"open": -0.25, "close": 0.25})");
  const Shot shot = loadShot(writeShot("eye_blink.json", text));
  const Frame open = buildFrame(shot, 1), closing = buildFrame(shot, 2);
  const MeshInstance& a = *findMesh(open, "face/M_ScleraRight/lashes");
  const MeshInstance& b = *findMesh(closing, "face/M_ScleraRight/lashes");
  ASSERT_EQ(a.mesh.positions.size(), b.mesh.positions.size());
  float meanDrop = 0.0f;
  for (size_t i = 0; i < a.mesh.positions.size(); ++i) meanDrop += a.mesh.positions[i].y() - b.mesh.positions[i].y();
  meanDrop /= float(a.mesh.positions.size());
  EXPECT_GT(meanDrop, 1e-3f);  // half a blink: the lashes come down with the lid
  // Within the shutter the lid moves: the lashes carry their shutter-close vertices.
  EXPECT_EQ(b.positionsAtClose.size(), b.mesh.positions.size());
  // The eyeball does not move with a blink: cornea and iris stay put.
  EXPECT_EQ(findMesh(open, "face/M_ScleraRight/iris")->mesh.positions,
            findMesh(closing, "face/M_ScleraRight/iris")->mesh.positions);
}

TEST(EyeShot, BadKeysGiveExactMessages) {
  auto expect = [](const std::string& name, const std::string& from, const std::string& to, const std::string& message) {
    expectSingleError(name, eyeShot(from, to), message);
  };
  expect("eye_part.json", R"("part": "M_ScleraRight")", R"("part": "M_ScleraRigth")",
         "/eyes/0/part: asset 'face' has no part 'M_ScleraRigth'; did you mean 'M_ScleraRight'?");
  expect("eye_cornea.json", R"("cornea": "cornea")", R"("cornea": "sclera")",
         "/eyes/0/cornea: the cornea material 'sclera' must be clear: of type 'water' or 'rough_dielectric'");
  expect("eye_pupil.json", R"("pupil": "pupil", )", "",
         "/eyes/0: missing required key 'pupil' (the name of a material in 'materials')");
  expect("eye_iris.json", R"("iris": "iris")", R"("iris": "irsi")",
         "/eyes/0/iris: undefined material 'irsi'; did you mean 'iris'?");
  expect("eye_limbus.json", R"("limbusRadius": 5.9)", R"("limbusRadius": 15)",
         "/eyes/0/limbusRadius: expected a number in [2, 12], found 15");
  expect("eye_depth.json", R"("irisDepth": 2.6)", R"("irisDepth": 6)",
         "/eyes/0/part: part 'M_ScleraRight': the pupil lies behind the chamber's back; reduce irisDepth (6 mm)");
  expect("eye_not_shell.json", R"("part": "M_ScleraRight")", R"("part": "M_EyeLashes")",
         "/eyes/0/part: part 'M_EyeLashes': no triangle of the eyeball shell lies within the limbus (5.9 mm)");
  expect("eye_lash_part.json", R"("part": "M_EyeLashes")", R"("part": "M_Face")",
         "/eyes/0/lashes/part: part 'M_Face': lash strip 0 (6706 vertices) is not a grid of columns along the lid by "
         "rows from root to tip in its texture coordinates");
  expect("eye_lash_tip.json", R"("seed": 3)", R"("seed": 3, "tipRadius": 80)",
         "/eyes/0/lashes/tipRadius: the tip radius (80 um) must not exceed the root radius (50 um)");
  expect("eye_lash_typo.json", R"("seed": 3)", R"("seed": 3, "uper": 3)",
         "/eyes/0/lashes/uper: unknown key 'uper'; did you mean 'upper'?");
}

}  // namespace eye_shot_test
}  // namespace lacrima
