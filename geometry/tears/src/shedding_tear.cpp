// Shedding tear, Lin & Cheng 2013 section 4.2 steps 1-5 (see shedding_tear.hpp for the construction).
#include "lacrima/tears/shedding_tear.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lacrima/mesh/closest_point_grid.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/moving_least_squares.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {
namespace {

constexpr const char* kSheddingTear = "shedding tear";

uint64_t splitmix64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

float uniformFromHash(uint64_t h) { return float(h >> 40) * (1.0f / 16777216.0f); }

float smoothstep01(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x * x * (3.0f - 2.0f * x);
}

void validate(const SheddingTearParams& p) {
  auto bad = [](const char* field, float value, const char* rule) {
    throw InputError(fmt::format("{}: {} = {} is invalid; it must be {}", kSheddingTear, field, value, rule));
  };
  if (!(p.width > 0.0f) || !std::isfinite(p.width)) bad("width", p.width, "finite and > 0");
  if (!(p.thickness > 0.0f) || !std::isfinite(p.thickness)) bad("thickness", p.thickness, "finite and > 0");
  if (!(p.baseOffset > 0.0f) || !std::isfinite(p.baseOffset)) bad("baseOffset", p.baseOffset, "finite and > 0");
  if (!(p.sampleSpacing > 0.0f) || !std::isfinite(p.sampleSpacing))
    bad("sampleSpacing", p.sampleSpacing, "finite and > 0");
  if (p.acrossSamples < 3 || p.acrossSamples > 1000) bad("acrossSamples", float(p.acrossSamples), "in 3..1000");
  if (!std::isfinite(p.start)) bad("start", p.start, "finite");
  if (!std::isfinite(p.speed)) bad("speed", p.speed, "finite");
  if (!(p.headLength >= 0.0f) || !std::isfinite(p.headLength)) bad("headLength", p.headLength, "finite and >= 0");
  if (!(p.headBulge >= 0.0f) || !std::isfinite(p.headBulge)) bad("headBulge", p.headBulge, "finite and >= 0");
  if (!(p.tipFraction > 0.0f && p.tipFraction <= 1.0f)) bad("tipFraction", p.tipFraction, "in (0, 1]");
  if (!(p.tailLength >= 0.0f) || !std::isfinite(p.tailLength)) bad("tailLength", p.tailLength, "finite and >= 0");
  if (!(p.noiseDensity >= 0.0f && p.noiseDensity <= 1.0f)) bad("noiseDensity", p.noiseDensity, "in [0, 1]");
  if (!(p.noiseAmplitude >= 0.0f) || !std::isfinite(p.noiseAmplitude))
    bad("noiseAmplitude", p.noiseAmplitude, "finite and >= 0");
  if (p.smoothingDegree < 0 || p.smoothingDegree > 15)
    bad("smoothingDegree", float(p.smoothingDegree), "in 0..15");
  if (!(p.smoothingEpsilon > 0.0f) || !std::isfinite(p.smoothingEpsilon))
    bad("smoothingEpsilon", p.smoothingEpsilon, "finite and > 0");
}

}  // namespace

