// loadShot's phases run one by one (scenes/src/shot_loader.cpp): reading the description opens no
// file and records what it names; loading opens the files; binding checks the names used inside
// them. Each phase's problems are reported at the JSON pointer of the value that caused them.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "load/shot_binding.hpp"
#include "load/shot_files.hpp"
#include "read/shot_reader.hpp"
#include "read/text_file.hpp"
#include "shot_support.hpp"
#include "support/test_directory.hpp"

namespace lacrima {
namespace shot_phases_test {

using shotfile::Checker;
using shotfile::ShotUses;

// A shot file read into `shot` and `uses`, with the checker that collected the reading's problems.
struct ReadShot {
  shotfile::ParsedJsonFile parsed;
  Shot shot;
  ShotUses uses;
  Checker checker;

  explicit ReadShot(const std::filesystem::path& path)
      : parsed(shotfile::readJsonFile(path, "the shot file")), checker(path, parsed.source) {
    shot.path = path;
    shotfile::ShotReader(checker, shot, uses).read(parsed.json);
  }

  // "pointer: message" of every problem so far, in file order.
  std::vector<std::string> problems() const {
    std::vector<std::string> out;
    for (const Diagnostic& d : checker.diagnostics()) out.push_back(d.jsonPath + ": " + test::firstLineOf(d.message));
    return out;
  }
};

// An asset of one primitive (part "skin", glTF material "skinMat", one triangle with uvs), one
// blendshape "smile" and one camera "closeup", one metre in front of the asset's origin.
std::shared_ptr<const GltfAsset> smallAsset(const std::filesystem::path& path) {
  auto asset = std::make_shared<GltfAsset>();
  asset->path = path;
  GltfPrimitive p;
  p.name = "mesh/skin";
  p.part = "skin";
  p.material.name = "skinMat";
  p.mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  p.mesh.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  p.mesh.indices = {0, 1, 2};
  asset->primitives.push_back(p);
  asset->targetNames = {"smile"};
  GltfCamera camera;
  camera.name = "closeup";
  camera.cameraToAsset.translation() = Vec3(0, 0, 1);
  asset->cameras.push_back(camera);
  return asset;
}

// A file "small.glb" in the test's folder `folder`, there to be found: the tests' loaders hand out
// smallAsset and never parse it. Its path.
std::string placeholderGlb(const std::string& folder) {
  const std::filesystem::path file = test::testDirectory(folder) / "small.glb";
  std::ofstream(file) << "handed to the test's loader, never parsed";
  return file.string();
}

const std::string kHead = R"({
  "version": 1,
  "frames": {"start": 1, "end": 1},
  "output": "out.####.exr",
  "render": {"width": 8, "height": 8, "spp": 1},
)";

TEST(ShotPhases, ReadingOpensNoFileAndRecordsEachWithTheValueThatNamesIt) {
  const auto path = test::writeShot("phases_missing.json", kHead + R"(
  "colorConfig": "missing.ocio",
  "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30},
  "materials": {"skin": {"type": "diffuse", "textures": {"albedo": "missing.png"}}},
  "assets": [{"name": "face", "file": "missing.glb", "blendshapes": {"smyle": 0.5}, "hide": ["nose"]}],
  "environment": {"file": "missing.exr"},
  "details": [{"pattern": "cheek", "asset": "face", "part": "skn", "center": {"landmark": 3},
               "extent": [0.01, 0.008], "scale": 0.0005, "startFrame": 1, "endFrame": 1}]
})");
  ReadShot read(path);
  EXPECT_EQ(read.problems(), std::vector<std::string>{}) << "no file is opened, no name inside one is checked";
  ASSERT_TRUE(read.uses.colorConfig && read.uses.environmentMap);
  EXPECT_EQ(read.uses.colorConfig->pointer, "/colorConfig");
  EXPECT_EQ(read.uses.environmentMap->pointer, "/environment/file");
  ASSERT_EQ(read.uses.textureImages.size(), 1u);
  EXPECT_EQ(read.uses.textureImages[0].pointer, "/materials/skin/textures/albedo");
  ASSERT_EQ(read.uses.assets.size(), 1u);
  ASSERT_TRUE(read.uses.assets[0].file);
  EXPECT_EQ(read.uses.assets[0].file->pointer, "/assets/0/file");
  EXPECT_EQ(read.uses.assets[0].file->resolved, path.parent_path() / "missing.glb");
  ASSERT_EQ(read.uses.assets[0].blendshapes.size(), 1u);
  EXPECT_EQ(read.uses.assets[0].blendshapes[0].pointer, "/assets/0/blendshapes/smyle");
  ASSERT_EQ(read.uses.parts.size(), 1u);
  EXPECT_EQ(read.uses.parts[0].pointer, "/details/0/part");
  ASSERT_EQ(read.uses.anchors.size(), 1u);
  EXPECT_EQ(read.uses.anchors[0].pointer, "/details/0/center");

