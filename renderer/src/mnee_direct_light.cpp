// Manifold next-event estimation in the path tracer (Caustics::Mnee): Hanika, Droske & Fascione
// 2015, "Manifold Next Event Estimation", CGF 34(4). The straight shadow ray towards a light
// sample seeds a specular chain through the smooth dielectric interfaces it crosses (as Cycles'
// "shadow caustics" do); the solver (specular_manifold.hpp) bends it into the refracted path.
//
// Estimator (derivation): direct light at x0 through the chain, integrated over the light's area,
//   L = int_A(y) f(x0, w0) |cos theta_0| T(chain) Le(y) |d w0 / d A(y)| dA(y),
// since radiance along a specular chain is Le times the chain's Fresnel transmissions with
// their n^2 radiance scalings (T, as the BSDF strategy's weights), and the direction w0 at x0
// is a function of y. |d w0 / d A(y)| is the generalized geometry term without the cosine at x0
// (manifoldGeometryTerm, Jakob & Marschner 2012 sec. 4.3). One sample y with area density p_A(y):
//   L ~ f |cos theta_0| T Le G / p_A(y),   p_A(y) = p_omega(seed) |cos theta_y| / |y - x0|^2,
// the light sampler's solid-angle density of the straight seed direction converted to area at y
// (the seed's geometry, which is how y was drawn). For the environment, the end is the fixed
// direction d, G is per unit solid angle of d and p is the sampler's solid-angle density of d.
// With no specular vertex G = |cos theta_y| / |y - x0|^2 and this is plain next-event estimation.
//
// MIS: the BSDF strategy drops every path that reaches a light through smooth dielectrics after
// a non-specular vertex (countedByTransparentShadows), so this one takes the full weight.
// Limits (documented in docs/shot-format.md): one solution per seed (Newton finds at most one
// of several refracted paths); a light focused onto points whose straight shadow ray misses the
// drop is not found; a failed solve contributes nothing (except under a tear lying on the
// receiver, where the straight transparent shadow stands in); more than 2 interfaces fall back to
// the straight transparent shadow.
#include <array>

#include "integrator.hpp"
#include "lacrima/materials/smooth_dielectric.hpp"
#include "ray_offset.hpp"
#include "segment_walk.hpp"
#include "shading_side.hpp"

namespace lacrima {

namespace {

// The seed walk gives up (the sample counts as blocked) after this many surfaces, as the
// straight transparent shadow does.
constexpr int kMaxSeedSurfaces = 16;
// A dielectric surface this close to the shading point along the shadow ray is a tear lying on
// it (shedding strips are ~0.7 mm thick, beads up to ~2 mm high), not a drop throwing a caustic
// from a distance (modelling choice, see manifoldDirectLight).
constexpr float kTearLayerThickness = 2.5e-3f;  // metres

// Re-projects a moved triangle vertex onto its mesh: a ray from the previous chain point
// towards the moved point (Hanika sec. 4.2; Cycles does the same), whose first hit must be the
// same mesh. The barycentrics are then recomputed in double precision along that ray.
class EmbreeProjection final : public ManifoldProjection {
 public:
  EmbreeProjection(const EmbreeScene& scene, float time, PathCounters& counters)
      : scene_(scene), time_(time), counters_(counters) {}

  std::optional<SurfacePatch> project(const SurfacePatch& moved, const Vec3d& from) const override {
    const Vec3d target = moved.position();
    const Vec3d direction = (target - from).normalized();
    const float step = 1e-4f * std::max(0.05f, from.cast<float>().cwiseAbs().maxCoeff());  // as offsetOrigin
    SurfaceHit hit;
    ++counters_.rays;
    if (!scene_.intersect(Ray{(from + double(step) * direction).cast<float>(), direction.cast<float>(), time_}, hit))
      return std::nullopt;
    if (hit.lightIndex >= 0 || hit.geometryId != moved.surfaceId) return std::nullopt;
    SurfacePatch patch = scene_.patchOf(hit, time_);
    refineOnTriangle(patch, from, direction);
    return patch;
  }

  // Exact (double) barycentrics of the ray from `from` along `direction` in the patch's plane.
  static void refineOnTriangle(SurfacePatch& patch, const Vec3d& from, const Vec3d& direction) {
    const Vec3d n = patch.edgeU.cross(patch.edgeV);
    const double denominator = n.dot(direction);
    if (std::abs(denominator) < 1e-30) return;
    const Vec3d p = from + (n.dot(patch.origin - from) / denominator) * direction - patch.origin;
    // Solve p = u edgeU + v edgeV in the plane (least squares via the 2x2 normal equations).
    const double uu = patch.edgeU.squaredNorm(), uv = patch.edgeU.dot(patch.edgeV), vv = patch.edgeV.squaredNorm();
    const double pu = p.dot(patch.edgeU), pv = p.dot(patch.edgeV), det = uu * vv - uv * uv;
    if (std::abs(det) < 1e-300) return;
    patch.uv = Vec2d((pu * vv - pv * uv) / det, (pv * uu - pu * uv) / det);
  }

