#pragma once
// Unidirectional path tracer with next-event estimation and multiple importance sampling
// (Veach 1997, ch. 9, power heuristic), Russian roulette, shading-normal handling that does
// not leak light through surfaces, and nested dielectrics with priorities (medium_stack.hpp).
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "embree_scene.hpp"
#include "light_sampler.hpp"
#include "surface_textures.hpp"
#include "subsurface_probe.hpp"
#include "subsurface_walk.hpp"
#include "lacrima/renderer/sampler.hpp"
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/materials/skin.hpp"
#include "lacrima/materials/subsurface.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "lacrima/renderer/cryptomatte.hpp"
#include "lacrima/renderer/light_groups.hpp"
#include "lacrima/renderer/light_paths.hpp"
#include "medium_stack.hpp"
#include "specular_manifold.hpp"

namespace lacrima {

// What the camera ray saw first, for the AOVs.
struct FirstHit {
  bool valid = false;
  Color albedo = Color::Zero();
  Vec3 normal = Vec3::Zero();
  float distance = 0.0f;
  FirstHitIds ids;  // its object and material (Cryptomatte)
};

// Where a camera path's radiance also goes, split (each zeroed by the caller; null: not split).
struct RadianceSplits {
  Color* groups = nullptr;  // PathIntegrator::lightGroups().size() colours: by light group (light_groups.hpp)
  Color* paths = nullptr;   // kLightPathCount colours: by light path (light_paths.hpp)
};

struct PathCounters {
  uint64_t rays = 0;
};

class PathIntegrator {
 public:
  PathIntegrator(const Frame& frame, const EmbreeScene& scene, const LightSampler& lights);

  Color radiance(const Ray& cameraRay, PixelSampler& sampler, FirstHit& firstHit, PathCounters& counters,
                 const RadianceSplits& splits = {}) const;
  const LightGroups& lightGroups() const { return groups_; }

 private:
  struct Vertex;  // the shading point of the current bounce (integrator.cpp)

  enum class Trace { Hit, Miss, Lost };

  // A next-event estimate: the light's contribution (f cos Le / pdf, MIS-weighted), its source
  // (the light's index; -1 the environment) and the local direction f was evaluated in.
  struct DirectLight {
    Color radiance = Color::Zero();
    int source = -1;
    Vec3 wiLocal = Vec3::Zero();
  };
  DirectLight sampleDirectLight(const Vertex& vertex, const MediumStack& media, PixelSampler& sampler,
                                PathCounters& counters) const;
  // What reaches the shading point along shadowRay, known to be blocked, within maxDistance
  // (see integrator.cpp); media: the media the shadow ray starts in.
  Color shadowTransmittance(const Ray& shadowRay, float maxDistance, MediumStack media, bool& crossedDielectric,
                            PathCounters& counters) const;
  bool countedByTransparentShadows(bool chainAfterNonSpecular, int crossings) const;
  // The hit's object and material as cryptomatteNames lists them (none when no Cryptomatte is written).
  FirstHitIds cryptomatteIdsOf(const SurfaceHit& hit) const;

  // Manifold next-event estimation (mnee_direct_light.cpp): the light sample's contribution
  // through the 1 or 2 smooth dielectric interfaces its straight shadow ray crosses; nothing
  // when that ray crosses none, or more than 2 (the caller then goes on as without caustics).
  // wiLocal: where f was evaluated (the chain's first segment), when there is a contribution.
  std::optional<Color> manifoldDirectLight(const Vertex& v, const LightSample& light, const MediumStack& shadowMedia,
                                           PathCounters& counters, Vec3& wiLocal) const;
  struct CausticSeed;  // mnee_direct_light.cpp
  bool traceCausticSeed(const Vertex& v, const LightSample& light, MediumStack media, CausticSeed& seed,
                        PathCounters& counters) const;
  bool causticChainIsVisible(const Vertex& v, const LightSample& light, const CausticSeed& seed,
                             const SpecularChain& chain, MediumStack media, PathCounters& counters) const;

  // Nested dielectrics: the first surface along ray that is not a false interface (ray's origin
  // moves past the skipped ones, media follows them); Lost when too many were skipped.
  Trace traceToRealSurface(Ray& ray, SurfaceHit& hit, MediumStack& media, PathCounters& counters) const;
  // A surface of dielectric materialId; entering when the ray arrives on its normal's side.
  // The interface a walk meets at hit (segment_walk.hpp), false or real, with the medium beyond it.
  InterfaceCrossing mediumInterface(const MediumStack& media, const SurfaceHit& hit, bool entering) const;
  InterfaceCrossing classifyInterface(const MediumStack& media, uint32_t materialId, bool entering) const;
  // The BSDF of a real interface of materialId against otherMaterial (-1 = air).
  const Bsdf* interfaceBsdf(uint32_t materialId, int otherMaterial) const;
  void crossInterface(MediumStack& media, uint32_t materialId, bool entering) const;
  // The media around the camera, found by a probe ray (see integrator.cpp).
  MediumStack mediaAroundCamera() const;
  bool isDielectric(uint32_t materialId) const { return media_[materialId].has_value(); }
  // A dielectric mesh marked as a thin sheet, crossed straight through (MeshInstance::thinSheet).
  bool isThinSheet(const SurfaceHit& hit) const { return hit.meshIndex >= 0 && thinSheetMesh_[size_t(hit.meshIndex)]; }
  // A dielectric surface that bounds a volume (a closed mesh or a sphere): paths enter its medium.
  bool boundsMedium(const SurfaceHit& hit) const { return isDielectric(hit.materialId) && !isThinSheet(hit); }
  void findThinSheets();
  static Ray pastThinSheet(const Ray& ray, float sheetDistance);

