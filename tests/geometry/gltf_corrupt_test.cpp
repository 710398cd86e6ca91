// Broken inputs must give an InputError that names the file, never a crash or another exception.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace gltf_corrupt_test {

using nlohmann::json;

// Loads `path` expecting an InputError whose message names the file and contains `fragment`.
void expectInputError(const std::filesystem::path& path, const std::string& fragment = "") {
  try {
    loadGltfAsset(path);
    ADD_FAILURE() << path << " loaded without error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << "message does not name the file: " << message;
    EXPECT_NE(message.find(fragment), std::string::npos) << "expected '" << fragment << "' in: " << message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << " threw a non-InputError: " << e.what();
  }
}

std::filesystem::path writeCase(const std::string& name, const std::vector<unsigned char>& bytes) {
  const std::filesystem::path path = test::testOutputDir() / name;
  test::writeBytes(path, bytes);
  return path;
}

TEST(GltfCorrupt, MissingFileAndDirectory) {
  expectInputError(test::testOutputDir() / "does_not_exist.glb", "file not found");
  expectInputError(test::testOutputDir(), "directory");
}

TEST(GltfCorrupt, TruncatedCopiesOfTheFace) {
  const std::vector<unsigned char> face = test::readBytes(test::faceAssetPath());
  const size_t jsonEnd = 20 + test::u32At(face, 12);
  const std::vector<size_t> lengths = {0, 3, 4, 11, 12, 16, 19, 20, 21, 1000, jsonEnd / 2, jsonEnd - 1, jsonEnd,
                                       jsonEnd + 4, jsonEnd + 8, jsonEnd + 100, face.size() / 2, face.size() - 4,
                                       face.size() - 1};
  for (size_t length : lengths) {
    SCOPED_TRACE(length);
    const std::vector<unsigned char> cut(face.begin(), face.begin() + long(length));
    expectInputError(writeCase(fmt::format("face_truncated_{}.glb", length), cut));
  }
}

TEST(GltfCorrupt, TruncationIsReportedAsSuch) {
  const std::vector<unsigned char> face = test::readBytes(test::faceAssetPath());
  const std::vector<unsigned char> cut(face.begin(), face.begin() + long(face.size() / 2));
  expectInputError(writeCase("face_half.glb", cut), "truncated");
}

TEST(GltfCorrupt, RandomBytes) {
  std::mt19937 rng(1234);
  std::vector<unsigned char> bytes(4096);
  for (auto& b : bytes) b = static_cast<unsigned char>(rng());
  expectInputError(writeCase("random.glb", bytes), "not a glTF file");
  bytes[0] = '{';  // looks like JSON, is not
  expectInputError(writeCase("random_brace.gltf", bytes), "not a valid glTF file");
  std::memcpy(bytes.data(), "glTF\x02\0\0\0", 8);  // GLB magic and version, garbage after
  expectInputError(writeCase("random_magic.glb", bytes));
}

TEST(GltfCorrupt, EmptyFile) { expectInputError(writeCase("empty.glb", {}), "not a glTF file"); }

// The face with its JSON edited and the container rebuilt correctly: errors the loader's own
// checks must catch (tinygltf accepts all of these).
class EditedFace : public ::testing::Test {
 protected:
  void SetUp() override { parts_ = test::splitGlb(test::readBytes(test::faceAssetPath())); }
  std::filesystem::path write(const std::string& name) { return writeCase(name, test::makeGlb(parts_.json, parts_.bin)); }
  json& gltf() { return parts_.json; }
  test::GlbParts parts_;
};

TEST_F(EditedFace, UneditedRoundTripLoads) {
  EXPECT_EQ(loadGltfAsset(write("face_roundtrip.glb")).primitives.size(), 12u);
}

TEST_F(EditedFace, BufferViewOutsideTheBuffer) {
  gltf()["bufferViews"][0]["byteOffset"] = 10'600'000;
  expectInputError(write("face_view_outside.glb"), "bufferView 0");
}

TEST_F(EditedFace, AccessorCountBeyondItsView) {
  gltf()["accessors"][0]["count"] = 20000;
  expectInputError(write("face_count.glb"), "accessor 0");
}

TEST_F(EditedFace, HugeAccessorCount) {
  gltf()["accessors"][0]["count"] = 4'000'000'000u;
  expectInputError(write("face_huge_count.glb"), "accessor 0");
}

TEST_F(EditedFace, IndicesOutOfRange) {
  gltf()["accessors"][2]["bufferView"] = 0;  // reinterpret float positions as uint32 indices
  gltf()["accessors"][2]["count"] = 300;
  expectInputError(write("face_indices.glb"), "index");
}

