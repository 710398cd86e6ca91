#pragma once
// Cryptomatte ID mattes (Friedman & Jones 2015; the Cryptomatte specification of Psyop's
// committee): every camera sample's first hit is named (its object: the frame mesh's name such as
// "face/M_Face" or "tear", "sphere <i>", a light by its light group's name, "light<i>" without one;
// its material: the shot's material name); a
// name becomes a float ID by MurmurHash3_x86_32 (Appleby 2011) converted "uint32_to_float32"; per
// pixel a ranking filter sums each ID's filter weights over the pixel's samples, divides by the
// sum of all of them (coverage), and keeps the IDs of the largest coverage, ranked. The EXR holds
// them as <Type>00.R/G/B/A = (ID, coverage) of ranks 0 and 1, <Type>01 of ranks 2 and 3, ...;
// its header names each type's hash, conversion and manifest (every name of the frame and its ID
// as 8 hex digits) under "cryptomatte/<key>/", the key the first 7 hex digits of the type name's
// hash.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima {

struct Frame;

// MurmurHash3_x86_32 of the bytes of `text` (Appleby 2011).
uint32_t murmurHash3_32(std::string_view text, uint32_t seed = 0);

// The specification's uint32_to_float32: the hash's bits as a float, its exponent clamped to
// [1, 254] so that no ID is zero (the empty sample), denormal, infinite or NaN.
float cryptomatteIdOf(uint32_t hash);
inline float cryptomatteIdOf(std::string_view name) { return cryptomatteIdOf(murmurHash3_32(name)); }
// The ID's bits as 8 lower-case hex digits (the manifest's values).
std::string cryptomatteHex(float id);
// The metadata key of a Cryptomatte type: the first 7 hex digits of the hash of its name.
std::string cryptomatteKey(std::string_view typeName);

// What a camera sample saw first, as indices into CryptomatteNames' lists (-1: nothing).
struct FirstHitIds {
  int object = -1;
  int material = -1;
};

// The names the IDs are made of: objects are the frame's meshes, then its spheres, then its lights;
// materials are the frame's materials, then the lights (a light has no material), then each
// material under a tear's film, "<material>/wet" (a wet trail is a film rendered on skin, not a
// mesh of its own: its own name lets a keyer take it with the tear). The manifests list the wet
// names of the skin materials of meshes that carry a film only.
struct CryptomatteNames {
  std::vector<std::string> objects, materials;
  std::vector<std::string> materialManifest;
  // The material list's index of a hit on material `materialId`, wet (a film on it) or not.
  static int materialIndex(const Frame& frame, uint32_t materialId, bool wet);
};
CryptomatteNames cryptomatteNames(const Frame& frame);

// A pixel's ranking filter: each ID's summed filter weight.
class IdCoverage {
 public:
  void add(float id, float weight);
  // The `ranks` largest (ID, coverage) pairs, coverage = weight / totalWeight, largest first (ties:
  // the smaller ID first), padded with (0, 0).
  std::vector<float> ranked(int ranks, float totalWeight) const;
  bool empty() const { return ids_.empty(); }

 private:
  std::vector<float> ids_, weights_;
};

// The manifest: {"name": "<hex ID>", ...} of every name, in the order given (JSON).
std::string cryptomatteManifest(const std::vector<std::string>& names);

}  // namespace lacrima
