#pragma once
// The walk along one straight line through the scene, surface by surface. The integrator walks
// a line without bending it in five places: the probe for the media around the camera, the skip
// over false interfaces of nested dielectrics, the transparent shadow, MNEE's caustic seed and a
// subsurface flight. Each asks for the next surface, decides whether to stop there, and
// otherwise crosses it: the walk then goes on from just past the surface (offsetOrigin, along
// the geometric normal), counting the distance it moved. A thin sheet is crossed in place
// instead: the next search starts just past its distance on the same ray, since an offset would
// jump over a surface that close behind it (the skin under a tear line).
#include <cmath>
#include <cstdint>
#include <limits>

#include "embree_scene.hpp"
#include "ray_offset.hpp"

namespace lacrima {

// A ray that goes on through a thin sheet ignores hits closer than the sheet's distance times
// (1 + this): past the rounding of the sheet's own hit, far short of a surface 1 um behind it.
inline constexpr float kThinSheetMargin = 1e-6f;
// The nearest distance a ray going on through a thin sheet at distance t may hit (strictly past
// t, also when t is 0: a ray that starts on the sheet).
inline float justPast(float t) {
  return std::nextafter(t * (1.0f + kThinSheetMargin), std::numeric_limits<float>::infinity());
}

class SegmentWalk {
 public:
  // A walk from ray.origin (hits nearer than ray.tnear ignored) along ray.direction that ends
  // maxDistance from the origin.
  SegmentWalk(const EmbreeScene& scene, const Ray& ray, float maxDistance = std::numeric_limits<float>::infinity())
      : scene_(scene), ray_(ray), remaining_(maxDistance) {}

  // The nearest surface from where the walk stands (hit.distance from there); false when the
  // line meets no more surfaces. Counts the ray.
  bool next(SurfaceHit& hit, uint64_t& rays) const {
    ++rays;
    return scene_.intersect(ray_, hit);
  }
  // Whether a surface next() found lies at or past the walk's end.
  bool pastTheEnd(const SurfaceHit& hit) const { return hit.distance >= remaining_; }
  // Whether the line meets the surface against its geometric normal (enters a closed surface).
  bool entering(const SurfaceHit& hit) const { return ray_.direction.dot(hit.geometricNormal) < 0.0f; }
  // Whether it meets the surface along its geometric normal (leaves a closed surface).
  bool leaving(const SurfaceHit& hit) const { return ray_.direction.dot(hit.geometricNormal) > 0.0f; }

  // Goes on from just past the surface, on the far side of its geometric normal.
  void cross(const SurfaceHit& hit) {
    const Vec3 next = offsetOrigin(hit.position, hit.geometricNormal, ray_.direction);
    const float moved = (next - ray_.origin).dot(ray_.direction);
    travelled_ += moved;
    remaining_ -= moved;
    ray_.origin = next;
    ray_.tnear = 0.0f;
  }
  // Goes on along the same ray from just past a thin sheet.
  void crossThinSheet(const SurfaceHit& hit) { ray_.tnear = justPast(hit.rayDistance); }

  // The ray the next search casts.
  const Ray& ray() const { return ray_; }
  // The distance moved by crossings, summed (thin sheets move the origin by nothing).
  float travelled() const { return travelled_; }
  // The distance left to the end: maxDistance less each crossing's, one by one.
  float remaining() const { return remaining_; }

 private:
  const EmbreeScene& scene_;
  Ray ray_;
  float travelled_ = 0.0f;
  float remaining_;
};

}  // namespace lacrima
