// `lacrima export`: the real binary writes each frame's meshes as glb or obj; the files are read
// back (glb with lacrima's own glTF loader, obj with a small parser here) and compared with
// buildFrame's meshes for the same frames, and bad input writes nothing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/mesh/shapes.hpp"
#include "lacrima/scenes/shot.hpp"
#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima {
namespace export_test {

namespace fs = std::filesystem;
using test::lacrima;
using test::filesIn;

const std::string kHint = "Run with --help for more information.\n";
const std::string kSource = LACRIMA_SOURCE_DIR;
constexpr float kTolerance = 1e-6f;

// Frames 1-3 of the ICT face with a raised cheek keyed over the frames (so frames differ), a
// dripping tear from frame 1, a keyed ellipsoid and an exact sphere. Render output out/geo.####.exr.
fs::path writeExportShot(const fs::path& dir) {
  const fs::path path = dir / "geo.json";
  std::ofstream(path) << R"({
  "version": 1,
  "frames": {"start": 1, "end": 3, "fps": 24},
  "output": "out/geo.####.exr",
  "render": {"width": 8, "height": 8, "spp": 1},
  "camera": {"position": [0, 0, 0.5], "lookAt": [0, 0, 0], "fov": 30},
  "materials": {"skin": {"type": "skin"}, "water": {"type": "water"},
                "grey": {"type": "diffuse", "albedo": [0.25, 0.5, 0.75]}},
  "assets": [{"name": "face", "file": ")" << kSource << R"(/scenes/assets/ict-face/ict_face.glb",
              "materials": {"M_Face": "skin"},
              "blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [3, 1]], "interpolation": "linear"}}}],
  "shapes": [
    {"type": "ellipsoid", "center": {"keys": [[1, [0.1, 0, 0]], [3, [0.1, 0.02, 0]]]}, "radii": [0.01, 0.02, 0.03],
     "material": "grey"},
    {"type": "sphere", "center": [-0.1, 0, 0], "radius": 0.01, "material": "water"}
  ],
  "tears": [{"type": "dripping", "asset": "face", "part": "M_Face", "start": [-0.0345, -0.0018, 0.0995],
             "startFrame": 1, "alpha": 0.0005, "beta": 0.004, "lambda": 0.1, "material": "water",
             "rings": 12, "segments": 16}]
}
)";
  return path;
}

// What the export must contain for a frame: its meshes, then its spheres as makeEllipsoid meshes
// (48 x 96, named "sphere", as documented), each with the name of its material.
struct ExpectedMesh {
  TriangleMesh mesh;
  std::string material;
};

std::vector<ExpectedMesh> expectedMeshes(const Shot& shot, int frameNumber) {
  const Frame frame = buildFrame(shot, frameNumber);
  std::vector<ExpectedMesh> out;
  for (const MeshInstance& m : frame.meshes) out.push_back({m.mesh, frame.materials[m.materialId].name});
  for (const Sphere& s : frame.spheres) {
    out.push_back({makeEllipsoid(s.center, Mat3(s.radius * Mat3::Identity()), 48, 96),
                   frame.materials[s.materialId].name});
    out.back().mesh.name = "sphere";
  }
  return out;
}

size_t triangles(const std::vector<ExpectedMesh>& meshes) {
  size_t n = 0;
  for (const ExpectedMesh& m : meshes) n += m.mesh.triangleCount();
  return n;
}

void expectSamePositions(const std::vector<Vec3>& actual, const std::vector<Vec3>& expected, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  float worst = 0.0f;
  for (size_t i = 0; i < actual.size(); ++i) worst = std::max(worst, (actual[i] - expected[i]).cwiseAbs().maxCoeff());
  EXPECT_LE(worst, kTolerance) << what;
}

// ---- glb ---------------------------------------------------------------------------------------

class ExportGlb : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::testDirectory("export", /*fresh=*/true);
    shotPath_ = writeExportShot(dir_);
    shot_ = loadShot(shotPath_);
  }
  fs::path dir_, shotPath_;
  Shot shot_;
};