SheddingTearStrip buildSheddingTearStrip(const TriangleMesh& restSkin, const std::vector<SurfacePoint>& path,
                                         const SheddingTearParams& params, float t) {
  validate(params);
  if (!std::isfinite(t)) throw InputError(fmt::format("{}: time {} is not finite", kSheddingTear, t));
  if (path.size() < 2)
    throw InputError(fmt::format("{}: the path has {} points; give at least two", kSheddingTear, path.size()));

  // Lin & Cheng 2013 section 4.2 step 1: the path on the rest skin, as a polyline with cumulative arc length.
  std::vector<Vec3> control(path.size());
  std::vector<float> arc(path.size(), 0.0f);
  for (size_t i = 0; i < path.size(); ++i) {
    control[i] = surfacePosition(restSkin, path[i]);
    if (i > 0) arc[i] = arc[i - 1] + (control[i] - control[i - 1]).norm();
  }
  const float pathLength = arc.back();

  // Lin & Cheng 2013 section 4.2 step 5: h = s + c t, the grown part of the path.
  SheddingTearStrip strip;
  strip.columns = params.acrossSamples;
  const float h = std::clamp(params.start + params.speed * t, 0.0f, pathLength);
  if (!(h >= 0.25f * params.sampleSpacing)) return strip;
  std::vector<float> rowArc;
  for (int i = 0; float(i) * params.sampleSpacing < h; ++i) rowArc.push_back(float(i) * params.sampleSpacing);
  if (h - rowArc.back() < 0.25f * params.sampleSpacing && rowArc.size() > 1) rowArc.back() = h;
  else rowArc.push_back(h);
  strip.rows = int(rowArc.size());
  strip.length = h;

  // Every grid point is projected to the skin: many queries on one mesh.
  const ClosestPointGrid skinLocator(restSkin);
  const int columns = strip.columns;
  const float headLength = std::min(params.headLength, h);
  size_t segment = 0;
  for (int i = 0; i < strip.rows; ++i) {
    const float a = rowArc[size_t(i)];
    while (segment + 2 < path.size() && arc[segment + 1] < a) ++segment;
    const float segmentLength = arc[segment + 1] - arc[segment];
    const float f = segmentLength > 0.0f ? std::clamp((a - arc[segment]) / segmentLength, 0.0f, 1.0f) : 0.0f;
    const Vec3 onPath = control[segment] + f * (control[segment + 1] - control[segment]);
    const SurfacePoint centre = skinLocator.closest(onPath);
    const Vec3 centrePos = surfacePosition(restSkin, centre);
    const Vec3 n = triangleNormal(restSkin, centre.triangle);
    const Vec3 d = control[segment + 1] - control[segment];
    Vec3 tangent = d - n * n.dot(d);
    if (!(tangent.norm() > 1e-6f * std::max(d.norm(), 1e-30f)))
      throw InputError(fmt::format("{}: the path near arc length {} runs along the skin normal; it must run over "
                                   "the skin",
                                   kSheddingTear, a));
    tangent.normalize();
    const Vec3 across = n.cross(tangent);  // (tangent, across, n) is right-handed

    // Lin & Cheng 2013 section 4.2 step 3: the head over the last headLength of the grown path.
    float g = 1.0f, widthFactor = 1.0f;
    if (headLength > 0.0f && a > h - headLength) {
      const float x = std::clamp((a - (h - headLength)) / headLength, 0.0f, 1.0f);
      g = 1.0f + params.headBulge * smoothstep01(2.0f * x);
      if (x > 0.5f) {
        const float e = 2.0f * x - 1.0f;
        const float close = std::max(params.tipFraction, std::sqrt(std::max(0.0f, 1.0f - e * e)));
        g *= close;
        widthFactor = close;
      }
    }
    // The tail: over the first tailLength of the path the strip narrows and thins towards the
    // source like the head's front (quarter ellipse, floored at tipFraction), so the tear emerges
    // from the skin instead of starting with a blunt cap.
    const float tailLength = std::min(params.tailLength, h - headLength);
    if (tailLength > 0.0f && a < tailLength) {
      const float e = 1.0f - a / tailLength;
      const float open = std::max(params.tipFraction, std::sqrt(std::max(0.0f, 1.0f - e * e)));
      g *= open;
      widthFactor *= open;
    }
    const float w = params.width * widthFactor;
    for (int j = 0; j < columns; ++j) {
      const float s = -0.5f + float(j) / float(columns - 1);  // -1/2 .. 1/2 across
      const float v = s * w;
      const SurfacePoint sp = (j == (columns - 1) / 2 && columns % 2 == 1)
                                  ? centre
                                  : skinLocator.closest(centrePos + across * v);
      strip.points.push_back(sp);
      strip.coordinates.emplace_back(a, v);
      const float q = (j == 0 || j == columns - 1) ? 0.0f : std::max(0.0f, 1.0f - 4.0f * s * s);
      strip.thickness.push_back(params.thickness * g * q);
    }
  }

  // Lin & Cheng 2013 section 4.2 step 4: upward-only noise, smoothed by MLS (eqs. 8-14), never below the plain top.
  if (params.noiseDensity > 0.0f && params.noiseAmplitude > 0.0f) {
    std::vector<float> bumps(strip.points.size(), 0.0f);
    bool any = false;
    for (int i = 0; i < strip.rows; ++i)
      for (int j = 1; j + 1 < columns; ++j) {
        const uint64_t key = splitmix64(splitmix64(params.seed) ^ (uint64_t(uint32_t(i)) << 20) ^ uint64_t(j));
        if (uniformFromHash(key) < params.noiseDensity) {
          bumps[size_t(i * columns + j)] = params.noiseAmplitude * (0.5f + 0.5f * uniformFromHash(splitmix64(key)));
          any = true;
        }
      }
    // A polynomial of total degree r vanishing on r + 1 rows of r + 1 distinct points each is zero,
    // so the fit is determined when both counts exceed the degree; a young tear with fewer rows
    // is smoothed with a lower degree (two rows alone would make a degree-2 fit singular).
    const int degree = std::min({params.smoothingDegree, strip.rows - 1, columns - 1});
    const int m = MovingLeastSquares::basisSize(2, degree);
    if (any && strip.rows >= 2 && int(bumps.size()) >= m) {
      const std::vector<float> smooth =
          smoothHeightField(strip.coordinates, bumps, degree, double(params.smoothingEpsilon));
      for (int i = 0; i < strip.rows; ++i)
        for (int j = 1; j + 1 < columns; ++j) {
          const float s = -0.5f + float(j) / float(columns - 1);
          const size_t k = size_t(i * columns + j);
          strip.thickness[k] += std::max(0.0f, smooth[k]) * std::max(0.0f, 1.0f - 4.0f * s * s);
        }
    }
  }
  return strip;
}

