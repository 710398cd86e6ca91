#include "integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include "lacrima/materials/diffuse.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/skin_relief.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "light_path_split.hpp"
#include "ray_offset.hpp"
#include "sample_dimensions.hpp"
#include "segment_walk.hpp"
#include "shading_side.hpp"
#include "subsurface_probe.hpp"
#include "subsurface_walk.hpp"

namespace lacrima {

namespace {

// Veach 1997, eq. 9.13 (power heuristic, beta = 2).
float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// Wet skin (MeshInstance::wetness, materials/wet_skin.hpp): a skin hit under a water film shades
// with the skin's BSDF under that film, built in `storage` (on the stack, no allocation per hit).
// The caller passes no film for skin the path meets inside a bead or rivulet: there the water over
// the skin is the drop itself, already crossed, and a film's own top surface would add a second,
// air-facing reflection (sparkles of the small lights under every bead); the skin's own lobes
// there meet water (skinAtHit).
const Bsdf* underSkinFilm(const Bsdf* bsdf, const Material& material, float filmThickness,
                          std::optional<WetSkinBsdf>& storage) {
  if (!(filmThickness > 0.0f) || !std::holds_alternative<SkinParams>(material.params)) return bsdf;
  storage.emplace(static_cast<const SkinBsdf&>(*bsdf), wetFilmCoverage(filmThickness));
  return &*storage;
}

// Textured materials (surface_textures.hpp): a hit with uvs on a material with maps shades with
// the material's parameters times the maps' values there, a BSDF built in place (no allocation
// per hit) like underSkinFilm's. Hits without uvs keep the material's constant BSDF.
struct TexturedHit {
  TextureValues values;
  std::optional<SkinParams> skin;  // the textured skin parameters (its subsurface medium follows them)
  std::variant<std::monostate, DiffuseBsdf, SkinBsdf> bsdf;
};

// footprint: the width in metres of the pixel's cone where the path meets the surface (the mip
// level of the lookups, surface_textures.hpp).
const Bsdf* withTextures(const Bsdf* bsdf, const SurfaceTextures& textures, const Material& material,
                         const SurfaceHit& hit, float footprint, TexturedHit& storage) {
  if (!hit.hasUv || !textures.textured(hit.materialId)) return bsdf;
  storage.values = textures.lookup(hit.materialId, hit.uv, uvFootprint(footprint, hit.dpdu, hit.dpdv));
  const MaterialParams params = applyTextureValues(material.params, storage.values);
  if (const auto* skin = std::get_if<SkinParams>(&params)) {
    storage.skin = *skin;
    return &storage.bsdf.emplace<SkinBsdf>(*skin);
  }
  if (const auto* diffuse = std::get_if<DiffuseParams>(&params)) return &storage.bsdf.emplace<DiffuseBsdf>(*diffuse);
  return bsdf;
}

// Skin's parameters at this hit, where they differ from the material's (textured ones kept), in
// a BSDF built in `storage`:
// - a relief that darkens its hollows (SkinParams::cavity, skin_relief.hpp): the albedo times the
//   cavity factor there; the BSDF also carries the relief's gradient, so the relief is evaluated
//   once per hit;
// - skin under water (surroundingIor > 1: inside a bead or a rivulet): its surface layer meets
//   water, not air, and the Fresnel equations depend on the ratio of the two indices alone (Born &
//   Wolf 1999, section 1.5.2), so its specular lobes, and the transmission its base or subsurface
//   entry pays, take the relative index ior / surroundingIor. For skin (1.4) under tear water
//   (1.337) F(0) falls from 2.8 % to 0.05 %: skin seen through a drop loses its sheen.
const Bsdf* skinAtHit(const Bsdf* bsdf, const Material& material, const Vec3& position, float surroundingIor,
                      TexturedHit& storage) {
  const auto* skin = std::get_if<SkinParams>(&material.params);
  if (!skin) return bsdf;
  const bool cavity = skin->cavity > 0.0f, immersed = surroundingIor != 1.0f;
  if (!cavity && !immersed) return bsdf;
  SkinParams params = storage.skin ? *storage.skin : *skin;
  std::optional<Vec3> reliefGradient;
  if (cavity) {
    const SkinRelief relief = skinReliefAt(params, position);
    params.albedo *= cavityAlbedoFactor(params, relief);
    reliefGradient = relief.gradient;
  }
  if (immersed) params.ior /= surroundingIor;
  storage.skin = params;
  return &storage.bsdf.emplace<SkinBsdf>(params, reliefGradient);
}

// The per-type bounce limits (RenderSettings::bounces): how many times a path has scattered of
// each kind, and whether the scattering just sampled goes over its kind's limit.
class BounceCounter {
 public:
  explicit BounceCounter(const BounceLimits& limits) : limits_(limits) {}
  // Counts the scattering; true when it is one more than its kind allows.
  bool countIsOverLimit(const BsdfSample& s) {
    if (s.transmitted) return ++transmission_ > limits_.transmission;
    if (s.glossy || s.specular) return ++glossy_ > limits_.glossy;
    return ++diffuse_ > limits_.diffuse;
  }