TEST_F(EditedFace, IndexCountNotAMultipleOfThree) {
  gltf()["accessors"][2]["count"] = 55379;
  expectInputError(write("face_index_count.glb"), "multiple of 3");
}

TEST_F(EditedFace, SparseCountLargerThanTheAccessor) {
  gltf()["accessors"][3]["sparse"]["count"] = 10000;  // the accessor has 9547 elements
  expectInputError(write("face_sparse_count.glb"), "sparse");
}

TEST_F(EditedFace, SparseIndexOutOfRange) {
  gltf()["accessors"][3]["sparse"]["indices"]["bufferView"] = 4;  // float bits as indices: huge
  expectInputError(write("face_sparse_index.glb"), "sparse");
}

TEST_F(EditedFace, NonTriangleModeNamesThePrimitive) {
  gltf()["meshes"][0]["primitives"][3]["mode"] = 1;
  expectInputError(write("face_lines.glb"), "primitive 3 of mesh 0 ('ICTFace') has mode LINES");
}

TEST_F(EditedFace, NodeCycle) {
  gltf()["nodes"][0]["children"] = {0};
  expectInputError(write("face_cycle.glb"), "cycle");
}

TEST_F(EditedFace, MissingNodeInScene) {
  gltf()["scenes"][0]["nodes"] = {5};
  expectInputError(write("face_scene_node.glb"), "node 5");
}

TEST_F(EditedFace, LandmarkVertexOutOfRange) {
  gltf()["nodes"][0]["extras"]["landmarks68"][3]["vertex"] = 100000;
  expectInputError(write("face_landmark.glb"), "landmarks68[3]");
}

TEST_F(EditedFace, WrongAccessorType) {
  gltf()["accessors"][0]["type"] = "VEC2";
  expectInputError(write("face_type.glb"), "components");
}

TEST_F(EditedFace, MorphTargetCountMismatch) {
  gltf()["accessors"][3]["count"] = 9546;
  expectInputError(write("face_target_count.glb"), "morph target");
}

TEST_F(EditedFace, NonFinitePosition) {
  const size_t offset = gltf()["bufferViews"][0].value("byteOffset", size_t(0));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&parts_.bin[offset + 12], &nan, 4);
  expectInputError(write("face_nan.glb"), "non-finite");
}

// Random byte edits of a whole small file: each must load or fail with InputError, nothing else.
TEST(GltfCorrupt, RandomEditsOfASmallFileNeverCrash) {
  std::vector<unsigned char> bin;
  const size_t pos = test::appendValues(bin, std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  const size_t idx = test::appendValues(bin, std::vector<uint16_t>{0, 1, 2, 0});
  const size_t sIdx = test::appendValues(bin, std::vector<uint8_t>{1, 0, 0, 0});
  const size_t sVal = test::appendValues(bin, std::vector<float>{0, 0, 1});
  const json gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}, {"scale", {1, 2, 3}}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"targets", {{{"POSITION", 2}}}}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}},
        {{"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
         {"sparse", {{"count", 1}, {"indices", {{"bufferView", 2}, {"componentType", 5121}}}, {"values", {{"bufferView", 3}}}}}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", pos}, {"byteLength", 36}},
        {{"buffer", 0}, {"byteOffset", idx}, {"byteLength", 6}},
        {{"buffer", 0}, {"byteOffset", sIdx}, {"byteLength", 1}},
        {{"buffer", 0}, {"byteOffset", sVal}, {"byteLength", 12}}}},
      {"buffers", {{{"byteLength", bin.size()}}}},
  };
  const std::vector<unsigned char> original = test::makeGlb(gltf, bin);
  ASSERT_EQ(loadGltfAsset(writeCase("small.glb", original)).primitives.size(), 1u);

  std::mt19937 rng(99);
  int loaded = 0, rejected = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<unsigned char> bytes = original;
    const int edits = 1 + int(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const size_t at = rng() % bytes.size();
      // Digits keep the JSON parseable more often, which reaches the loader's own checks.
      bytes[at] = (rng() % 2) ? static_cast<unsigned char>('0' + rng() % 10) : static_cast<unsigned char>(rng());
    }
    const std::filesystem::path path = writeCase("small_edited.glb", bytes);
    try {
      loadGltfAsset(path);
      ++loaded;
    } catch (const InputError& e) {
      ++rejected;
      ASSERT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      FAIL() << "trial " << trial << ": non-InputError " << e.what();
    }
  }
  EXPECT_GT(rejected, 100);
  std::printf("[ info     ] random edits: %d loaded, %d rejected with InputError\n", loaded, rejected);
}

}  // namespace gltf_corrupt_test
}  // namespace lacrima