TEST_F(ExportGlb, TwoFramesLoadBackAsTheFrameBuildersMeshes) {
  const auto run = lacrima({"export", shotPath_.string(), "--frames", "2-3"});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_EQ(filesIn(dir_), (std::set<std::string>{"geo.json", "out/geo.0002.glb", "out/geo.0003.glb"}))
      << "the default output is the render output with .glb, and no temporary file is left";
  std::string expectedLines;
  for (int f : {2, 3}) {
    const std::vector<ExpectedMesh> expected = expectedMeshes(shot_, f);
    const fs::path file = dir_ / fmt::format("out/geo.{:04d}.glb", f);
    expectedLines += fmt::format("frame {}: {} meshes, {} triangles -> {}\n", f, expected.size(), triangles(expected),
                                 file.string());
    const GltfAsset asset = loadGltfAsset(file);
    ASSERT_EQ(asset.primitives.size(), expected.size()) << "frame " << f;
    ASSERT_GE(expected.size(), 5u) << "face primitives, ellipsoid, tear and sphere";
    for (size_t i = 0; i < expected.size(); ++i) {
      const TriangleMesh& want = expected[i].mesh;
      const GltfPrimitive& got = asset.primitives[i];
      const std::string what = fmt::format("frame {}, mesh {} ({})", f, i, want.name);
      // The loader names a primitive "<glTF mesh name>/<material name>".
      EXPECT_EQ(got.name, want.name + "/" + expected[i].material) << what;
      EXPECT_EQ(got.material.name, expected[i].material) << what;
      EXPECT_EQ(got.mesh.triangleCount(), want.triangleCount()) << what;
      EXPECT_EQ(got.mesh.indices, want.indices) << what;
      expectSamePositions(got.mesh.positions, want.positions, what);
      EXPECT_EQ(got.mesh.uvs.size(), want.uvs.size()) << what;
    }
  }
  EXPECT_NE(run.output.find(expectedLines + "lacrima: 2 frames exported as glb in "), std::string::npos) << run.output;
}

TEST_F(ExportGlb, NamesAreUniqueAndMaterialsKeepTheirColourAndIor) {
  const fs::path file = dir_ / "one.glb";
  const auto run = lacrima({"export", shotPath_.string(), "--frames", "1", "--out", file.string()});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  const GltfAsset asset = loadGltfAsset(file);
  std::set<std::string> names;
  for (const GltfPrimitive& p : asset.primitives) EXPECT_TRUE(names.insert(p.name).second) << p.name;
  EXPECT_EQ(names.count("tear/water"), 1u);
  EXPECT_EQ(names.count("ellipsoid/grey"), 1u);
  EXPECT_EQ(names.count("sphere/water"), 1u);
  for (const GltfPrimitive& p : asset.primitives) {
    if (p.material.name == "grey") {
      EXPECT_TRUE((p.material.baseColor == Color(0.25f, 0.5f, 0.75f)).all());
      EXPECT_EQ(p.material.transmission, 0.0f);
    }
    if (p.material.name == "water") {
      EXPECT_EQ(p.material.transmission, 1.0f);
      EXPECT_FLOAT_EQ(p.material.ior, kTearIor);
    }
  }
}

TEST_F(ExportGlb, ClosedTearStaysClosedThroughTheFile) {
  const fs::path file = dir_ / "tear.glb";
  ASSERT_EQ(lacrima({"export", shotPath_.string(), "--frames", "3", "--out", file.string()}).exitStatus, 0);
  const GltfAsset asset = loadGltfAsset(file);
  const std::vector<ExpectedMesh> expected = expectedMeshes(shot_, 3);
  int closedMeshes = 0;
  for (size_t i = 0; i < expected.size() && i < asset.primitives.size(); ++i) {
    if (!findClosedMeshDefect(expected[i].mesh).empty()) continue;  // the face is open
    ++closedMeshes;
    EXPECT_EQ(findClosedMeshDefect(asset.primitives[i].mesh), "") << expected[i].mesh.name;
  }
  EXPECT_EQ(closedMeshes, 3) << "tear, ellipsoid and sphere are closed before export";
}

