#include "integrator.hpp"

#include <limits>

namespace lacrima {

namespace {

// Veach 1997, eq. 9.13 (power heuristic, beta = 2).
float powerHeuristic(float pdfA, float pdfB) {
  const float a = pdfA * pdfA, b = pdfB * pdfB;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

// Ray origins are pushed off the surface along the geometric normal, on the side the new ray
// leaves towards; the offset scales with the coordinates' magnitude (float spacing).
Vec3 offsetOrigin(const Vec3& position, const Vec3& geometricNormal, const Vec3& direction) {
  const float scale = 1e-4f * std::max(0.05f, position.cwiseAbs().maxCoeff());
  return position + (direction.dot(geometricNormal) > 0.0f ? scale : -scale) * geometricNormal;
}

constexpr int kRussianRouletteDepth = 3;
// A shadow ray gives up (counts as blocked) after this many dielectric crossings.
constexpr int kMaxShadowCrossings = 16;

}  // namespace

bool PathIntegrator::countedByTransparentShadows(bool chainAfterNonSpecular, int crossings) const {
  return frame_.settings.transparentShadows && chainAfterNonSpecular && crossings > 0;
}

struct PathIntegrator::Vertex {
  Vec3 position;
  Vec3 geometricNormal;  // oriented as the shading frame's side (see orientNormals)
  ShadingFrame frame;
  Vec3 wo;               // world, towards the previous vertex
  Vec3 woLocal;
  const Bsdf* bsdf;
  float time;            // shutter time of the path
};

PathIntegrator::PathIntegrator(const Frame& frame, const EmbreeScene& scene, const LightSampler& lights)
    : frame_(frame), scene_(scene), lights_(lights), maxDepth_(frame.settings.maxDepth) {
  bsdfs_.reserve(frame.materials.size());
  for (const Material& material : frame.materials) bsdfs_.push_back(makeBsdf(material.params));
}

Color PathIntegrator::sampleDirectLight(const Vertex& v, PixelSampler& sampler, PathCounters& counters) const {
  const float uSelect = sampler.get1D();
  const Vec2 u = sampler.get2D();
  if (v.bsdf->isPureSpecular() || lights_.empty()) return Color::Zero();
  const LightSample light = lights_.sample(v.position, uSelect, u);
  if (light.pdf <= 0.0f || (light.radiance <= 0.0f).all()) return Color::Zero();

  const Vec3 wiLocal = v.frame.toLocal(light.direction);
  // No leaks: the shading frame and the geometric surface must agree on reflect vs transmit.
  const bool geometricReflect = light.direction.dot(v.geometricNormal) * v.wo.dot(v.geometricNormal) > 0.0f;
  const bool shadingReflect = wiLocal.z() * v.woLocal.z() > 0.0f;
  if (geometricReflect != shadingReflect) return Color::Zero();

  const Color f = v.bsdf->eval(v.woLocal, wiLocal) * absCosTheta(wiLocal);
  if ((f <= 0.0f).all()) return Color::Zero();
  const Vec3 origin = offsetOrigin(v.position, v.geometricNormal, light.direction);
  const float maxDistance = std::isinf(light.distance) ? light.distance : light.distance * (1.0f - 1e-4f);
  bool crossedDielectric = false;
  const Color transmittance =
      shadowTransmittance(Ray{origin, light.direction, v.time}, maxDistance, crossedDielectric, counters);
  if ((transmittance <= 0.0f).all()) return Color::Zero();
  // Through a dielectric, only this strategy counts the path (the BSDF strategy drops it, see
  // radiance()), so it takes the full weight.
  const float weight = crossedDielectric ? 1.0f : powerHeuristic(light.pdf, v.bsdf->pdf(v.woLocal, wiLocal));
  return f * light.radiance * transmittance * (weight / light.pdf);
}

// Transparent shadows: a shadow ray that meets smooth dielectric surfaces (drops, the cornea)
// continues straight through them, keeping each one's Fresnel transmission. Without it, light
// reaches skin under a drop or the iris under the cornea only through BSDF-sampled paths that
// happen to hit a small light after refraction, which leaves those regions black and speckled.
// The straight line ignores refraction: the shadow of a drop is a soft, slightly dimmed shadow
// instead of a focused caustic (the bias, documented in docs/shot-format.md). Caustics need
// manifold next-event estimation (a later issue).
Color PathIntegrator::shadowTransmittance(const Ray& shadowRay, float maxDistance, bool& crossedDielectric,
                                          PathCounters& counters) const {
  const Vec3& direction = shadowRay.direction;
  ++counters.rays;
  if (!scene_.occluded(shadowRay.origin, direction, maxDistance, shadowRay.time)) return Color::Ones();
  if (!frame_.settings.transparentShadows) return Color::Zero();
  Color transmittance = Color::Ones();
  Vec3 position = shadowRay.origin;
  float remaining = maxDistance;
  for (int crossing = 0; crossing < kMaxShadowCrossings; ++crossing) {
    SurfaceHit hit;
    ++counters.rays;
    if (!scene_.intersect(Ray{position, direction, shadowRay.time}, hit) || hit.distance >= remaining) return transmittance;
    if (hit.lightIndex >= 0) return Color::Zero();
    Vec3 ns = hit.shadingNormal.dot(hit.geometricNormal) < 0.0f ? -hit.shadingNormal : hit.shadingNormal;
    const Vec3 woLocal = ShadingFrame::fromNormal(ns).toLocal(-direction);
    transmittance *= bsdfs_[hit.materialId]->straightTransmittance(woLocal);
    if ((transmittance <= 0.0f).all()) return Color::Zero();
    crossedDielectric = true;
    const Vec3 next = offsetOrigin(hit.position, hit.geometricNormal, direction);
    remaining -= (next - position).dot(direction);
    position = next;
  }
  return Color::Zero();
}

Color PathIntegrator::radiance(const Ray& cameraRay, PixelSampler& sampler, FirstHit& firstHit,
                               PathCounters& counters) const {
  Color result = Color::Zero();
  Color throughput = Color::Ones();
  float etaScale = 1.0f;         // undoes the 1/eta^2 radiance scaling for Russian roulette
  bool previousSpecular = true;  // camera rays count as specular: no MIS on what they see
  // Since the last non-specular vertex, the path only went straight on through smooth
  // dielectrics (chainAfterNonSpecular) and crossed at least one (crossings > 0): a light it
  // hits now was already counted by transparent shadows, so it must not count twice.
  bool chainAfterNonSpecular = false;
  int crossings = 0;
  float previousBsdfPdf = 0.0f;
  Vec3 previousPosition = cameraRay.origin;
  Ray ray = cameraRay;

  for (int depth = 0;; ++depth) {
    SurfaceHit hit;
    ++counters.rays;
    if (!scene_.intersect(ray, hit)) {
      // A uniform background is not light-sampled, so only the environment map can be counted twice.
      if (lights_.environmentIsSampled() && countedByTransparentShadows(chainAfterNonSpecular, crossings)) break;
      const Color background = lights_.background(ray.direction);
      const float weight = previousSpecular ? 1.0f : powerHeuristic(previousBsdfPdf, lights_.pdfEnvironment(ray.direction));
      result += throughput * background * weight;
      break;
    }
    if (hit.lightIndex >= 0) {
      if (countedByTransparentShadows(chainAfterNonSpecular, crossings)) break;
      const Color emitted = lights_.emitted(hit.lightIndex, -ray.direction);
      const float lightPdf = lights_.pdfAreaLight(hit.lightIndex, previousPosition, hit.position, hit.geometricNormal);
      const float weight = previousSpecular ? 1.0f : powerHeuristic(previousBsdfPdf, lightPdf);
      result += throughput * emitted * weight;
      if (depth == 0) firstHit = {true, emitted.cwiseMin(1.0f), hit.geometricNormal, hit.distance};
      break;
    }

    const Material& material = frame_.materials[hit.materialId];
    Vertex v;
    v.bsdf = bsdfs_[hit.materialId].get();
    v.position = hit.position;
    v.wo = -ray.direction;
    v.time = ray.time;
    Vec3 ng = hit.geometricNormal;
    Vec3 ns = hit.shadingNormal;
    if (ns.dot(ng) < 0.0f) ns = -ns;  // interpolated normals follow the winding's side
    const bool frontFacing = v.wo.dot(ng) > 0.0f;
    if (!v.bsdf->isTransmissive()) {
      // Opaque surfaces are two-sided: shade the side the ray arrives from.
      if (!frontFacing) { ng = -ng; ns = -ns; }
      // Fine-scale relief of the material (skin pores); ns unchanged for other materials.
      ns = v.bsdf->perturbShadingNormal(hit.position, ns, ng);
      // A shading normal that hides wo would make the surface black or leak: fall back to ng.
      if (v.wo.dot(ns) <= 0.0f) ns = ng;
    }
    v.geometricNormal = ng;
    v.frame = ShadingFrame::fromNormal(ns);
    v.woLocal = v.frame.toLocal(v.wo);

    if (depth == 0) firstHit = {true, v.bsdf->albedo(), ns, hit.distance};
    // Emissive opaque materials emit from both sides (an emitting box seen from inside).
    if ((material.emission > 0.0f).any() && (frontFacing || !v.bsdf->isTransmissive()))
      result += throughput * material.emission;
    if (depth >= maxDepth_) break;

    result += throughput * sampleDirectLight(v, sampler, counters);

    const float uLobe = sampler.get1D();
    const std::optional<BsdfSample> bs = v.bsdf->sample(v.woLocal, uLobe, sampler.get2D());
    if (!bs || bs->pdf <= 0.0f) break;
    const Vec3 wi = v.frame.toWorld(bs->wi).normalized();
    const bool geometricReflect = wi.dot(ng) * v.wo.dot(ng) > 0.0f;
    if (geometricReflect == bs->transmitted) break;  // the shading normal sent it through the surface
    throughput *= bs->f * (absCosTheta(bs->wi) / bs->pdf);
    if (bs->transmitted) etaScale *= bs->eta * bs->eta;
    if (!bs->specular) {
      chainAfterNonSpecular = true;
      crossings = 0;
    } else if (bs->transmitted && (v.bsdf->straightTransmittance(v.woLocal) > 0.0f).any()) {
      ++crossings;
    } else {
      chainAfterNonSpecular = false;  // a mirror bounce: shadow rays never follow it
    }
    previousSpecular = bs->specular;
    previousBsdfPdf = bs->pdf;
    previousPosition = hit.position;
    ray = Ray{offsetOrigin(hit.position, ng, wi), wi, ray.time};

    if (depth >= kRussianRouletteDepth) {
      const float survive = std::min(1.0f, (throughput * etaScale).maxCoeff());
      if (sampler.get1D() >= survive) break;
      throughput /= survive;
    }
    if ((throughput <= 0.0f).all()) break;
  }
  return result;
}

}  // namespace lacrima