 private:
  const BounceLimits& limits_;
  int diffuse_ = 0, glossy_ = 0, transmission_ = 0;
};

constexpr int kRussianRouletteDepth = 3;
// A shadow ray gives up (counts as blocked) after this many dielectric crossings.
constexpr int kMaxShadowCrossings = 16;
// A path is dropped (absorbed) after skipping this many false interfaces in one segment.
constexpr int kMaxFalseInterfaces = 64;
// The camera-media probe looks at no more than this many surfaces.
constexpr int kMaxProbeSurfaces = 256;

}  // namespace

bool PathIntegrator::countedByTransparentShadows(bool chainAfterNonSpecular, int crossings) const {
  return frame_.settings.caustics != Caustics::Off && chainAfterNonSpecular && crossings > 0;
}

PathIntegrator::PathIntegrator(const Frame& frame, const EmbreeScene& scene, const LightSampler& lights)
    : frame_(frame),
      scene_(scene),
      lights_(lights),
      groups_(lightGroupsOf(frame)),
      textures_(frame.materials),
      pixelSpread_(2.0f * std::tan(0.5f * frame.camera.verticalFovRadians) / float(std::max(1, frame.settings.height))),
      maxDepth_(frame.settings.maxDepth) {
  bsdfs_.reserve(frame.materials.size());
  for (const Material& material : frame.materials) bsdfs_.push_back(makeBsdf(material.params));
  subsurface_.resize(frame.materials.size());
  for (size_t id = 0; id < frame.materials.size(); ++id) subsurface_[id] = makeSubsurfaceSkin(frame.materials[id]);
  media_.reserve(frame.materials.size());
  for (const Material& material : frame.materials) {
    media_.push_back(dielectricMedium(material.params));
    if (media_.back() && media_.back()->priority > 0) nested_ = true;
  }
  for (const auto& medium : media_) dielectricIndex_.push_back(medium ? medium->ior : 0.0f);
  findThinSheets();
  if (!nested_) return;
  // Every real interface a path can meet, built once: dielectric `hit` of priority >= 1 against
  // each medium that can surround it.
  const size_t count = frame.materials.size();
  pairBsdfs_.resize(count * count);
  for (size_t hit = 0; hit < count; ++hit) {
    if (!media_[hit] || media_[hit]->priority == 0) continue;
    for (size_t other = 0; other < count; ++other)
      if (media_[other]) pairBsdfs_[hit * count + other] = makeBsdf(againstMedium(frame.materials[hit].params, media_[other]->ior));
  }
  cameraMedia_ = mediaAroundCamera();
}

// The ray that goes on straight through a thin sheet it hit at `sheetDistance`: the same line, with
// hits up to just past the sheet ignored. An origin offset off the sheet (offsetOrigin, 1e-4 of
// the coordinates: 10-20 um on a face) would jump over a surface that close behind it, and tear
// lines lie on the lid margin's skin that closely (the ICT face's M_LacrimalFluid): the camera
// would see into the head there, black.
Ray PathIntegrator::pastThinSheet(const Ray& ray, float sheetDistance) {
  Ray on = ray;
  on.tnear = justPast(sheetDistance);
  return on;
}

// Thin sheets (MeshInstance::thinSheet) of dielectric materials, each material's thin-sheet BSDF.
void PathIntegrator::findThinSheets() {
  thinSheetMesh_.assign(frame_.meshes.size(), 0);
  thinSheetBsdfs_.resize(frame_.materials.size());
  for (size_t i = 0; i < frame_.meshes.size(); ++i) {
    const MeshInstance& instance = frame_.meshes[i];
    if (!instance.thinSheet || !isDielectric(instance.materialId)) continue;
    thinSheetMesh_[i] = 1;
    if (!thinSheetBsdfs_[instance.materialId])
      thinSheetBsdfs_[instance.materialId] = makeThinSheetBsdf(frame_.materials[instance.materialId].params);
  }
}

InterfaceCrossing PathIntegrator::classifyInterface(const MediumStack& media, uint32_t materialId, bool entering) const {
  return media.classify(MediumEntry{materialId, media_[materialId]->priority}, entering);
}

// Only the surfaces that bound a medium can be false interfaces; every other surface (a light,
// an opaque one, a thin sheet), and every surface without priorities, is real.
InterfaceCrossing PathIntegrator::mediumInterface(const MediumStack& media, const SurfaceHit& hit, bool entering) const {
  if (!nested_ || hit.lightIndex >= 0 || !boundsMedium(hit)) return InterfaceCrossing{};
  return classifyInterface(media, hit.materialId, entering);
}

const Bsdf* PathIntegrator::interfaceBsdf(uint32_t materialId, int otherMaterial) const {
  if (otherMaterial < 0) return bsdfs_[materialId].get();
  return pairBsdfs_[materialId * bsdfs_.size() + size_t(otherMaterial)].get();
}

void PathIntegrator::crossInterface(MediumStack& media, uint32_t materialId, bool entering) const {
  if (nested_ && isDielectric(materialId)) media.cross(MediumEntry{materialId, media_[materialId]->priority}, entering);
}

// The media the camera sits in: a probe ray from the camera position at shutter open, in a fixed
// direction off the axes (so it rarely grazes mesh edges). A medium whose surface the probe
// meets first from inside encloses the camera (closed surfaces assumed). A thin lens's aperture
// is assumed to lie in the same media as its centre.
MediumStack PathIntegrator::mediaAroundCamera() const {
  const Vec3 direction = Vec3(0.5773f, 0.6139f, 0.5384f).normalized();
  SegmentWalk walk(scene_, Ray{frame_.camera.cameraToWorld.translation(), direction, 0.0f});
  std::vector<uint32_t> seen, enclosing;  // enclosing: innermost first
  SurfaceHit hit;
  uint64_t rays = 0;  // not a path's: set-up, uncounted
  for (int i = 0; i < kMaxProbeSurfaces && walk.next(hit, rays); ++i) {
    const bool firstMeeting = std::find(seen.begin(), seen.end(), hit.materialId) == seen.end();
    if (hit.lightIndex < 0 && boundsMedium(hit) && firstMeeting) {
      seen.push_back(hit.materialId);
      if (walk.leaving(hit)) enclosing.push_back(hit.materialId);
    }
    walk.cross(hit);
  }
  MediumStack media;
  for (auto id = enclosing.rbegin(); id != enclosing.rend(); ++id) crossInterface(media, *id, true);
  return media;
}

// Schmidt & Budge 2002 (medium_stack.hpp): false interfaces are crossed without scattering; only
// the media the path is in change. Without priorities every surface is real.
PathIntegrator::Trace PathIntegrator::traceToRealSurface(Ray& ray, SurfaceHit& hit, MediumStack& media,
                                                         PathCounters& counters) const {
  SegmentWalk walk(scene_, ray);
  const auto stop = [&](Trace trace) {
    ray = walk.ray();
    return trace;
  };
  for (int skipped = 0;; ++skipped) {
    if (!walk.next(hit, counters.rays)) return stop(Trace::Miss);
    hit.distance += walk.travelled();  // so that hit.distance (the depth AOV) counts from the real origin
    const bool entering = walk.entering(hit);
    if (!mediumInterface(media, hit, entering).isFalse) return stop(Trace::Hit);
    if (skipped == kMaxFalseInterfaces) return stop(Trace::Lost);
    crossInterface(media, hit.materialId, entering);
    walk.cross(hit);
  }
}

PathIntegrator::DirectLight PathIntegrator::sampleDirectLight(const Vertex& v, const MediumStack& media,
                                                             PixelSampler& sampler, PathCounters& counters) const {
  const std::array<float, 4> light4 = sampler.get4D();  // the light's choice, the point on it
  const float uSelect = light4[0];
  const Vec2 u(light4[1], light4[2]);
  if (v.bsdf->isPureSpecular() || lights_.empty()) return {};
  const LightSample light = lights_.sample(v.position, uSelect, u);
  if (light.pdf <= 0.0f || (light.radiance <= 0.0f).all()) return {};

  const Vec3 wiLocal = v.frame.toLocal(light.direction);
  DirectLight direct{Color::Zero(), light.lightIndex, wiLocal};
  // No leaks: the shading frame and the geometric surface must agree on reflect vs transmit.
  const bool geometricReflect = reflectsGeometrically(v.wo, light.direction, v.geometricNormal);
  if (geometricReflect != reflectsInShadingFrame(v.woLocal, wiLocal)) return {};
  // A shadow ray through a (rough) dielectric starts in the media on the far side.
  MediumStack shadowMedia = media;
  if (!geometricReflect && !v.thinSheet) crossInterface(shadowMedia, v.materialId, v.entering);

  const Color f = v.bsdf->eval(v.woLocal, wiLocal) * absCosTheta(wiLocal);
  if ((f <= 0.0f).all()) return {};
  const Vec3 origin = offsetOrigin(v.position, v.geometricNormal, light.direction);
  const float maxDistance = std::isinf(light.distance) ? light.distance : light.distance * (1.0f - 1e-4f);
  ++counters.rays;
  const bool blocked = scene_.occluded(origin, light.direction, maxDistance, v.time);
  // Blocked with no dielectric on the way: something opaque (or another light) is in front, and
  // every caustics mode gives no light. The dielectrics' small BVH settles it without the full
  // hit that MNEE's seed or the transparent shadow would trace to find that out.
  if (blocked) {
    ++counters.rays;
    if (!scene_.dielectricOnSegment(origin, light.direction, maxDistance, v.time)) return {};
  }
  // MNEE seeds its chain with this straight shadow ray (so a sample whose straight direction
  // is below the surface, f = 0 above, finds no caustic either).
  if (blocked && frame_.settings.caustics == Caustics::Mnee)
    if (const std::optional<Color> caustic = manifoldDirectLight(v, light, shadowMedia, counters, direct.wiLocal)) {
      direct.radiance = *caustic;
      return direct;
    }
  bool crossedDielectric = false;
  const Color transmittance =
      blocked ? shadowTransmittance(Ray{origin, light.direction, v.time}, maxDistance, shadowMedia, crossedDielectric, counters)
              : Color::Ones();
  if ((transmittance <= 0.0f).all()) return {};
  // Through a dielectric, only this strategy counts the path (the BSDF strategy drops it, see
  // radiance()), so it takes the full weight. The BSDF strategy's density counts how likely the
  // path is to sample v.bsdf at all (Vertex::bsdfSamplingProbability).
  const float weight =
      crossedDielectric ? 1.0f
                        : powerHeuristic(light.pdf, v.bsdfSamplingProbability * v.bsdf->pdf(v.woLocal, wiLocal));
  direct.radiance = f * light.radiance * transmittance * (weight / light.pdf);
  return direct;
}

// Transparent shadows: a shadow ray that meets smooth dielectric surfaces (drops, the cornea)
// continues straight through them, keeping each one's Fresnel transmission. Without it, light
// reaches skin under a drop or the iris under the cornea only through BSDF-sampled paths that
// happen to hit a small light after refraction, which leaves those regions black and speckled.
// The straight line ignores refraction: the shadow of a drop is a soft, slightly dimmed shadow
// instead of a focused caustic (the bias, documented in docs/shot-format.md). Caustics::Mnee
// replaces it by the refracted connection (mnee_direct_light.cpp) for 1 or 2 interfaces and
// keeps it as the fallback for more.
// Nested dielectrics: false interfaces cost nothing (the BSDF path skips them too, so it stays
// the other MIS strategy); real ones transmit with the pair of indices present there.
Color PathIntegrator::shadowTransmittance(const Ray& shadowRay, float maxDistance, MediumStack media,
                                          bool& crossedDielectric, PathCounters& counters) const {
  const Vec3& direction = shadowRay.direction;
  if (frame_.settings.caustics == Caustics::Off) return Color::Zero();
  Color transmittance = Color::Ones();
  SegmentWalk walk(scene_, Ray{shadowRay.origin, direction, shadowRay.time}, maxDistance);
  for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
    SurfaceHit hit;
    if (!walk.next(hit, counters.rays) || walk.pastTheEnd(hit)) return transmittance;
    if (hit.lightIndex >= 0) return Color::Zero();
    const bool entering = walk.entering(hit);
    const bool thin = isThinSheet(hit);
    const InterfaceCrossing surface = mediumInterface(media, hit, entering);
    if (!surface.isFalse) {
      const Vec3 ns = onGeometricSide(hit.shadingNormal, hit.geometricNormal);
      const Vec3 woLocal = ShadingFrame::fromNormal(ns).toLocal(-direction);
      const Bsdf* bsdf = thin ? thinSheetBsdfs_[hit.materialId].get() : interfaceBsdf(hit.materialId, surface.otherMaterial);
      transmittance *= bsdf->straightTransmittance(woLocal);
      if ((transmittance <= 0.0f).all()) return Color::Zero();
      crossedDielectric = true;
    }
    if (thin) {  // on along the same line (see pastThinSheet)
      walk.crossThinSheet(hit);
      continue;
    }
    crossInterface(media, hit.materialId, entering);
    walk.cross(hit);
  }
  return Color::Zero();
}