// ---- obj ---------------------------------------------------------------------------------------

struct ObjObject {
  std::string name, material;
  size_t firstPosition = 0;  // 0-based index of its first `v` in the file
  std::vector<Vec3> positions;
  std::vector<uint32_t> indices;  // 0-based into the whole file's positions
};

struct ObjFile {
  std::string mtllib;
  std::vector<Vec3> positions;
  size_t uvs = 0, normals = 0, faces = 0;
  std::vector<ObjObject> objects;
};

// Reads the statements lacrima writes; a corner is v, v/vt, v//vn or v/vt/vn. Every index must
// be in range of the positions, uvs and normals read so far.
ObjFile parseObj(const fs::path& path) {
  ObjFile obj;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::istringstream s(line);
    std::string keyword;
    s >> keyword;
    if (keyword == "mtllib") s >> obj.mtllib;
    if (keyword == "o") obj.objects.push_back({line.substr(2), "", obj.positions.size(), {}, {}});
    if (keyword == "usemtl" && !obj.objects.empty()) obj.objects.back().material = line.substr(7);
    if (keyword == "v") {
      Vec3 p;
      s >> p.x() >> p.y() >> p.z();
      obj.positions.push_back(p);
      if (!obj.objects.empty()) obj.objects.back().positions.push_back(p);
    }
    if (keyword == "vt") ++obj.uvs;
    if (keyword == "vn") ++obj.normals;
    if (keyword != "f") continue;
    ++obj.faces;
    int corners = 0;
    for (std::string corner; s >> corner; ++corners) {
      size_t v = 0, vt = 0, vn = 0;
      char slash;
      std::istringstream c(corner);
      c >> v;
      if (c >> slash && c.peek() != '/') c >> vt;
      if (c >> slash) c >> vn;
      EXPECT_TRUE(v >= 1 && v <= obj.positions.size()) << line;
      EXPECT_TRUE(vt == 0 || vt <= obj.uvs) << line;
      EXPECT_TRUE(vn == 0 || vn <= obj.normals) << line;
      if (!obj.objects.empty()) obj.objects.back().indices.push_back(uint32_t(v - 1));
    }
    EXPECT_EQ(corners, 3) << line;
  }
  return obj;
}

TEST(ExportObj, ParsesBackToTheFrameBuildersMeshes) {
  const fs::path dir = test::testDirectory("export", /*fresh=*/true);
  const fs::path shotPath = writeExportShot(dir);
  const Shot shot = loadShot(shotPath);
  const fs::path file = dir / "obj" / "frame.obj";  // one frame: no frame field needed
  const auto run = lacrima({"export", shotPath.string(), "--frames", "2", "--format", "obj", "--out", file.string()});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_EQ(filesIn(dir / "obj"), (std::set<std::string>{"frame.obj", "frame.mtl"}));

  const std::vector<ExpectedMesh> expected = expectedMeshes(shot, 2);
  const ObjFile obj = parseObj(file);
  EXPECT_EQ(obj.mtllib, "frame.mtl");
  size_t vertices = 0, uvs = 0, normals = 0;
  for (const ExpectedMesh& m : expected) {
    vertices += m.mesh.positions.size();
    uvs += m.mesh.uvs.size();
    normals += m.mesh.normals.size();
  }
  EXPECT_EQ(obj.positions.size(), vertices);
  EXPECT_EQ(obj.uvs, uvs);
  EXPECT_EQ(obj.normals, normals);
  EXPECT_EQ(obj.faces, triangles(expected));
  ASSERT_EQ(obj.objects.size(), expected.size());
  std::ifstream mtlStream(dir / "obj" / "frame.mtl");
  const std::string mtl((std::istreambuf_iterator<char>(mtlStream)), std::istreambuf_iterator<char>());
  for (size_t i = 0; i < expected.size(); ++i) {
    const ObjObject& got = obj.objects[i];
    const TriangleMesh& want = expected[i].mesh;
    EXPECT_EQ(got.material, expected[i].material) << want.name;
    EXPECT_NE(mtl.find("newmtl " + expected[i].material + "\n"), std::string::npos) << mtl;
    expectSamePositions(got.positions, want.positions, want.name);
    ASSERT_EQ(got.indices.size(), want.indices.size()) << want.name;
    for (size_t k = 0; k < want.indices.size(); ++k)
      ASSERT_EQ(got.indices[k], got.firstPosition + want.indices[k]) << want.name << ", corner " << k;
  }
  EXPECT_EQ(obj.objects[expected.size() - 2].name, "tear");
  EXPECT_EQ(obj.objects.back().name, "sphere");
  EXPECT_NE(mtl.find("newmtl grey\nKd 0.25 0.5 0.75\n"), std::string::npos) << mtl;
}