  bool loaderCalled = false;
  shotfile::loadShotFiles(read.uses, read.shot, read.checker, [&](const std::filesystem::path& file) {
    loaderCalled = true;
    return smallAsset(file);
  });
  EXPECT_FALSE(loaderCalled) << "a file that is not there is not handed to the glTF loader";
  const std::vector<std::string> missing = {
      "/colorConfig: file not found: 'missing.ocio' (resolved to '" + (path.parent_path() / "missing.ocio").string() + "')",
      "/materials/skin/textures/albedo: file not found: 'missing.png' (resolved to '" +
          (path.parent_path() / "missing.png").string() + "')",
      "/assets/0/file: file not found: 'missing.glb' (resolved to '" + (path.parent_path() / "missing.glb").string() + "')",
      "/environment/file: file not found: 'missing.exr' (resolved to '" +
          (path.parent_path() / "missing.exr").string() + "')"};
  EXPECT_EQ(read.problems(), missing);

  shotfile::bindShotUses(read.uses, read.shot, read.checker);
  EXPECT_EQ(read.problems(), missing) << "nothing is checked against an asset that did not load";
}

TEST(ShotPhases, BindingChecksTheNamesUsedInsideTheLoadedAssetAndDerivesWhatFollows) {
  const std::string file = placeholderGlb("phases");
  const auto shotText = [&](const std::string& blendshape, const std::string& hide, const std::string& part,
                            const std::string& camera) {
    return kHead + R"(
  "camera": {"gltf": {"asset": "small", "camera": ")" + camera + R"("}, "fov": 40},
  "materials": {"skin": {"type": "diffuse"}},
  "assets": [{"file": ")" + file + R"(", "materials": {"skinMat": "skin"},
              "blendshapes": {")" + blendshape + R"(": 0.5}, "hide": [")" + hide + R"("]}],
  "details": [{"pattern": "cheek", "asset": "small", "part": ")" + part + R"(", "center": {"vertex": 1},
               "extent": [0.01, 0.008], "scale": 0.0005, "startFrame": 1, "endFrame": 1}]
})";
  };
  const GltfAssetLoader loader = [](const std::filesystem::path& file) { return smallAsset(file); };

  ReadShot bad(test::writeShot("phases_bad_names.json", shotText("smyle", "skn", "skim", "close")));
  shotfile::loadShotFiles(bad.uses, bad.shot, bad.checker, loader);
  EXPECT_EQ(bad.problems(), std::vector<std::string>{}) << "every name is checked only once the asset is loaded";
  shotfile::bindShotUses(bad.uses, bad.shot, bad.checker);
  EXPECT_EQ(bad.problems(), (std::vector<std::string>{
                                "/camera/gltf/camera: asset 'small' has no camera 'close'; did you mean 'closeup'?",
                                "/assets/0/blendshapes/smyle: unknown blendshape 'smyle'; did you mean 'smile'?",
                                "/assets/0/hide/0: asset 'small' has no part or material named 'skn'; did you mean "
                                "'skin'?",
                                "/details/0/part: asset 'small' has no part 'skim'; did you mean 'skin'?"}));

  ReadShot good(test::writeShot("phases_good_names.json", shotText("smile", "mesh/skin", "skin", "closeup")));
  shotfile::loadShotFiles(good.uses, good.shot, good.checker, loader);
  shotfile::bindShotUses(good.uses, good.shot, good.checker);
  EXPECT_EQ(good.problems(), std::vector<std::string>{});
  const ShotAsset& asset = good.shot.assets.at(0);
  EXPECT_EQ(asset.weights, std::vector<float>{0.5f}) << "the weights are indexed like the asset's blendshapes";
  EXPECT_EQ(asset.primitiveMaterials, std::vector<int>{-1}) << "the hidden primitive has no material";
  EXPECT_EQ(good.shot.camera.camera.cameraToWorld.translation(), Vec3(0, 0, 1)) << "the glTF camera's place";
  EXPECT_NEAR(good.shot.camera.camera.verticalFovRadians, degreesToRadians(40.0f), 1e-7f);
}

