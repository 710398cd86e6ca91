// Flesh states filed on disk: a state reads back bitwise under its key, and anything else (another
// key, another size, a truncated or corrupt file, non-finite values) reads as no state at all.
#include "lacrima/flesh/flesh_state_cache.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "support/test_directory.hpp"

namespace lacrima::flesh {
namespace flesh_state_cache_test {

namespace fs = std::filesystem;

FleshState someState(size_t nodes) {
  FleshState s;
  for (size_t i = 0; i < nodes; ++i) {
    const double k = double(i);
    s.positions.emplace_back(std::sin(k), 1e-3 * k, -0.1 / (1.0 + k));
    s.velocities.emplace_back(1e-4 * k, std::cos(k), 0.3);
  }
  return s;
}

fs::path stateDirectory() {
  return test::testDirectory("flesh_states", true);
}

TEST(FleshStateCache, AStateReadsBackBitwiseUnderItsKey) {
  const FleshState state = someState(57);
  const fs::path file = fleshStateFile(stateDirectory(), 12, 0xabcdefull);
  EXPECT_NE(file.filename().string().find("frame00012-"), std::string::npos) << file;
  writeFleshState(file, state, 0xabcdefull);
  const std::optional<FleshState> back = readFleshState(file, 0xabcdefull, 57);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->positions, state.positions);
  EXPECT_EQ(back->velocities, state.velocities);
  EXPECT_FALSE(readFleshState(file, 0xabcdeeull, 57)) << "another key";
  EXPECT_FALSE(readFleshState(file, 0xabcdefull, 56)) << "another node count";
  EXPECT_FALSE(readFleshState(stateDirectory() / "missing.state", 0xabcdefull, 57));
}

TEST(FleshStateCache, TruncatedCorruptOrNonFiniteFilesAreNoState) {
  const fs::path dir = stateDirectory();
  const FleshState state = someState(20);
  const fs::path file = dir / "whole.state";
  writeFleshState(file, state, 7);
  const auto size = fs::file_size(file);
  // Truncated by one byte, and one byte too long.
  fs::copy_file(file, dir / "short.state", fs::copy_options::overwrite_existing);
  fs::resize_file(dir / "short.state", size - 1);
  EXPECT_FALSE(readFleshState(dir / "short.state", 7, 20));
  fs::copy_file(file, dir / "long.state", fs::copy_options::overwrite_existing);
  std::ofstream(dir / "long.state", std::ios::binary | std::ios::app) << 'x';
  EXPECT_FALSE(readFleshState(dir / "long.state", 7, 20));
  // Not a state file at all.
  std::ofstream(dir / "text.state", std::ios::binary) << "not a flesh state, but long enough to hold a header";
  EXPECT_FALSE(readFleshState(dir / "text.state", 7, 20));
  // A NaN where a position was.
  FleshState bad = state;
  bad.positions[3].y() = std::numeric_limits<double>::quiet_NaN();
  writeFleshState(dir / "nan.state", bad, 7);
  EXPECT_FALSE(readFleshState(dir / "nan.state", 7, 20));
}

TEST(FleshStateCache, ChainKeysChangeWithAnyDrivingValueAndTheirOrder) {
  const std::vector<Vec3d> a{{0.0, 1.0, 2.0}, {3.0, 4.0, 5.0}};
  std::vector<Vec3d> b = a;
  b[1].z() = std::nextafter(5.0, 6.0);
  EXPECT_NE(chainFleshStateKey(1, a), chainFleshStateKey(1, b));
  EXPECT_NE(chainFleshStateKey(1, a), chainFleshStateKey(2, a));
  EXPECT_NE(chainFleshStateKey(chainFleshStateKey(1, a), b), chainFleshStateKey(chainFleshStateKey(1, b), a));
  EXPECT_EQ(chainFleshStateKey(chainFleshStateKey(1, a), b), chainFleshStateKey(chainFleshStateKey(1, a), b));
}

}  // namespace flesh_state_cache_test
}  // namespace lacrima::flesh
