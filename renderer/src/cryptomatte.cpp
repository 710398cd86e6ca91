// Cryptomatte IDs and the ranking filter; see cryptomatte.hpp.
#include "lacrima/renderer/cryptomatte.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstring>
#include <numeric>

#include "lacrima/renderer/frame.hpp"

namespace lacrima {

namespace {

uint32_t rotateLeft(uint32_t x, int r) { return (x << r) | (x >> (32 - r)); }

// MurmurHash3's mixing of one 4-byte block into the hash (Appleby 2011).
uint32_t scrambledBlock(uint32_t k) {
  k *= 0xcc9e2d51u;
  k = rotateLeft(k, 15);
  return k * 0x1b873593u;
}

}  // namespace

uint32_t murmurHash3_32(std::string_view text, uint32_t seed) {
  const auto* bytes = reinterpret_cast<const uint8_t*>(text.data());
  const size_t blocks = text.size() / 4;
  uint32_t h = seed;
  for (size_t i = 0; i < blocks; ++i) {
    // Little-endian blocks, as the reference implementation reads them on x86.
    const uint32_t k = uint32_t(bytes[4 * i]) | uint32_t(bytes[4 * i + 1]) << 8 | uint32_t(bytes[4 * i + 2]) << 16 |
                       uint32_t(bytes[4 * i + 3]) << 24;
    h ^= scrambledBlock(k);
    h = rotateLeft(h, 13) * 5u + 0xe6546b64u;
  }
  const uint8_t* tail = bytes + 4 * blocks;
  uint32_t k = 0;
  switch (text.size() & 3u) {
    case 3: k ^= uint32_t(tail[2]) << 16; [[fallthrough]];
    case 2: k ^= uint32_t(tail[1]) << 8; [[fallthrough]];
    case 1: k ^= uint32_t(tail[0]); h ^= scrambledBlock(k);
  }
  // The finaliser: every input bit avalanches.
  h ^= uint32_t(text.size());
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

float cryptomatteIdOf(uint32_t hash) {
  const uint32_t exponent = std::clamp<uint32_t>((hash >> 23) & 255u, 1u, 254u);
  return std::bit_cast<float>((hash & 0x807fffffu) | (exponent << 23));
}

std::string cryptomatteHex(float id) { return fmt::format("{:08x}", std::bit_cast<uint32_t>(id)); }

std::string cryptomatteKey(std::string_view typeName) {
  return fmt::format("{:08x}", murmurHash3_32(typeName)).substr(0, 7);
}

CryptomatteNames cryptomatteNames(const Frame& frame) {
  CryptomatteNames names;
  for (size_t i = 0; i < frame.meshes.size(); ++i) {
    const std::string& name = frame.meshes[i].mesh.name;
    names.objects.push_back(name.empty() ? fmt::format("mesh {}", i) : name);
  }
  for (size_t i = 0; i < frame.spheres.size(); ++i) names.objects.push_back(fmt::format("sphere {}", i));
  for (size_t i = 0; i < frame.materials.size(); ++i) {
    const std::string& name = frame.materials[i].name;
    names.materials.push_back(name.empty() ? fmt::format("material {}", i) : name);
  }
  // A light is named as its light group (light_groups.hpp), so "key" picks the same light in both.
  for (size_t i = 0; i < frame.lights.size(); ++i) {
    const std::string& group = frame.lights[i].group;
    const std::string name = group.empty() ? fmt::format("light{}", i) : group;
    names.objects.push_back(name);
    names.materials.push_back(name);
  }
  names.materialManifest = names.materials;
  std::vector<bool> filmed(frame.materials.size(), false);
  for (const MeshInstance& mesh : frame.meshes)
    if (!mesh.wetness.empty() && mesh.materialId < filmed.size() &&
        std::holds_alternative<SkinParams>(frame.materials[mesh.materialId].params))
      filmed[mesh.materialId] = true;
  for (size_t i = 0; i < frame.materials.size(); ++i) {
    names.materials.push_back(names.materials[i] + "/wet");
    if (filmed[i]) names.materialManifest.push_back(names.materials.back());
  }
  return names;
}

int CryptomatteNames::materialIndex(const Frame& frame, uint32_t materialId, bool wet) {
  return int(materialId) + (wet ? int(frame.materials.size() + frame.lights.size()) : 0);
}

void IdCoverage::add(float id, float weight) {
  for (size_t i = 0; i < ids_.size(); ++i)
    if (ids_[i] == id) {
      weights_[i] += weight;
      return;
    }
  ids_.push_back(id);
  weights_.push_back(weight);
}

std::vector<float> IdCoverage::ranked(int ranks, float totalWeight) const {
  std::vector<size_t> order(ids_.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return weights_[a] != weights_[b] ? weights_[a] > weights_[b] : ids_[a] < ids_[b];
  });
  std::vector<float> pairs(2 * size_t(ranks), 0.0f);
  const float inverse = totalWeight != 0.0f ? 1.0f / totalWeight : 0.0f;
  for (size_t r = 0; r < order.size() && r < size_t(ranks); ++r) {
    pairs[2 * r] = ids_[order[r]];
    pairs[2 * r + 1] = weights_[order[r]] * inverse;
  }
  return pairs;
}

std::string cryptomatteManifest(const std::vector<std::string>& names) {
  nlohmann::ordered_json manifest = nlohmann::ordered_json::object();
  for (const std::string& name : names) manifest[name] = cryptomatteHex(cryptomatteIdOf(name));
  return manifest.dump();
}

}  // namespace lacrima