FirstHitIds PathIntegrator::cryptomatteIdsOf(const SurfaceHit& hit) const {
  if (!frame_.settings.cryptomatte.any()) return {};  // only Cryptomatte reads them
  const int meshes = int(frame_.meshes.size()), spheres = int(frame_.spheres.size());
  if (hit.lightIndex >= 0)
    return {meshes + spheres + hit.lightIndex, int(frame_.materials.size()) + hit.lightIndex};
  const int object = hit.meshIndex >= 0 ? hit.meshIndex : hit.sphereIndex >= 0 ? meshes + hit.sphereIndex : -1;
  // As underSkinFilm: a film is rendered on skin only.
  const bool wet = hit.wetness > 0.0f && std::holds_alternative<SkinParams>(frame_.materials[hit.materialId].params);
  return {object, CryptomatteNames::materialIndex(frame_, hit.materialId, wet)};
}

Color PathIntegrator::radiance(const Ray& cameraRay, PixelSampler& sampler, FirstHit& firstHit,
                               PathCounters& counters, const RadianceSplits& splits) const {
  Color result = Color::Zero();
  // Every contribution goes to the beauty and, when asked, to its light's group.
  const auto gather = [&](const Color& contribution, int group) {
    result += contribution;
    if (splits.groups) splits.groups[size_t(group)] += contribution;
  };
  // And, when asked, to its light path (light_paths.hpp).
  LightPathSplit paths(splits.paths);
  Color throughput = Color::Ones();
  float etaScale = 1.0f;         // undoes the 1/eta^2 radiance scaling for Russian roulette
  bool previousSpecular = true;  // camera rays count as specular: no MIS on what they see
  // Since the last non-specular vertex, the path only went straight on through smooth
  // dielectrics (chainAfterNonSpecular) and crossed at least one (crossings > 0): a light it
  // hits now was already counted by transparent shadows, so it must not count twice.
  bool chainAfterNonSpecular = false;
  int crossings = 0;
  float previousBsdfPdf = 0.0f;
  float pathLength = 0.0f;  // metres travelled from the camera, for texture footprints
  Vec3 previousPosition = cameraRay.origin;
  Ray ray = cameraRay;
  MediumStack media = cameraMedia_;  // the dielectric media the path is in (nested dielectrics only)
  // The index of the closed dielectric (a bead, a rivulet) the path refracted into and has not
  // left, 1 in air (the innermost entered; nested media are not unwound here). Skin met inside is
  // wetted by that water, which is its film (see underSkinFilm), and its surface meets a medium of
  // that index (see skinAtHit). A dielectric of index 1 is air to the skin as well.
  float surroundingIor = 1.0f;
  BounceCounter bounces(frame_.settings.bounces);
  // A bounce limit was passed: this segment gathers the light it meets, then the path ends.
  bool lastSegment = false;
  // The path has scattered diffusely (a Lambertian lobe or a subsurface exit's) at least once.
  bool diffuseAncestor = false;

  for (int depth = 0;; ++depth) {
    SurfaceHit hit;
    const Trace trace = traceToRealSurface(ray, hit, media, counters);
    if (trace == Trace::Lost) break;
    if (trace == Trace::Miss) {
      // A uniform background is not light-sampled, so only the environment map can be counted twice.
      if (lights_.environmentIsSampled() && countedByTransparentShadows(chainAfterNonSpecular, crossings)) break;
      Color contribution;
      if (previousSpecular) {
        contribution = throughput * lights_.background(ray.direction);
      } else {
        const LightSampler::Background background = lights_.backgroundWithPdf(ray.direction);
        contribution = throughput * background.radiance * powerHeuristic(previousBsdfPdf, background.pdf);
      }
      gather(contribution, groups_.environment);
      paths.lightHit(contribution, depth, LightPath::Environment);
      break;
    }
    if (hit.lightIndex >= 0) {
      if (countedByTransparentShadows(chainAfterNonSpecular, crossings)) break;
      const Color emitted = lights_.emitted(hit.lightIndex, -ray.direction);
      const float lightPdf = lights_.pdfAreaLight(hit.lightIndex, previousPosition, hit.position, hit.geometricNormal);
      const float weight = previousSpecular ? 1.0f : powerHeuristic(previousBsdfPdf, lightPdf);
      const Color contribution = throughput * emitted * weight;
      gather(contribution, groups_.ofLight[size_t(hit.lightIndex)]);
      paths.lightHit(contribution, depth, LightPath::Emission);
      if (depth == 0) firstHit = {true, emitted.cwiseMin(1.0f), hit.geometricNormal, hit.distance, cryptomatteIdsOf(hit)};
      break;
    }

    // Subsurface skin met after a diffuse bounce shades with its Lambertian base instead (as
    // Cycles does, svm_closure.h: "can't see it well then and adds considerably noise"): light
    // that has scattered diffusely once no longer shows the skin's blur of a millimetre, and each
    // probe there costs a ray query, a second light sample and the noise of its weight.
    const SubsurfaceSkin* subsurface = subsurface_[hit.materialId] ? &*subsurface_[hit.materialId] : nullptr;
    const bool skinAsDiffuse = subsurface && diffuseAncestor;
    if (skinAsDiffuse) subsurface = nullptr;
    const Material& material = skinAsDiffuse ? subsurface_[hit.materialId]->asDiffuse : frame_.materials[hit.materialId];
    pathLength += hit.distance - ray.tnear;
    Vertex v;
    v.position = hit.position;
    v.wo = -ray.direction;
    v.time = ray.time;
    v.materialId = hit.materialId;
    Vec3 ng = hit.geometricNormal;
    Vec3 ns = onGeometricSide(hit.shadingNormal, ng);  // interpolated normals follow the winding's side
    const bool frontFacing = v.wo.dot(ng) > 0.0f;
    v.entering = frontFacing;
    v.thinSheet = isThinSheet(hit);
    v.bsdf = skinAsDiffuse ? subsurface_[hit.materialId]->asDiffuseBsdf.get() : bsdfs_[hit.materialId].get();
    if (v.thinSheet)
      v.bsdf = thinSheetBsdfs_[hit.materialId].get();
    else if (nested_ && isDielectric(hit.materialId))
      v.bsdf = interfaceBsdf(hit.materialId, classifyInterface(media, hit.materialId, frontFacing).otherMaterial);
    TexturedHit textured;  // v.bsdf may point here for this bounce
    v.bsdf = withTextures(v.bsdf, textures_, material, hit, pathLength * pixelSpread_, textured);
    v.bsdf = skinAtHit(v.bsdf, material, hit.position, surroundingIor, textured);
    std::optional<WetSkinBsdf> wetSkin;  // v.bsdf may point here for this bounce
    v.bsdf = underSkinFilm(v.bsdf, material, surroundingIor != 1.0f ? 0.0f : hit.wetness, wetSkin);
    if (!v.bsdf->isTransmissive()) {
      // Opaque surfaces are two-sided: shade the side the ray arrives from.
      if (!frontFacing) { ng = -ng; ns = -ns; }
      if (textured.values.normal) ns = applyNormalMap(*textured.values.normal, ns, hit.dpdu, hit.dpdv);
      // Fine-scale relief of the material (skin pores); ns unchanged for other materials.
      ns = v.bsdf->perturbShadingNormal(hit.position, ns, ng);
      // A shading normal that hides wo would make the surface black or leak: fall back to ng.
      if (v.wo.dot(ns) <= 0.0f) ns = ng;
    }
    v.geometricNormal = ng;
    v.frame = ShadingFrame::fromNormal(ns);
    v.woLocal = v.frame.toLocal(v.wo);

    if (depth == 0) firstHit = {true, v.bsdf->albedo(), ns, hit.distance, cryptomatteIdsOf(hit)};
    // Emissive opaque materials emit from both sides (an emitting box seen from inside).
    if ((material.emission > 0.0f).any() && (frontFacing || !v.bsdf->isTransmissive())) {
      const Color contribution = throughput * material.emission;
      gather(contribution, groups_.emission);
      paths.lightHit(contribution, depth, LightPath::Emission);
    }
    if (depth >= maxDepth_ || lastSegment) break;

    // Subsurface skin: the path goes on by v.bsdf's lobes with probability pSurface, else from the
    // exit below (scatterBelowSurface); the light samples' MIS weights count that probability in
    // the BSDF technique's density (Vertex::bsdfSamplingProbability; Veach 1997, section 9.2: a
    // technique's density is that of the samples it actually draws). Without it, light that the
    // specular lobes find by sampling counted 1 / pSurface times (~10x) where it was found: the
    // skin's specular sheen had 2.8x the noise of the Lambertian skin's, at the same mean.
    const SkinParams* beneath = nullptr;  // the skin below: its own, or a textured hit's (TexturedHit)
    const SkinBsdf* surface = nullptr;
    if (subsurface) {
      beneath = textured.skin ? &*textured.skin : &subsurface->params;
      surface = textured.skin ? &std::get<SkinBsdf>(textured.bsdf) : subsurface->bsdf.get();
      v.bsdfSamplingProbability = surfaceProbability(*surface, wetSkin ? &*wetSkin : nullptr, v);
    }
    const uint32_t dimensions = sample_dimensions::bounceBase(depth);
    sampler.setDimension(dimensions + sample_dimensions::kLight);
    const DirectLight direct = sampleDirectLight(v, media, sampler, counters);
    gather(throughput * direct.radiance, groups_.ofSource(direct.source));
    if (depth > 0)
      paths.afterFirstBounce(throughput * direct.radiance, false);
    else if (paths.active() && (direct.radiance != 0.0f).any())  // lobes only where light arrived
      paths.firstVertexDirect(throughput * direct.radiance, v.bsdf->evalLobes(v.woLocal, direct.wiLocal));
    if (subsurface) {  // skin with subsurface: v.bsdf's lobes or a random walk
      sampler.setDimension(dimensions + sample_dimensions::kSubsurfaceChoice);
      const Below below = scatterBelowSurface(*subsurface, *beneath, *surface, wetSkin ? &*wetSkin : nullptr, v,
                                              v.bsdfSamplingProbability, sampler, counters);
      if (below.exit) {  // the light that leaves at the exit, whichever way the path goes on
        sampler.setDimension(dimensions + sample_dimensions::kExitLight);
        const DirectLight exitDirect = sampleDirectLight(*below.exit, media, sampler, counters);
        const Color contribution = throughput * below.exitWeight * exitDirect.radiance;
        gather(contribution, groups_.ofSource(exitDirect.source));
        if (depth == 0) paths.belowFirstVertex(contribution);
        else paths.afterFirstBounce(contribution, false);
      }
      if (!below.goesBelow) {
        throughput /= below.pSurface;
      } else {
        if (!below.exit) break;  // absorbed below the skin
        if (depth == 0) paths.leftBelowTheSkin();
        throughput *= below.exitWeight / (1.0f - below.pSurface);
        v = *below.exit;
        hit.position = v.position;  // the path goes on from the exit point
        ng = v.geometricNormal;
      }
    }

    sampler.setDimension(dimensions + sample_dimensions::kBsdf);
    const std::array<float, 4> u = sampler.get4D();  // the lobe, the direction
    const std::optional<BsdfSample> bs = v.bsdf->sample(v.woLocal, u[0], Vec2(u[1], u[2]));
    if (!bs || bs->pdf <= 0.0f) break;
    const Vec3 wi = v.frame.toWorld(bs->wi).normalized();
    if (reflectsGeometrically(v.wo, wi, ng) == bs->transmitted) break;  // the shading normal sent it through the surface
    lastSegment = bounces.countIsOverLimit(*bs);
    if (depth == 0 && paths.active()) {
      if (bs->specular) paths.leftByDeltaLobe(bs->transmitted);
      else paths.leftWithLobes(v.bsdf->evalLobes(v.woLocal, bs->wi));
    }
    throughput *= bs->f * (absCosTheta(bs->wi) / bs->pdf);
    if (bs->transmitted) {
      etaScale *= bs->eta * bs->eta;
      if (!v.thinSheet) {
        crossInterface(media, hit.materialId, frontFacing);
        if (isDielectric(hit.materialId)) surroundingIor = frontFacing ? media_[hit.materialId]->ior : 1.0f;
      }
    }
    if (!bs->specular) {
      chainAfterNonSpecular = true;
      crossings = 0;
    } else if (bs->transmitted && (v.bsdf->straightTransmittance(v.woLocal) > 0.0f).any()) {
      ++crossings;
    } else {
      chainAfterNonSpecular = false;  // a mirror bounce: shadow rays never follow it
    }
    if (!bs->specular && !bs->glossy && !bs->transmitted) diffuseAncestor = true;
    previousSpecular = bs->specular;
    previousBsdfPdf = bs->pdf * v.bsdfSamplingProbability;
    previousPosition = hit.position;
    ray = v.thinSheet && bs->transmitted ? pastThinSheet(ray, hit.rayDistance) : Ray{offsetOrigin(hit.position, ng, wi), wi, ray.time};

    if (depth >= kRussianRouletteDepth) {
      const float survive = std::min(1.0f, (throughput * etaScale).maxCoeff());
      sampler.setDimension(dimensions + sample_dimensions::kRoulette);
      if (sampler.get1D() >= survive) break;
      throughput /= survive;
    }
    if ((throughput <= 0.0f).all()) break;
  }
  return result;
}

