#pragma once
// Flesh volumes kept on disk: TetGen takes seconds on a face region, and a shot's frames, its farm
// tasks and the next run all need the same volume. A volume is filed under a hash of everything it
// is built from (the patch's positions and triangles, the settings, this file format's version),
// written whole or not at all (a temporary file renamed into place).
#include <cstdint>
#include <filesystem>
#include <optional>

#include "lacrima/flesh/flesh_volume.hpp"

namespace lacrima::flesh {

// FNV-1a (Fowler, Noll & Vo) over the inputs of buildFleshVolume.
uint64_t fleshVolumeKey(const SkinPatch& patch, const FleshVolumeSettings& settings);

void writeFleshVolume(const std::filesystem::path& file, const FleshVolume& volume, uint64_t key);
// The volume in `file` when it holds one filed under `key`; nullopt when it is missing, another
// volume's, truncated or corrupt.
std::optional<FleshVolume> readFleshVolume(const std::filesystem::path& file, uint64_t key);

// The volume from `cacheDirectory` when it has it, else built and filed there (a directory that
// cannot be written only loses the filing). An empty directory: built, not filed.
FleshVolume cachedFleshVolume(const SkinPatch& patch, const FleshVolumeSettings& settings,
                              const std::filesystem::path& cacheDirectory);

}  // namespace lacrima::flesh
