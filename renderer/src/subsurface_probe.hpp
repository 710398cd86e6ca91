#pragma once
// The diffusion-profile method of subsurface skin (lacrima/materials/diffusion_profile.hpp): the
// exit point is found by a probe ray instead of a random walk, after King, Kulla, Conty & Fajardo
// 2013 ("BSSRDF Importance Sampling", SIGGRAPH Talks), as pbrt-v3 §15.4 implements it
// (SeparableBSSRDF::Sample_Sp and Pdf_Sp): pick a projection axis (the normal with probability
// 0.8, each tangent 0.1; subsurface_probe.cpp says why) and a channel (in proportion to its
// albedo), sample a radius from that channel's profile
// and an angle, and shoot a ray along the axis through the disk at that radius, inside the
// sphere of the channel's maximum radius. Every crossing of the same skin material is a
// candidate; one is chosen in proportion to the profile at its distance (subsurface_probe.cpp).
// Its weight is R(|p_exit - p_entry|) over that choice's probability and the combined density
// of all axes and channels (one-sample MIS), so a point
// that one axis samples badly (a surface seen edge-on) is covered by the others.
#include <cstdint>
#include <optional>
#include <vector>

#include "embree_scene.hpp"
#include "lacrima/materials/diffusion_profile.hpp"
#include "subsurface_walk.hpp"

namespace lacrima {

// The numbers one probe draws, each in [0, 1). The channel and the axis share one number (the
// channel by its cumulative probability, the axis by what is left of the number within it), so
// that a stratified number stratifies all nine pairs: a pixel's probes then take each channel
// and each axis in close to their proportions, instead of a binomial share of them, whose
// spread would be colour noise and, for the tangent probes that find nothing, grain.
struct ProbeNumbers {
  float channelAndAxis = 0.0f;
  float radius = 0.0f;
  float angle = 0.0f;
  float candidate = 0.0f;
};

// The skin surface a probe may land on: the material, and which side of its triangles' winding
// the entry was on (the exit's normals take the same side, so they point out of the skin).
struct ProbeSurface {
  uint32_t materialId = 0;
  bool entryOnWindingSide = true;
};

// Finds where light that entered at `entry` (outwardNormal: its geometric normal, out of the
// skin) leaves, and the weight R / pdf per channel. Nothing when the probe meets no skin.
// Like the walk, a skin point under a dielectric (a drop) carries the radiance ratio
// (n_entry / n_exit)^2 (subsurface_walk.hpp). `rays` counts the ray queries.
std::optional<SubsurfaceExit> probeDiffusionExit(const EmbreeScene& scene, const DiffusionProfile& profile,
                                                 const ProbeSurface& surface, const std::vector<float>& dielectricIndex,
                                                 const Vec3& entry, const Vec3& outwardNormal, float time,
                                                 const ProbeNumbers& u, uint64_t& rays);

}  // namespace lacrima