// Subsurface scattering (subsurface_walk.hpp, subsurface_probe.hpp). v.bsdf holds the skin's
// specular lobes (and, under a tear film, the film's coat: wet_skin.hpp, "Subsurface skin"); the
// walk or probe replaces the Lambertian base, dry or under the film. Every sample finds an exit
// and takes the light there, weighted by the light that crosses into the skin, 1 - F(cos_o) (dry)
// or WetSkinBsdf::belowTransmission (wet), times the method's weight: the light through the skin
// is split off the path, as the light at any vertex is (NEE). One of the two then continues the
// path: v.bsdf with probability pB = specularProbability(wo) (dry) or 1 - belowProbability(wo)
// (wet), else the exit, weighted 1 / (1 - pB). Each branch divides by its probability, so the sum
// is unbiased, and the light found by the continuation pairs with the NEE of its own vertex by MIS
// as before.
std::optional<PathIntegrator::SubsurfaceSkin> PathIntegrator::makeSubsurfaceSkin(const Material& material) {
  const auto* skin = std::get_if<SkinParams>(&material.params);
  if (!skin || !skin->subsurface) return std::nullopt;
  Material asDiffuse = material;
  std::get<SkinParams>(asDiffuse.params).subsurface.reset();
  std::shared_ptr<const Bsdf> asDiffuseBsdf = makeBsdf(asDiffuse.params);
  return SubsurfaceSkin{*skin,        std::make_shared<SkinBsdf>(*skin), std::make_shared<SubsurfaceExitBsdf>(skin->ior),
                        skin->ior,    std::move(asDiffuse),              std::move(asDiffuseBsdf)};
}