TEST(ExportSph, TheSurfacedLiquidIsExportedAsTheFrameBuilderSurfacesIt) {
  // A 1.5 mm SPH drop of 0.25 mm particles falling onto a card at 240 fps: frame 3 holds the card
  // and the liquid's surface ("sph 0"), closed, in its water material.
  const fs::path dir = test::testDirectory("export_sph", /*fresh=*/true);
  const fs::path shotPath = dir / "sph.json";
  std::ofstream(shotPath) << R"({
  "version": 1,
  "frames": {"start": 1, "end": 3, "fps": 240},
  "output": "out/sph.####.exr",
  "render": {"width": 8, "height": 8, "spp": 1},
  "camera": {"position": [0, 0.01, 0.03], "lookAt": [0, 0, 0], "fov": 30},
  "materials": {"card": {"type": "diffuse"}, "water": {"type": "water"}},
  "shapes": [{"type": "rectangle", "center": [0, 0, 0], "size": [0.02, 0.02], "normal": [0, 1, 0], "material": "card"}],
  "sph": [{"material": "water", "particleRadius": 0.00025, "sigma": 0.072,
           "drops": [{"center": [0, 0.0041, 0], "radius": 0.0015, "velocity": [0, -0.3, 0]}],
           "colliders": [{"shape": 0}]}]
}
)";
  const Shot shot = loadShot(shotPath);
  const fs::path file = dir / "sph.glb";
  const auto run = lacrima({"export", shotPath.string(), "--frames", "3", "--out", file.string()});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  const std::vector<ExpectedMesh> expected = expectedMeshes(shot, 3);
  const GltfAsset asset = loadGltfAsset(file);
  ASSERT_EQ(asset.primitives.size(), expected.size());
  bool sawLiquid = false;
  for (size_t i = 0; i < expected.size(); ++i) {
    const TriangleMesh& want = expected[i].mesh;
    const GltfPrimitive& got = asset.primitives[i];
    EXPECT_EQ(got.name, want.name + "/" + expected[i].material);
    EXPECT_EQ(got.mesh.indices, want.indices) << want.name;
    expectSamePositions(got.mesh.positions, want.positions, want.name);
    if (want.name != "sph 0") continue;
    sawLiquid = true;
    EXPECT_EQ(got.material.transmission, 1.0f) << "the liquid keeps its water material";
    EXPECT_GT(got.mesh.triangleCount(), 100u);
  }
  EXPECT_TRUE(sawLiquid) << "no mesh named 'sph 0' in the export";
}

