// Random-walk subsurface scattering (Chiang, Kutz & Burley 2016), free-flight sampling after
// Pharr, Jakob & Humphreys, pbrt-v4 §11.2 and §14.1 (homogeneous medium, spectral MIS).
#include "subsurface_walk.hpp"

#include <cmath>

#include "lacrima/materials/sampling.hpp"
#include "ray_offset.hpp"
#include "segment_walk.hpp"
#include "shading_side.hpp"

namespace lacrima {

namespace {

// Channel probabilities proportional to the walk's weight so far (as Cycles' random walk does):
// a channel that has been absorbed is no longer sampled. Any choice that depends only on the past
// keeps the one-sample MIS estimator unbiased.
Color channelProbabilities(const Color& weight) {
  const float sum = weight.sum();
  return sum > 0.0f ? Color(weight / sum) : Color::Zero();
}

enum class FlightEnd { Scattered, Surface, Lost };

// Follows a free flight of length `distance`: Surface when it meets a surface that ends the walk
// first (hit.distance then counts from ray.origin), Scattered when it does not. Surfaces of
// dielectrics (a drop sitting on the skin reaches into it) are crossed as if absent. Lost when
// nothing is hit (an open mesh) or too many surfaces were crossed.
FlightEnd flyToSurface(const EmbreeScene& scene, const std::vector<float>& dielectricIndex, Ray ray, float distance,
                       SurfaceHit& hit, uint64_t& rays) {
  constexpr int kMaxCrossed = 16;
  SegmentWalk walk(scene, ray);
  for (int crossed = 0; crossed <= kMaxCrossed; ++crossed) {
    if (!walk.next(hit, rays)) return FlightEnd::Lost;
    if (walk.travelled() + hit.distance > distance) return FlightEnd::Scattered;
    if (hit.lightIndex >= 0 || dielectricIndex[hit.materialId] == 0.0f) {
      hit.distance += walk.travelled();
      return FlightEnd::Surface;
    }
    walk.cross(hit);
  }
  return FlightEnd::Lost;
}

}  // namespace

int pickChannel(const Color& probabilities, float u) {
  int last = 0;
  float cumulative = 0.0f;
  for (int c = 0; c < 3; ++c) {
    if (probabilities[c] <= 0.0f) continue;
    last = c;
    cumulative += probabilities[c];
    if (u < cumulative) return c;
  }
  return last;
}

float indexOutsideSkin(const EmbreeScene& scene, const std::vector<float>& dielectricIndex, const Vec3& position,
                       const Vec3& outwardNormal, float time, uint64_t& rays) {
  // The dielectrics alone first: most skin lies under none, and their small BVH answers that
  // without descending the skin's (measured: the two lookups of a probe were 11 % of a frame).
  SurfaceHit hit;
  ++rays;
  const Ray probe{offsetOrigin(position, outwardNormal, outwardNormal), outwardNormal, time};
  if (!scene.intersectDielectrics(probe, hit)) return 1.0f;
  const float index = dielectricIndex[hit.materialId];
  if (!(index > 0.0f) || hit.geometricNormal.dot(outwardNormal) <= 0.0f) return 1.0f;  // outside it
  // Inside that dielectric, unless another surface (an eyelash, the sclera) comes first: then,
  // as with one query over everything, the nearest surface decides and it is not the water's.
  ++rays;
  return scene.occluded(probe.origin, probe.direction, hit.rayDistance * (1.0f - 1e-4f), time) ? 1.0f : index;
}

std::optional<SubsurfaceExit> walkBelowSurface(const EmbreeScene& scene, const SubsurfaceMedium& medium,
                                               const std::vector<float>& dielectricIndex, const Vec3& entry,
                                               const Vec3& outwardNormal, float time,
                                               PixelSampler& sampler, uint64_t& rays) {
  // Lambertian entry: cosine-distributed about the inward normal (subsurface.hpp).
  const Vec3 entryDirection = sampleCosineHemisphere(sampler.get2D());
  Vec3 direction = ShadingFrame::fromNormal(-outwardNormal).toWorld(entryDirection).normalized();
  Vec3 position = offsetOrigin(entry, outwardNormal, direction);
  const Color sigmaS = medium.sigmaS();
  Color weight = Color::Ones();
  const float entryIndex = indexOutsideSkin(scene, dielectricIndex, entry, outwardNormal, time, rays);
  for (int step = 0; step < kMaxSubsurfaceSteps; ++step) {
    const Color probabilities = channelProbabilities(weight);
    if ((probabilities <= 0.0f).all()) return std::nullopt;
    const int channel = pickChannel(probabilities, sampler.get1D());
    // Free flight in the chosen channel: t ~ sigma_t exp(-sigma_t t) (pbrt-v4 §11.2.2 SampleExponential).
    const float distance = -std::log1p(-sampler.get1D()) / medium.sigmaT[channel];
    SurfaceHit hit;
    const FlightEnd end = flyToSurface(scene, dielectricIndex, Ray{position, direction, time}, distance, hit, rays);
    if (end == FlightEnd::Lost) return std::nullopt;
    if (end == FlightEnd::Surface) {
      // Left the medium: P(flight > d) = sum_c p_c exp(-sigma_t,c d) over the channel mixture.
      if (hit.lightIndex >= 0) return std::nullopt;
      const Color transmittance = (-medium.sigmaT * hit.distance).exp();
      const float pdf = (probabilities * transmittance).sum();
      if (pdf <= 0.0f) return std::nullopt;
      weight *= transmittance / pdf;
      const Vec3 ng = hit.geometricNormal.dot(direction) > 0.0f ? hit.geometricNormal : Vec3(-hit.geometricNormal);
      const Vec3 ns = onGeometricSide(hit.shadingNormal, ng);
      // Radiance scales with the square of the index of the medium it is in (L / n^2 is conserved,
      // pbrt-v4 §9.5.2): a walk from under a drop out into air, or back, carries that ratio.
      const float ratio = entryIndex / indexOutsideSkin(scene, dielectricIndex, hit.position, ng, time, rays);
      weight *= ratio * ratio;
      return SubsurfaceExit{hit.position, ng, ns, weight};
    }
    // Scattered: weight sigma_s T(t) / p(t), p(t) = sum_c p_c sigma_t,c exp(-sigma_t,c t) (pbrt-v4 §14.1.3).
    const Color transmittance = (-medium.sigmaT * distance).exp();
    const float pdf = (probabilities * medium.sigmaT * transmittance).sum();
    if (pdf <= 0.0f) return std::nullopt;
    weight *= sigmaS * transmittance / pdf;
    position += distance * direction;
    direction = sampleUniformSphere(sampler.get2D());  // isotropic phase function
  }
  return std::nullopt;  // the step cap (kMaxSubsurfaceSteps): absorbed, the documented bias
}

}  // namespace lacrima
