#include "lacrima/flesh/flesh_volume_cache.hpp"

#include "binary_file.hpp"
#include "lacrima/flesh/fnv1a.hpp"

#include <fmt/format.h>

#include <cstring>
#include <fstream>
#include <system_error>

namespace lacrima::flesh {

namespace {

constexpr char kVolumeCacheMagic[8] = {'L', 'C', 'F', 'L', 'E', 'S', 'H', '2'};

}  // namespace

uint64_t fleshVolumeKey(const SkinPatch& patch, const FleshVolumeSettings& settings) {
  Fnv1a h;
  h.add(kVolumeCacheMagic, sizeof kVolumeCacheMagic);
  h.add(patch.positions.size());
  for (const Vec3d& p : patch.positions) h.add(p.data(), sizeof(double) * 3);
  for (const Vec3d& n : patch.normals) h.add(n.data(), sizeof(double) * 3);
  h.add(patch.triangles.size());
  for (const auto& t : patch.triangles) h.add(t);
  h.add(settings.depth);
  h.add(settings.maxTetVolume);
  h.add(settings.radiusEdgeRatio);
  const std::string recipe = fleshVolumeRecipe(settings);
  h.add(recipe.data(), recipe.size());
  return h.value();
}

void writeFleshVolume(const std::filesystem::path& file, const FleshVolume& volume, uint64_t key) {
  writeFileWhole(file, [&](std::ostream& out) {
    out.write(kVolumeCacheMagic, sizeof kVolumeCacheMagic);
    put(out, key);
    put(out, uint64_t(volume.mesh.nodes.size()));
    put(out, uint64_t(volume.mesh.tets.size()));
    put(out, int32_t(volume.skinNodes));
    for (const Vec3d& p : volume.mesh.nodes) out.write(reinterpret_cast<const char*>(p.data()), sizeof(double) * 3);
    for (const Tet& t : volume.mesh.tets) out.write(reinterpret_cast<const char*>(t.data()), sizeof(int) * 4);
    for (bool k : volume.kinematic) put(out, uint8_t(k));
    for (const NodeAnchor& a : volume.anchors) {
      put(out, int32_t(a.triangle));
      out.write(reinterpret_cast<const char*>(a.barycentric.data()), sizeof(double) * 3);
      out.write(reinterpret_cast<const char*>(a.offset.data()), sizeof(double) * 3);
    }
  });
}

std::optional<FleshVolume> readFleshVolume(const std::filesystem::path& file, uint64_t key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  char magic[sizeof kVolumeCacheMagic];
  uint64_t filedKey = 0, nodes = 0, tets = 0;
  int32_t skinNodes = 0;
  if (!in.read(magic, sizeof magic) || std::memcmp(magic, kVolumeCacheMagic, sizeof kVolumeCacheMagic) != 0) return std::nullopt;
  if (!get(in, filedKey) || filedKey != key || !get(in, nodes) || !get(in, tets) || !get(in, skinNodes)) return std::nullopt;
  const auto size = std::filesystem::file_size(file);
  const uint64_t expected = sizeof kVolumeCacheMagic + 3 * sizeof(uint64_t) + sizeof(int32_t) + nodes * 24 + tets * 16 + nodes +
                            nodes * (4 + 48);
  if (size != expected || skinNodes < 0 || uint64_t(skinNodes) > nodes) return std::nullopt;
  FleshVolume volume;
  volume.skinNodes = skinNodes;
  volume.mesh.nodes.resize(nodes);
  volume.mesh.tets.resize(tets);
  for (Vec3d& p : volume.mesh.nodes) in.read(reinterpret_cast<char*>(p.data()), sizeof(double) * 3);
  for (Tet& t : volume.mesh.tets) in.read(reinterpret_cast<char*>(t.data()), sizeof(int) * 4);
  volume.kinematic.resize(nodes);
  for (size_t i = 0; i < nodes; ++i) {
    uint8_t k = 0;
    get(in, k);
    volume.kinematic[i] = k != 0;
  }
  volume.anchors.resize(nodes);
  for (NodeAnchor& a : volume.anchors) {
    int32_t triangle = 0;
    get(in, triangle);
    a.triangle = triangle;
    in.read(reinterpret_cast<char*>(a.barycentric.data()), sizeof(double) * 3);
    in.read(reinterpret_cast<char*>(a.offset.data()), sizeof(double) * 3);
  }
  if (!in || !findTetMeshDefect(volume.mesh).empty()) return std::nullopt;
  return volume;
}

FleshVolume cachedFleshVolume(const SkinPatch& patch, const FleshVolumeSettings& settings,
                              const std::filesystem::path& cacheDirectory) {
  if (cacheDirectory.empty()) return buildFleshVolume(patch, settings);
  const uint64_t key = fleshVolumeKey(patch, settings);
  const std::filesystem::path file = cacheDirectory / fmt::format("{:016x}.flesh", key);
  if (std::optional<FleshVolume> cached = readFleshVolume(file, key)) {
    // A file of the right key but for another patch size is another volume: rebuild.
    bool fits = cached->skinNodes == int(patch.positions.size());
    for (const NodeAnchor& a : cached->anchors) fits = fits && a.triangle >= 0 && size_t(a.triangle) < patch.triangles.size();
    if (fits) return std::move(*cached);
  }
  FleshVolume volume = buildFleshVolume(patch, settings);
  try {
    std::error_code ec;
    std::filesystem::create_directories(cacheDirectory, ec);
    writeFleshVolume(file, volume, key);
  } catch (const std::exception&) {
    // Not filed: the next run builds it again.
  }
  return volume;
}

}  // namespace lacrima::flesh
