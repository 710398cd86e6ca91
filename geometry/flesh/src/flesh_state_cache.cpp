#include "lacrima/flesh/flesh_state_cache.hpp"

#include <fmt/format.h>

#include <cstring>
#include <fstream>

#include "binary_file.hpp"
#include "lacrima/flesh/fnv1a.hpp"

namespace lacrima::flesh {

namespace {

constexpr char kStateCacheMagic[8] = {'L', 'C', 'F', 'S', 'T', 'A', 'T', '1'};

void putVectors(std::ostream& out, const std::vector<Vec3d>& values) {
  for (const Vec3d& v : values) out.write(reinterpret_cast<const char*>(v.data()), sizeof(double) * 3);
}

bool getVectors(std::istream& in, std::vector<Vec3d>& values) {
  for (Vec3d& v : values)
    if (!in.read(reinterpret_cast<char*>(v.data()), sizeof(double) * 3) || !v.allFinite()) return false;
  return true;
}

}  // namespace

uint64_t chainFleshStateKey(uint64_t previous, const std::vector<Vec3d>& drivingValues) {
  Fnv1a h(previous);
  h.add(drivingValues.size());
  for (const Vec3d& v : drivingValues) h.add(v.data(), sizeof(double) * 3);
  return h.value();
}

std::filesystem::path fleshStateFile(const std::filesystem::path& directory, long frameIndex, uint64_t key) {
  return directory / fmt::format("frame{:05d}-{:016x}.state", frameIndex, key);
}

void writeFleshState(const std::filesystem::path& file, const FleshState& state, uint64_t key) {
  writeFileWhole(file, [&](std::ostream& out) {
    out.write(kStateCacheMagic, sizeof kStateCacheMagic);
    put(out, key);
    put(out, uint64_t(state.positions.size()));
    putVectors(out, state.positions);
    putVectors(out, state.velocities);
  });
}

std::optional<FleshState> readFleshState(const std::filesystem::path& file, uint64_t key, size_t nodes) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  char magic[sizeof kStateCacheMagic];
  uint64_t filedKey = 0, filedNodes = 0;
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kStateCacheMagic, sizeof kStateCacheMagic) != 0) return std::nullopt;
  if (!get(in, filedKey) || filedKey != key || !get(in, filedNodes) || filedNodes != nodes) return std::nullopt;
  FleshState state{std::vector<Vec3d>(nodes), std::vector<Vec3d>(nodes)};
  if (!getVectors(in, state.positions) || !getVectors(in, state.velocities)) return std::nullopt;
  if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;  // longer than a state: not one
  return state;
}

}  // namespace lacrima::flesh