  // Subsurface skin (integrator.cpp, subsurface_walk.hpp): what a skin with subsurface needs.
  struct SubsurfaceSkin {
    SkinParams params;  // untextured: the albedo and mean free path below the surface
    std::shared_ptr<const SkinBsdf> bsdf;  // for the specular/walk split
    std::shared_ptr<const Bsdf> exitBsdf;
    float ior;
    // The same skin with its Lambertian base instead of subsurface, and its BSDF: what a path
    // sees after a diffuse bounce (PathIntegrator::radiance says why).
    Material asDiffuse;
    std::shared_ptr<const Bsdf> asDiffuseBsdf;
  };
  struct Below;  // defined below, after Vertex
  static std::optional<SubsurfaceSkin> makeSubsurfaceSkin(const Material& material);
  // Finds the exit below the skin, dry or under a film (a random walk or a diffusion-profile probe,
  // SubsurfaceParams::method) for every sample, so the light through the skin is never left to a
  // coin toss, then picks how the path goes on: v.bsdf's lobes with probability pSurface, else
  // from the exit. below and surface: skin's own, or those of a textured hit (TexturedHit); wet:
  // the hit's wet skin (v.bsdf) under a tear film, else null.
  Below scatterBelowSurface(const SubsurfaceSkin& skin, const SkinParams& below, const SkinBsdf& surface,
                            const WetSkinBsdf* wet, const Vertex& v, float pSurface, PixelSampler& sampler,
                            PathCounters& counters) const;
  // The probability that the path goes on by the skin's own lobes (v.bsdf) rather than from the
  // exit below: the specular lobes' share at wo (dry), or the film's and the skin's (wet).
  static float surfaceProbability(const SkinBsdf& surface, const WetSkinBsdf* wet, const Vertex& v);
  // Where light that entered at v leaves the skin `below`, by its method: the probe with the
  // stratified numbers `probe`, the walk with as many numbers of `walkStream` (an independent
  // stream) as it takes steps.
  std::optional<SubsurfaceExit> findSubsurfaceExit(const SkinParams& below, const Vertex& v, const ProbeNumbers& probe,
                                                   PixelSampler walkStream, PathCounters& counters) const;

  const Frame& frame_;
  const EmbreeScene& scene_;
  const LightSampler& lights_;
  LightGroups groups_;
  SurfaceTextures textures_;  // the maps of textured materials; empty (no texture system) without any
  // Radians per pixel at the image centre: a path that has travelled d metres from the camera
  // meets surfaces with a footprint of about d * pixelSpread_ (texture mip levels). Ignores
  // the widening by curved or rough surfaces it bounced off, so later bounces under-blur.
  float pixelSpread_;
  std::vector<std::unique_ptr<Bsdf>> bsdfs_;  // one per material
  int maxDepth_;
  // Nested dielectrics, active only when some dielectric has a priority >= 1 (otherwise every
  // path renders exactly as without them).
  bool nested_ = false;
  std::vector<std::optional<DielectricMedium>> media_;  // per material; none for opaque ones
  // pairBsdfs_[hit * materialCount + other]: dielectric `hit` (priority >= 1) against medium `other`.
  std::vector<std::unique_ptr<Bsdf>> pairBsdfs_;
  MediumStack cameraMedia_;
  std::vector<std::optional<SubsurfaceSkin>> subsurface_;  // per material; none unless skin with subsurface
  std::vector<float> dielectricIndex_;  // per material: a dielectric's index, 0 if opaque (subsurface walks)
  std::vector<uint8_t> thinSheetMesh_;  // per frame mesh: 1 for a dielectric thin sheet
  std::vector<std::unique_ptr<Bsdf>> thinSheetBsdfs_;  // per material: its thin-sheet BSDF, where a sheet uses it
};

struct PathIntegrator::Vertex {
  Vec3 position;
  Vec3 geometricNormal;  // oriented as the shading frame's side (see orientNormals)
  ShadingFrame frame;
  uint32_t materialId;
  bool entering;         // arrived on the geometric normal's side (into a dielectric's medium)
  bool thinSheet = false;  // an open dielectric mesh: crossing it enters no medium
  Vec3 wo;               // world, towards the previous vertex
  Vec3 woLocal;
  const Bsdf* bsdf;
  float time;            // shutter time of the path
  // The probability that the path goes on by sampling bsdf here: 1, but on subsurface skin the
  // specular lobes' share at the entry and the rest at the exit (PathIntegrator::Below). The BSDF
  // technique's density is this times the BSDF's pdf, and MIS weighs the light samples with it.
  float bsdfSamplingProbability = 1.0f;
};

// What happened below the skin at one hit: where the light that entered there leaves (none when
// the walk or probe found no exit, or the skin is all wet) and with what weight (the dry
// fraction's entry Fresnel times the method's weight), and which way the path goes on.
struct PathIntegrator::Below {
  std::optional<Vertex> exit;  // the exit vertex, with the exit lobe as its BSDF
  Color exitWeight = Color::Zero();
  bool goesBelow = false;   // the path continues from the exit (else on v.bsdf's lobes)
  float pSurface = 1.0f;    // the probability of going on on v.bsdf's lobes
};

}  // namespace lacrima