 private:
  const EmbreeScene& scene_;
  float time_;
  PathCounters& counters_;
};

// The light end of the chain at the sample: the point on the light with its tangent frame, or
// the environment direction with two unit vectors orthogonal to it.
ManifoldEndpoint endpointOf(const Vec3& x0, const LightSample& light) {
  ManifoldEndpoint end;
  end.atInfinity = light.lightIndex < 0;
  const Vec3 axis = end.atInfinity ? light.direction : light.normal;
  const ShadingFrame frame = ShadingFrame::fromNormal(axis.normalized());
  end.point = end.atInfinity ? light.direction.cast<double>()
                             : Vec3d(x0.cast<double>() + double(light.distance) * light.direction.cast<double>());
  end.tangentS = frame.s.cast<double>().normalized();
  end.tangentT = axis.cast<double>().normalized().cross(end.tangentS);
  return end;
}

// The shading normal of a dielectric surface on its geometric normal's side, as the straight
// transparent shadow orients it.
Vec3 outsideShadingNormal(const SurfacePatch& patch) {
  return onGeometricSide(patch.shadingNormal(), patch.geometricNormal()).cast<float>();
}

}  // namespace

// The real interfaces the straight shadow ray crosses, with what each needs for the chain.
struct PathIntegrator::CausticSeed {
  struct Crossing {
    SurfaceHit hit;
    bool entering = false;          // the ray arrives on the geometric normal's side
    const Bsdf* bsdf = nullptr;     // the interface's BSDF with its pair of indices
    float relativeIor = 1.0f;       // n inside / n outside at this interface
  };
  std::array<Crossing, kMaxManifoldVertices> crossings;
  int count = 0;
};

// Walks the straight shadow ray (known to be blocked) like shadowTransmittance. False: MNEE does
// not apply (no real interface, more than kMaxManifoldVertices, or one that is not a smooth
// dielectric); the caller then falls back. True with seed.count == 0: blocked by something opaque.
bool PathIntegrator::traceCausticSeed(const Vertex& v, const LightSample& light, MediumStack media, CausticSeed& seed,
                                      PathCounters& counters) const {
  const Vec3& direction = light.direction;
  const float maxDistance = std::isinf(light.distance) ? light.distance : light.distance * (1.0f - 1e-4f);
  SegmentWalk walk(scene_, Ray{offsetOrigin(v.position, v.geometricNormal, direction), direction, v.time}, maxDistance);
  seed.count = 0;
  for (int surface = 0; surface < kMaxSeedSurfaces; ++surface) {
    SurfaceHit hit;
    if (!walk.next(hit, counters.rays) || walk.pastTheEnd(hit)) return seed.count > 0;
    if (hit.lightIndex >= 0 || !isDielectric(hit.materialId)) break;  // opaque
    if (isThinSheet(hit)) return false;  // it bends nothing: the straight transparent shadow is exact there
    const bool entering = walk.entering(hit);
    const InterfaceCrossing crossing = mediumInterface(media, hit, entering);
    if (!crossing.isFalse) {
      const Bsdf* bsdf = interfaceBsdf(hit.materialId, crossing.otherMaterial);
      const auto* smooth = dynamic_cast<const SmoothDielectricBsdf*>(bsdf);
      if (!smooth || seed.count == kMaxManifoldVertices) return false;
      seed.crossings[seed.count++] = {hit, entering, bsdf, smooth->ior()};
    }
    crossInterface(media, hit.materialId, entering);
    walk.cross(hit);
  }
  seed.count = 0;  // blocked (or too many surfaces, as the straight shadow gives up)
  return true;
}

// Every segment of the solved chain must reach the next chain point (or the light) without
// meeting another real surface (false interfaces are skipped, as everywhere).
bool PathIntegrator::causticChainIsVisible(const Vertex& v, const LightSample& light, const CausticSeed& seed,
                                           const SpecularChain& chain, MediumStack media, PathCounters& counters) const {
  Vec3 from = v.position, fromNormal = v.geometricNormal;
  const ManifoldEndpoint end = endpointOf(v.position, light);
  for (int i = 0; i <= chain.count; ++i) {
    const bool toLight = i == chain.count;
    const Vec3 target = toLight ? end.point.cast<float>() : chain.vertices[i].patch.position().cast<float>();
    const Vec3 direction = toLight && end.atInfinity ? target : Vec3((target - from).normalized());
    Ray ray{offsetOrigin(from, fromNormal, direction), direction, v.time};
    SurfaceHit hit;
    const Trace trace = traceToRealSurface(ray, hit, media, counters);
    if (toLight && end.atInfinity) return trace == Trace::Miss;
    if (trace != Trace::Hit) return false;
    const float tolerance = 1e-3f * (target - from).norm() + 1e-4f * std::max(0.05f, target.cwiseAbs().maxCoeff());
    if ((hit.position - target).norm() > tolerance) return false;
    if (toLight) return hit.lightIndex == light.lightIndex;
    if (hit.lightIndex >= 0 || hit.geometryId != chain.vertices[i].patch.surfaceId) return false;
    crossInterface(media, hit.materialId, seed.crossings[i].entering);
    from = target;
    fromNormal = chain.vertices[i].patch.geometricNormal().cast<float>();
  }
  return false;
}

std::optional<Color> PathIntegrator::manifoldDirectLight(const Vertex& v, const LightSample& light,
                                                         const MediumStack& shadowMedia, PathCounters& counters,
                                                         Vec3& wiLocalOut) const {
  CausticSeed seed;
  if (!traceCausticSeed(v, light, shadowMedia, seed, counters)) return std::nullopt;
  if (seed.count == 0) return Color::Zero();  // blocked by an opaque surface

  SpecularChain chain;
  chain.count = seed.count;
  const Vec3d x0 = v.position.cast<double>();
  for (int i = 0; i < seed.count; ++i) {
    const CausticSeed::Crossing& c = seed.crossings[i];
    SurfacePatch patch = scene_.patchOf(c.hit, v.time);
    if (patch.kind == SurfacePatch::Kind::Triangle)
      EmbreeProjection::refineOnTriangle(patch, x0, light.direction.cast<double>());
    // eta = n(light side) / n(x0 side): entering goes from outside to inside.
    const double eta = c.entering ? c.relativeIor : 1.0 / c.relativeIor;
    if (std::abs(eta - 1.0) < 1e-6) return std::nullopt;  // index-matched: the straight line is exact
    chain.vertices[i] = {patch, eta};
  }
  const ManifoldEndpoint end = endpointOf(v.position, light);
  // A receiver under a tear lying on it (the seed's first interface within kTearLayerThickness)
  // is lit through the tear for nearly every light point, a refraction offset of about the
  // tear's thickness away from the straight line. Where the chain fails there (the strip's edges
  // and side walls, a ridge of its interpolated normals, the strip's bottom and top as two
  // interfaces) the straight transparent shadow stands in, instead of leaving the skin under the
  // tear black (found on the default shot's jaw).
  const bool receiverUnderTear = (seed.crossings[0].hit.position - v.position).norm() < kTearLayerThickness;
  const Color failed = Color::Zero();
  if (!solveSpecularChain(x0, chain, end, EmbreeProjection(scene_, v.time, counters)))
    return receiverUnderTear ? std::nullopt : std::optional<Color>(failed);

  // The solved chain must cross each interface the way the seed did (its media stay valid).
  Vec3d previous = x0;
  for (int i = 0; i < chain.count; ++i) {
    const SurfacePatch& patch = chain.vertices[i].patch;
    if (((previous - patch.position()).dot(patch.geometricNormal()) > 0.0) != seed.crossings[i].entering)
      return receiverUnderTear ? std::nullopt : std::optional<Color>(failed);
    previous = patch.position();
  }

  // f at x0 towards the chain's first vertex, with the same no-leak rule as direct light.
  const Vec3 w0 = (chain.vertices[0].patch.position() - x0).normalized().cast<float>();
  const Vec3 wiLocal = v.frame.toLocal(w0);
  if (reflectsGeometrically(v.wo, w0, v.geometricNormal) != reflectsInShadingFrame(v.woLocal, wiLocal))
    return Color::Zero();
  const Color f = v.bsdf->eval(v.woLocal, wiLocal) * absCosTheta(wiLocal);
  if ((f <= 0.0f).all()) return Color::Zero();
  wiLocalOut = wiLocal;

  // Fresnel transmission with the n^2 radiance scaling at each vertex (as the BSDF strategy's
  // refraction weight, smooth_dielectric.hpp), seen from the x0 side.
  Color transmission = Color::Ones();
  previous = x0;
  for (int i = 0; i < chain.count; ++i) {
    const SurfacePatch& patch = chain.vertices[i].patch;
    const Vec3 towardsX0 = (previous - patch.position()).normalized().cast<float>();
    transmission *= seed.crossings[i].bsdf->straightTransmittance(ShadingFrame::fromNormal(outsideShadingNormal(patch)).toLocal(towardsX0));
    previous = patch.position();
  }
  if ((transmission <= 0.0f).all()) return Color::Zero();

  Color emitted = light.radiance;
  float pdf = light.pdf;  // solid angle of the seed direction
  if (!end.atInfinity) {
    const Vec3 fromLight = (chain.vertices[chain.count - 1].patch.position() - end.point).normalized().cast<float>();
    // A rectangle's emitting side; a sphere light is seen from outside (the visibility test
    // below finds it at y first).
    emitted = lights_.emitted(light.lightIndex, fromLight);
    // To area measure at y with the seed's geometry (how y was drawn).
    pdf *= std::abs(light.normal.dot(light.direction)) / (light.distance * light.distance);
  }
  if ((emitted <= 0.0f).all() || !(pdf > 0.0f)) return Color::Zero();
  const double g = manifoldGeometryTerm(x0, chain, end);
  if (!(g > 0.0) || !std::isfinite(g)) return Color::Zero();
  if (!causticChainIsVisible(v, light, seed, chain, shadowMedia, counters))
    return receiverUnderTear ? std::nullopt : std::optional<Color>(failed);
  return f * transmission * emitted * float(g / double(pdf));
}

}  // namespace lacrima