// --threads caps the loading and the frames' geometry; the files are the same for any count.
TEST(ExportThreads, OneThreadWritesTheSameBytesAsAllCores) {
  const fs::path dir = test::testDirectory("export_threads", /*fresh=*/true);
  const fs::path shotPath = writeExportShot(dir);
  auto bytesOf = [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  for (const std::string threads : {"1", "0"}) {
    const auto run = lacrima({"export", shotPath.string(), "--frames", "2", "--threads", threads, "--out",
                              (dir / ("threads" + threads + ".glb")).string()});
    ASSERT_EQ(run.exitStatus, 0) << run.output;
  }
  const std::string one = bytesOf(dir / "threads1.glb");
  EXPECT_GT(one.size(), 1000u);
  EXPECT_TRUE(one == bytesOf(dir / "threads0.glb"));
}

// ---- bad input ---------------------------------------------------------------------------------

class ExportErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::testDirectory("export", /*fresh=*/true);
    shotPath_ = writeExportShot(dir_);
  }
  // Runs export with the options; it must fail with exit 2 and leave only the shot file.
  std::string exportFails(const std::vector<std::string>& options) {
    std::vector<std::string> args = {"export", shotPath_.string()};
    args.insert(args.end(), options.begin(), options.end());
    const auto run = lacrima(args);
    EXPECT_EQ(run.exitStatus, 2) << run.output;
    EXPECT_EQ(filesIn(dir_), std::set<std::string>{"geo.json"});
    return run.output;
  }
  fs::path dir_, shotPath_;
};

TEST_F(ExportErrors, UnknownFormat) {
  EXPECT_EQ(exportFails({"--format", "fbx"}), "--format: expected glb or obj, found 'fbx'\n" + kHint);
}

TEST_F(ExportErrors, NegativeThreads) {
  EXPECT_EQ(exportFails({"--threads", "-1"}), "--threads: expected an integer >= 0, found -1\n" + kHint);
}

TEST_F(ExportErrors, FramesOutsideTheShotOrMalformed) {
  EXPECT_EQ(exportFails({"--frames", "2-4"}),
            "--frames 2-4: frame 4 is outside the frame range 1-3 of " + shotPath_.string() + "\n");
  EXPECT_EQ(exportFails({"--frames", "3-1"}), "--frames 3-1: range '3-1' ends before it starts\n");
}

TEST_F(ExportErrors, OutputWithoutFrameFieldOrWithTheWrongExtension) {
  const std::string still = (dir_ / "geo.glb").string();
  EXPECT_EQ(exportFails({"--frames", "1-2", "--out", still}),
            "output '" + still +
                "' has no #### frame field but 2 frames are to be exported: every frame would overwrite the last\n");
  const std::string obj = (dir_ / "geo.####.obj").string();
  EXPECT_EQ(exportFails({"--out", obj}),
            "output '" + obj + "': --format glb writes .glb files, the name must end in .glb\n");
}

TEST_F(ExportErrors, BadShotGivesTheMessagesOfCheck) {
  const std::string bad = kSource + "/tests/data/bad_shots/unknown_key.json";
  const auto check = lacrima({"check", bad});
  ASSERT_EQ(check.exitStatus, 2);
  const auto run = lacrima({"export", bad, "--out", (dir_ / "x.####.glb").string()});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, check.output);
  EXPECT_EQ(filesIn(dir_), std::set<std::string>{"geo.json"});
}

TEST_F(ExportErrors, OutputDirectoryThatCannotBeCreated) {
  std::ofstream(dir_ / "blocker") << "a file where the output directory should be\n";
  const fs::path out = dir_ / "blocker" / "geo.0001.glb";
  const auto run = lacrima({"export", shotPath_.string(), "--frames", "1", "--out", out.string()});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, "cannot write glTF file '" + out.string() + "': cannot create directory '" +
                            (dir_ / "blocker").string() + "': Not a directory\n");
  EXPECT_EQ(filesIn(dir_), (std::set<std::string>{"blocker", "geo.json"}));
}

TEST(ExportHelp, HelpHasExamples) {
  const auto run = lacrima({"export", "--help"});
  EXPECT_EQ(run.exitStatus, 0);
  EXPECT_NE(run.output.find("\nExamples:\n  lacrima export "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--format"), std::string::npos) << run.output;
}

}  // namespace export_test
}  // namespace lacrima
