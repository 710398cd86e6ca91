#pragma once
// Unidirectional path tracer with next-event estimation and multiple importance sampling
// (Veach 1997, ch. 9, power heuristic), Russian roulette, and shading-normal handling that does
// not leak light through surfaces.
#include <cstdint>
#include <memory>
#include <vector>

#include "embree_scene.hpp"
#include "light_sampler.hpp"
#include "lacrima/geometry/sampler.hpp"
#include "lacrima/materials/bsdf.hpp"

namespace lacrima {

// What the camera ray saw first, for the AOVs.
struct FirstHit {
  bool valid = false;
  Color albedo = Color::Zero();
  Vec3 normal = Vec3::Zero();
  float distance = 0.0f;
};

struct PathCounters {
  uint64_t rays = 0;
};

class PathIntegrator {
 public:
  PathIntegrator(const Frame& frame, const EmbreeScene& scene, const LightSampler& lights);

  Color radiance(const Ray& cameraRay, PixelSampler& sampler, FirstHit& firstHit, PathCounters& counters) const;

 private:
  struct Vertex;  // the shading point of the current bounce (integrator.cpp)

  Color sampleDirectLight(const Vertex& vertex, PixelSampler& sampler, PathCounters& counters) const;
  // What reaches the shading point along shadowRay within maxDistance (see integrator.cpp).
  Color shadowTransmittance(const Ray& shadowRay, float maxDistance, bool& crossedDielectric,
                            PathCounters& counters) const;
  bool countedByTransparentShadows(bool chainAfterNonSpecular, int crossings) const;

  const Frame& frame_;
  const EmbreeScene& scene_;
  const LightSampler& lights_;
  std::vector<std::unique_ptr<Bsdf>> bsdfs_;  // one per material
  int maxDepth_;
};

}  // namespace lacrima