float PathIntegrator::surfaceProbability(const SkinBsdf& surface, const WetSkinBsdf* wet, const Vertex& v) {
  const float pBelow = wet ? wet->belowProbability(v.woLocal) : 1.0f - surface.specularProbability(v.woLocal);
  return 1.0f - pBelow;
}

PathIntegrator::Below PathIntegrator::scatterBelowSurface(const SubsurfaceSkin& skin, const SkinParams& below,
                                                          const SkinBsdf& surface, const WetSkinBsdf* wet,
                                                          const Vertex& v, float pSurface, PixelSampler& sampler,
                                                          PathCounters& counters) const {
  Below result;
  result.pSurface = pSurface;
  // The walk's independent stream is keyed by the dimension just past the choice's first.
  const uint32_t walkStream = sampler.dimension() + 1;
  // One stratified 4D block: the choice (and, rescaled, the probe's radius), then the probe's
  // channel and axis, its angle and its candidate (the walk draws its own numbers).
  const std::array<float, 4> uBelow = sampler.get4D();
  const float uChoice = uBelow[0];
  result.goesBelow = uChoice >= result.pSurface;
  // The choice's number, uniform again on [0, 1) within its branch: stratified for the probe's radius.
  const float uRadius = std::min(result.goesBelow ? (uChoice - result.pSurface) / (1.0f - result.pSurface)
                                                  : uChoice / result.pSurface,
                                 0.99999994f);
  const ProbeNumbers probe{uBelow[1], uRadius, uBelow[2], uBelow[3]};
  const auto exit = findSubsurfaceExit(below, v, probe, sampler.independentStream(walkStream), counters);
  if (!exit) return result;
  // Entry pays the Fresnel transmission of the base it replaces (skin.hpp, subsurface.hpp): of the
  // skin's surface (against water under a drop: skinAtHit), and of the film's top where wet.
  const float entry =
      wet ? wet->belowTransmission(v.woLocal) : 1.0f - fresnelDielectric(v.woLocal.z(), surface.ior());
  result.exitWeight = exit->weight * entry;
  Vertex& out = result.exit.emplace(v);
  out.position = exit->position;
  out.geometricNormal = exit->geometricNormal;
  out.frame = ShadingFrame::fromNormal(exit->shadingNormal);
  out.wo = exit->shadingNormal;  // the exit lobe ignores wo; any direction above the surface will do
  out.woLocal = Vec3(0.0f, 0.0f, 1.0f);
  out.bsdf = skin.exitBsdf.get();
  out.entering = true;
  out.bsdfSamplingProbability = 1.0f - pSurface;  // the path goes on from the exit otherwise
  return result;
}

std::optional<SubsurfaceExit> PathIntegrator::findSubsurfaceExit(const SkinParams& below, const Vertex& v,
                                                                  const ProbeNumbers& probe, PixelSampler walkStream,
                                                                  PathCounters& counters) const {
  if (below.subsurface->method == SubsurfaceMethod::RandomWalk)
    return walkBelowSurface(scene_, subsurfaceMedium(below, *below.subsurface), dielectricIndex_, v.position,
                            v.geometricNormal, v.time, walkStream, counters.rays);
  const DiffusionProfile profile(below.albedo, below.subsurface->meanFreePath);
  return probeDiffusionExit(scene_, profile, {v.materialId, v.entering}, dielectricIndex_, v.position,
                            v.geometricNormal, v.time, probe, counters.rays);
}

}  // namespace lacrima