TriangleMesh sheddingTearMesh(const TriangleMesh& skin, const SheddingTearStrip& strip, float baseOffset) {
  TriangleMesh mesh;
  mesh.name = "shedding tear";
  if (strip.rows == 0) return mesh;
  const int rows = strip.rows, columns = strip.columns;
  if (rows < 2 || columns < 3 || strip.points.size() != size_t(rows * columns) ||
      strip.thickness.size() != strip.points.size())
    throw InputError(fmt::format("{}: inconsistent strip ({} x {} grid, {} points, {} thicknesses)", kSheddingTear, rows,
                                 columns, strip.points.size(), strip.thickness.size()));
  if (!(baseOffset > 0.0f) || !std::isfinite(baseOffset))
    throw InputError(fmt::format("{}: baseOffset = {} must be finite and > 0", kSheddingTear, baseOffset));

  // Lin & Cheng 2013 section 4.2 step 2: base grid (rows x columns), then the top's interior columns;
  // the edge columns are shared.
  const uint32_t topStart = uint32_t(rows * columns);
  mesh.positions.resize(size_t(rows * columns + rows * (columns - 2)));
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < columns; ++j) {
      const size_t k = size_t(i * columns + j);
      const SurfacePoint& sp = strip.points[k];
      const Vec3 p = surfacePosition(skin, sp);
      const Vec3 n = triangleNormal(skin, sp.triangle);
      mesh.positions[k] = p + n * baseOffset;
      if (j > 0 && j + 1 < columns)
        mesh.positions[topStart + size_t(i * (columns - 2) + j - 1)] = p + n * (baseOffset + strip.thickness[k]);
    }
  auto base = [&](int i, int j) { return uint32_t(i * columns + j); };
  auto top = [&](int i, int j) {
    return (j == 0 || j == columns - 1) ? base(i, j) : topStart + uint32_t(i * (columns - 2) + j - 1);
  };
  auto tri = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (a == b || b == c || a == c) return;
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  for (int i = 0; i + 1 < rows; ++i)
    for (int j = 0; j + 1 < columns; ++j) {
      // Base faces the skin (-n): (tangent, across) winding reversed.
      tri(base(i, j), base(i, j + 1), base(i + 1, j));
      tri(base(i + 1, j), base(i, j + 1), base(i + 1, j + 1));
      // Top faces away from the skin (+n).
      tri(top(i, j), top(i + 1, j), top(i, j + 1));
      tri(top(i + 1, j), top(i + 1, j + 1), top(i, j + 1));
    }
  // Lens-shaped caps: the start faces -tangent, the leading end +tangent.
  for (int j = 0; j + 1 < columns; ++j) {
    tri(base(0, j), top(0, j), base(0, j + 1));
    tri(base(0, j + 1), top(0, j), top(0, j + 1));
    const int e = rows - 1;
    tri(base(e, j), base(e, j + 1), top(e, j));
    tri(base(e, j + 1), top(e, j + 1), top(e, j));
  }
  computeSmoothNormals(mesh, false);
  return mesh;
}

TriangleMesh buildSheddingTear(const TriangleMesh& skin, const std::vector<SurfacePoint>& path,
                               const SheddingTearParams& params, float t) {
  return sheddingTearMesh(skin, buildSheddingTearStrip(skin, path, params, t), params.baseOffset);
}

}  // namespace lacrima
