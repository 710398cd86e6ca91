#pragma once
// Light-path AOVs: the beauty split by how its light reached the camera, one layer per pass,
// named as compositors expect them (Arnold's and Cycles' passes): what the first surface the
// camera sees scattered, by the kind of that scattering (diffuse, specular, transmission) and
// whether the light came straight from a light to it (direct) or after more bounces (indirect);
// the light that went through the skin below that surface (subsurface); emitters and the
// environment seen straight from the camera (emission, environment).
//
// The path's kind is decided at its first vertex by the lobes of the BSDF there
// (Bsdf::evalLobes): a next-event estimate there is split by each lobe's share of f towards the
// light, and whatever the path gathers after its first bounce by each lobe's share of f in the
// bounce's direction (a delta lobe's sample is wholly its own kind). The shares add up to 1, so
// the passes add up to the beauty sample by sample (to float rounding), and each pass is itself
// an unbiased estimate of the light its lobes scatter (Cycles splits its passes the same way,
// by the evaluated closures' weights). "Direct" is one bounce: the first vertex's next-event
// estimate and the light or environment its sampled direction hits.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace lacrima {

enum class LightPath : uint8_t {
  DiffuseDirect,
  DiffuseIndirect,
  SpecularDirect,
  SpecularIndirect,
  TransmissionDirect,
  TransmissionIndirect,
  Subsurface,
  Emission,
  Environment,
};
inline constexpr size_t kLightPathCount = 9;

// The pass's EXR layer name: "diffuse_direct", ..., "environment".
const std::string& lightPathName(LightPath pass);
// All passes, in enum order.
const std::array<LightPath, kLightPathCount>& allLightPaths();

// Which passes a render writes, one bit per LightPath.
struct LightPathSet {
  uint16_t bits = 0;
  bool any() const { return bits != 0; }
  bool has(LightPath pass) const { return (bits >> unsigned(pass)) & 1u; }
  void add(LightPath pass) { bits = uint16_t(bits | (1u << unsigned(pass))); }
  void addAll() { bits = uint16_t((1u << kLightPathCount) - 1u); }
};

}  // namespace lacrima