TEST(ShotPhases, AFileNamedByTwoAssetsIsLoadedOnceAndShared) {
  const std::string file = placeholderGlb("phases_shared");
  ReadShot read(test::writeShot("phases_shared.json", kHead + R"(
  "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30},
  "assets": [{"name": "left", "file": ")" + file + R"("},
             {"name": "right", "file": ")" + file + R"(", "transform": {"translate": [1, 0, 0]}}]
})"));
  int loads = 0;
  shotfile::loadShotFiles(read.uses, read.shot, read.checker, [&](const std::filesystem::path& path) {
    ++loads;
    return smallAsset(path);
  });
  shotfile::bindShotUses(read.uses, read.shot, read.checker);
  EXPECT_EQ(read.problems(), std::vector<std::string>{});
  EXPECT_EQ(loads, 1);
  ASSERT_EQ(read.shot.assets.size(), 2u);
  EXPECT_EQ(read.shot.assets[0].gltf, read.shot.assets[1].gltf);
  EXPECT_EQ(read.shot.assets[1].transform.translate, Vec3(1, 0, 0)) << "each asset keeps its own placement";
}

TEST(ShotPhases, AFileThatFailsToLoadIsReportedForEveryAssetNamingIt) {
  const auto dir = test::testDirectory("phases_shared_bad");
  std::ofstream(dir / "bad.glb") << "not a glTF file";
  const std::string file = (dir / "bad.glb").string();
  ReadShot read(test::writeShot("phases_shared_bad.json", kHead + R"(
  "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30},
  "assets": [{"name": "left", "file": ")" + file + R"("}, {"name": "right", "file": ")" + file + R"("}]
})"));
  int loads = 0;
  shotfile::loadShotFiles(read.uses, read.shot, read.checker,
                          [&](const std::filesystem::path&) -> std::shared_ptr<const GltfAsset> {
                            ++loads;
                            throw InputError("truncated");
                          });
  EXPECT_EQ(loads, 1);
  EXPECT_EQ(read.problems(), (std::vector<std::string>{"/assets/0/file: cannot load the glTF asset: truncated",
                                                        "/assets/1/file: cannot load the glTF asset: truncated"}));
}

TEST(ShotPhases, WarningsAreInFileOrderWhicheverPhaseFoundThem) {
  // The asset's warning is found by the loading phase, after the reading phase's warning about the
  // camera below it.
  const std::string file = placeholderGlb("phases_warnings");
  const auto path = test::writeShot("phases_warnings.json", kHead + R"(
  "assets": [{"file": ")" + file + R"("}],
  "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "focus": "surface"}
})");
  const Shot shot = loadShot(path, [](const std::filesystem::path& file) {
    auto asset = std::make_shared<GltfAsset>(*smallAsset(file));
    asset->warnings.push_back("a caveat of the loader");
    return std::shared_ptr<const GltfAsset>(asset);
  });
  ASSERT_EQ(shot.warnings.size(), 2u);
  EXPECT_EQ(shot.warnings[0].jsonPath, "/assets/0/file");
  EXPECT_EQ(shot.warnings[1].jsonPath, "/camera/focus");
}

}  // namespace shot_phases_test
}  // namespace lacrima
