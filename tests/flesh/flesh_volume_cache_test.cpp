// Flesh volumes filed on disk: read back bitwise, keyed by their inputs, and never trusted when
// the file is cut short or corrupt.
#include "lacrima/flesh/flesh_volume_cache.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fmt/format.h>

#include <fstream>

namespace lacrima::flesh {
namespace flesh_volume_cache_test {

namespace fs = std::filesystem;

SkinPatch smallPatch() {
  std::vector<Vec3d> positions, normals;
  std::vector<std::array<uint32_t, 3>> triangles;
  const int n = 4;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) positions.emplace_back(0.01 * i, 0.01 * j, 0.0), normals.emplace_back(0, 0, 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i);
      triangles.push_back({a, a + 1, a + n + 2});
      triangles.push_back({a, a + n + 2, a + n + 1});
    }
  return extractSkinPatch(positions, normals, triangles, std::vector<bool>(triangles.size(), true));
}

fs::path freshDirectory(const std::string& name) {
  const fs::path dir = fs::path(LACRIMA_TEST_OUTPUT_DIR) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void expectSameVolume(const FleshVolume& a, const FleshVolume& b) {
  EXPECT_EQ(a.mesh.nodes, b.mesh.nodes);
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.kinematic, b.kinematic);
  EXPECT_EQ(a.skinNodes, b.skinNodes);
  ASSERT_EQ(a.anchors.size(), b.anchors.size());
  for (size_t i = 0; i < a.anchors.size(); ++i) {
    EXPECT_EQ(a.anchors[i].triangle, b.anchors[i].triangle);
    EXPECT_EQ(a.anchors[i].barycentric, b.anchors[i].barycentric);
    EXPECT_EQ(a.anchors[i].offset, b.anchors[i].offset);
  }
}

// The small patch's volume built through a fresh cache directory, its key and the file it went to.
struct FiledVolume {
  fs::path dir;
  SkinPatch patch = smallPatch();
  FleshVolumeSettings settings;
  FleshVolume built;
  uint64_t key = 0;
  fs::path file;
  explicit FiledVolume(const std::string& name) : dir(freshDirectory(name)) {
    built = cachedFleshVolume(patch, settings, dir);
    key = fleshVolumeKey(patch, settings);
    file = dir / fmt::format("{:016x}.flesh", key);
  }
};

TEST(FleshVolumeCache, FiledVolumeReadsBackBitwise) {
  const FiledVolume filed("flesh_cache_roundtrip");
  const auto& [dir, patch, settings, built, key, file] = filed;
  ASSERT_TRUE(fs::exists(file));
  const std::optional<FleshVolume> read = readFleshVolume(file, key);
  ASSERT_TRUE(read);
  expectSameVolume(built, *read);
  EXPECT_FALSE(readFleshVolume(file, key + 1));  // another volume's key
  expectSameVolume(built, cachedFleshVolume(patch, settings, dir));
}

TEST(FleshVolumeCache, KeyChangesWithEveryInput) {
  const SkinPatch patch = smallPatch();
  const FleshVolumeSettings settings;
  const uint64_t key = fleshVolumeKey(patch, settings);
  FleshVolumeSettings deeper = settings;
  deeper.depth *= 1.01;
  EXPECT_NE(fleshVolumeKey(patch, deeper), key);
  FleshVolumeSettings finer = settings;
  finer.maxTetVolume *= 0.5;
  EXPECT_NE(fleshVolumeKey(patch, finer), key);
  SkinPatch moved = patch;
  moved.positions[3].z() += 1e-9;
  EXPECT_NE(fleshVolumeKey(moved, settings), key);
}

TEST(FleshVolumeCache, TruncatedOrCorruptFileIsNotTrusted) {
  const FiledVolume filed("flesh_cache_corrupt");
  const auto& [dir, patch, settings, built, key, file] = filed;
  fs::resize_file(file, fs::file_size(file) - 10);
  EXPECT_FALSE(readFleshVolume(file, key));
  expectSameVolume(built, cachedFleshVolume(patch, settings, dir));  // rebuilt and filed again
  ASSERT_TRUE(readFleshVolume(file, key));
  {
    // A tetrahedron's corner overwritten with a node that does not exist.
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(8 + 3 * 8 + 4 + std::streamoff(built.mesh.nodes.size() * 24));
    const int bad = 1 << 30;
    f.write(reinterpret_cast<const char*>(&bad), sizeof bad);
  }
  EXPECT_FALSE(readFleshVolume(file, key));
  // An unwritable directory only loses the filing.
  expectSameVolume(built, cachedFleshVolume(patch, settings, "/proc/lacrima-no-such-dir"));
}

}  // namespace flesh_volume_cache_test
}  // namespace lacrima::flesh
