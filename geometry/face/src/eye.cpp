// Eyes for close-ups; see eye.hpp.
#include "lacrima/face/eye.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>
#include <utility>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/sphere_fit.hpp"

namespace lacrima {

namespace {

constexpr float kMm = 1e-3f;
// Shells whose vertices lie this far outside the fitted ball belong to the corneal bulge.
constexpr float kBulgeThreshold = 0.5f * kMm;
// Clearances that keep the iris and pupil off the chamber's walls (no coincident surfaces).
constexpr float kWallClearance = 0.15f * kMm;
constexpr float kPupilSetBack = 0.3f * kMm;
// The iris root lies this far behind the limbus: inside the ball, and close enough that the
// chamber's wall above it does not show through the cornea at oblique views.
constexpr float kIrisRootSetBack = 0.3f * kMm;
// The iris stays at least this far below the cornea.
constexpr float kCorneaClearance = 0.05f * kMm;

// The chamber's flat back lies this far behind the limbus: behind iris and pupil, inside the ball.
constexpr float kChamberBackDepth = 3.0f * kMm;

// Cylindrical coordinates about the optical axis: (distance from the axis, height along it).
struct AxialPoint {
  float radial = 0.0f, height = 0.0f;
};

AxialPoint axial(const EyeModel& m, const Vec3& p) {
  const Vec3 d = p - m.center;
  const float h = d.dot(m.axis);
  return {(d - h * m.axis).norm(), h};
}

// Sphere through the shell without its bulge: fit all, then refit the vertices near the median radius.
FittedSphere fitBall(const std::vector<Vec3>& points) {
  const FittedSphere first = fitSphere(points);
  std::vector<float> radii;
  for (const Vec3& p : points) radii.push_back((p - first.center).norm());
  std::vector<float> sorted = radii;
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const float median = sorted[sorted.size() / 2];
  std::vector<Vec3> ball;
  for (size_t i = 0; i < points.size(); ++i)
    if (radii[i] < median + kBulgeThreshold) ball.push_back(points[i]);
  return fitSphere(ball);
}

// The optical axis: the bulge's mean direction from the centre, weighted by how far it stands out.
Vec3 bulgeAxis(const std::vector<Vec3>& points, const FittedSphere& ball, const std::string& what) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) {
    const Vec3 d = p - ball.center;
    const float excess = d.norm() - ball.radius;
    if (excess > kBulgeThreshold) sum += excess * d.normalized();
  }
  if (!(sum.norm() > 0.0f))
    throw InputError(fmt::format("{}: the eyeball shell has no corneal bulge (no vertex stands {} mm out of its sphere)",
                                 what, kBulgeThreshold / kMm));
  return sum.normalized();
}

// How far inside the limbus a shell point is: R - its distance from the axis in front of the
// centre; behind the centre (where the shell comes near the axis again, at its back) -R, outside.
float insideLimbus(const EyeModel& m, const Vec3& p) {
  const AxialPoint a = axial(m, p);
  return a.height > 0.0f ? m.params.limbusRadius - a.radial : -m.params.limbusRadius;
}

// Vertices this close to the limbus count as this far on their side, so that no crossing falls on
// a vertex (which would leave pieces without area).
constexpr float kLimbusVertexClearance = 1e-3f * kMm;

// Splits the shell's triangles where the limbus circle crosses their edges (the circle met along
// each crossed edge by linear interpolation of insideLimbus), so the cap's boundary lies on the
// circle instead of following the shell's edges in a zig-zag (up to 1.5 mm off it on the ICT eye,
// a notched limbus at 1:1). Fills the model's crossings, cutIndices and the cornea / sclera
// partition of the cut triangles.
void splitAtLimbus(const TriangleMesh& shell, EyeModel& m) {
  const std::vector<uint32_t> weld = findCoincidentVertices(shell);
  std::vector<float> inside(shell.vertexCount());
  for (size_t v = 0; v < inside.size(); ++v) {
    const float d = insideLimbus(m, shell.positions[v]);
    inside[v] = d > 0.0f ? std::max(d, kLimbusVertexClearance) : std::min(d, -kLimbusVertexClearance);
  }
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> crossingOf;
  const uint32_t shellVertices = uint32_t(shell.vertexCount());
  // The vertex where the limbus crosses edge a-b, one per edge. Ordered by welded index, so the two
  // copies of an edge on a UV seam give the same point bitwise and weld again.
  auto crossing = [&](uint32_t a, uint32_t b) {
    if (weld[a] > weld[b] || (weld[a] == weld[b] && a > b)) std::swap(a, b);
    const auto [it, added] = crossingOf.emplace(std::pair(a, b), shellVertices + uint32_t(m.crossings.size()));
    if (added) m.crossings.push_back({a, b, inside[a] / (inside[a] - inside[b])});
    return it->second;
  };
  auto add = [&](bool cornea, std::initializer_list<uint32_t> corners) {
    (cornea ? m.corneaTriangles : m.scleraTriangles).push_back(uint32_t(m.cutIndices.size() / 3));
    m.cutIndices.insert(m.cutIndices.end(), corners);
  };
  for (size_t t = 0; t < shell.triangleCount(); ++t) {
    const uint32_t* v = &shell.indices[3 * t];
    const bool in[3] = {inside[v[0]] > 0.0f, inside[v[1]] > 0.0f, inside[v[2]] > 0.0f};
    if (in[0] == in[1] && in[1] == in[2]) {
      add(in[0], {v[0], v[1], v[2]});
      continue;
    }
    // The corner alone on its side, then the other two in the triangle's winding.
    const int k = in[0] == in[1] ? 2 : (in[0] == in[2] ? 1 : 0);
    const uint32_t lone = v[k], next = v[(k + 1) % 3], last = v[(k + 2) % 3];
    const uint32_t toNext = crossing(lone, next), toLast = crossing(lone, last);
    add(in[k], {lone, toNext, toLast});
    add(!in[k], {toNext, next, last});
    add(!in[k], {toNext, last, toLast});
  }
}

// The cap's boundary as one loop of welded vertices in the cap's winding; throws unless it is one simple loop.
std::vector<uint32_t> capBoundaryLoop(const TriangleMesh& shell, const EyeModel& m, const std::string& what) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (uint32_t t : m.corneaTriangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = m.weldMap[shell.indices[3 * t + k]], b = m.weldMap[shell.indices[3 * t + (k + 1) % 3]];
      ++directed[{a, b}];
    }
  std::map<uint32_t, uint32_t> next;
  const std::string problem = fmt::format(
      "{}: the limbus at {:.3g} mm from the optical axis does not cut the eyeball shell into one cap and the rest; "
      "try another limbusRadius",
      what, m.params.limbusRadius / kMm);
  for (const auto& [edge, count] : directed) {
    if (directed.count({edge.second, edge.first})) continue;
    if (count != 1 || !next.emplace(edge.first, edge.second).second) throw InputError(problem);
  }
  if (next.size() < 3) throw InputError(problem);
  std::vector<uint32_t> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    const auto it = next.find(loop.back());
    if (it == next.end()) throw InputError(problem);
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  if (loop.size() != next.size()) throw InputError(problem);
  return loop;
}

// Angle of a point about the axis in the rest frame's (right, up) plane.
float angleAbout(const EyeModel& m, const Vec3& p) {
  const Vec3 d = p - m.center;
  return std::atan2(d.dot(m.up), d.dot(m.up.cross(m.axis)));
}

// Wraps an angle into (-pi, pi].
float wrapAngle(float a) { return std::remainder(a, 2.0f * kPi); }

// The limbus loop's (radius, height) at an angle about the axis: interpolated along the loop edge
// that spans the angle.
Vec2 limbusAt(const TriangleMesh& shell, const EyeModel& m, float phi) {
  const size_t n = m.limbusLoop.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec3& p = shell.positions[m.limbusLoop[i]];
    const Vec3& q = shell.positions[m.limbusLoop[(i + 1) % n]];
    const float span = wrapAngle(angleAbout(m, q) - angleAbout(m, p)), along = wrapAngle(phi - angleAbout(m, p));
    if (span == 0.0f || along * span < 0.0f || std::abs(along) > std::abs(span)) continue;
    const float t = along / span;
    const AxialPoint a = axial(m, p), b = axial(m, q);
    return Vec2(a.radial + t * (b.radial - a.radial), a.height + t * (b.height - a.height));
  }
  return Vec2(axial(m, shell.positions[m.limbusLoop[0]]).radial, axial(m, shell.positions[m.limbusLoop[0]]).height);
}

// Places the iris root just under the limbus all round, like the real iris's root at the ciliary
// body behind the scleral spur: a hair outside the chamber's wall (the limbus loop pushed straight
// back) and below the loop, so neither a gap nor the wall shows between iris and sclera. Beyond
// the limbus the shell falls away far less steeply (~0.5 mm per mm out) than the root's
// set-back over its clearance (0.3 over 0.15 mm), so the root stays inside the eyeball. Checks
// that the iris clears the cornea and that iris and pupil lie in front of the chamber's back.
void fitIris(const TriangleMesh& shell, EyeModel& m, const std::string& what) {
  float minHeight = std::numeric_limits<float>::infinity();
  for (uint32_t v : m.limbusLoop) minHeight = std::min(minHeight, axial(m, shell.positions[v]).height);
  m.irisRoot.clear();
  m.irisRootRadius = 0.0f;
  m.irisRootHeight = std::numeric_limits<float>::infinity();
  for (int s = 0; s < m.params.irisSegments; ++s) {
    const Vec2 limbus = limbusAt(shell, m, 2.0f * kPi * float(s) / float(m.params.irisSegments));
    const Vec2 root(limbus.x() + kWallClearance, limbus.y() - kIrisRootSetBack);
    m.irisRoot.push_back(root);
    m.irisRootRadius = std::max(m.irisRootRadius, root.x());
    m.irisRootHeight = std::min(m.irisRootHeight, root.y());
  }
  m.backHeight = minHeight - kChamberBackDepth;
  m.pupilHeight = m.apexHeight - m.params.irisDepth;
  float smallestRoot = m.irisRootRadius;
  for (const Vec2& root : m.irisRoot) smallestRoot = std::min(smallestRoot, root.x());
  if (m.params.pupilRadius > smallestRoot - 0.5f * kMm)
    throw InputError(fmt::format("{}: the pupil ({:.3g} mm) must be at least 0.5 mm smaller than the iris ({:.3g} mm)",
                                 what, m.params.pupilRadius / kMm, smallestRoot / kMm));
  if (m.pupilHeight - kPupilSetBack < m.backHeight + kWallClearance)
    throw InputError(fmt::format("{}: the pupil lies behind the chamber's back; reduce irisDepth ({:.3g} mm)", what,
                                 m.params.irisDepth / kMm));
  // The iris is a cone from root to pupil margin; every cap vertex above it must stay clear.
  for (uint32_t t : m.corneaTriangles)
    for (int k = 0; k < 3; ++k) {
      const AxialPoint a = axial(m, shell.positions[shell.indices[3 * t + k]]);
      const float phi = angleAbout(m, shell.positions[shell.indices[3 * t + k]]);
      const Vec2 root = m.irisRoot[size_t(std::lround(wrapAngle(phi) / (2.0f * kPi) * float(m.params.irisSegments)) +
                                          m.params.irisSegments) % m.irisRoot.size()];
      if (a.radial < m.params.pupilRadius || a.radial > root.x()) continue;
      const float s = (a.radial - m.params.pupilRadius) / (root.x() - m.params.pupilRadius);
      const float irisHeight = m.pupilHeight + s * (root.y() - m.pupilHeight);
      if (irisHeight > a.height - kCorneaClearance)
        throw InputError(fmt::format("{}: the iris would cut through the cornea; increase irisDepth ({:.3g} mm)", what,
                                     m.params.irisDepth / kMm));
    }
}

// Local (right, up, axis) frame of the rest eye, as world vectors from the centre.
Vec3 localToRest(const EyeModel& m, float x, float y, float height) {
  const Vec3 right = m.up.cross(m.axis);
  return m.center + x * right + y * m.up + height * m.axis;
}

}  // namespace

EyeModel analyseEye(const TriangleMesh& shell, const EyeParams& params, const std::string& what) {
  if (const std::string defect = findMeshDefect(shell); !defect.empty())
    throw InputError(fmt::format("{}: {}", what, defect));
  EyeModel m;
  m.params = params;
  m.restPositions = shell.positions;
  const FittedSphere ball = fitBall(shell.positions);
  m.center = ball.center;
  m.radius = ball.radius;
  m.axis = bulgeAxis(shell.positions, ball, what);
  const Vec3 worldUp = std::abs(m.axis.y()) < 0.9f ? Vec3(Vec3::UnitY()) : Vec3(Vec3::UnitZ());
  m.up = (worldUp - worldUp.dot(m.axis) * m.axis).normalized();
  for (const Vec3& p : shell.positions) m.apexHeight = std::max(m.apexHeight, (p - m.center).dot(m.axis));
  splitAtLimbus(shell, m);
  if (m.corneaTriangles.empty())
    throw InputError(fmt::format("{}: no triangle of the eyeball shell lies within the limbus ({:.3g} mm)", what,
                                 params.limbusRadius / kMm));
  const TriangleMesh cut = cutAtLimbus(m, shell);
  m.weldMap = findCoincidentVertices(cut);
  m.limbusLoop = capBoundaryLoop(cut, m, what);
  fitIris(cut, m, what);
  return m;
}

TriangleMesh cutAtLimbus(const EyeModel& m, const TriangleMesh& shell) {
  if (shell.positions.size() != m.restPositions.size())
    throw InputError(fmt::format("eye: the posed shell has {} vertices, the rest shell {}", shell.positions.size(),
                                 m.restPositions.size()));
  TriangleMesh cut;
  cut.name = shell.name;
  cut.positions = shell.positions;
  const bool normals = shell.normals.size() == shell.positions.size();
  if (normals) cut.normals = shell.normals;
  for (const LimbusCrossing& c : m.crossings) {
    cut.positions.push_back((1.0f - c.t) * shell.positions[c.a] + c.t * shell.positions[c.b]);
    if (normals) cut.normals.push_back(((1.0f - c.t) * shell.normals[c.a] + c.t * shell.normals[c.b]).normalized());
  }
  cut.indices = m.cutIndices;
  return cut;
}

Affine3 eyeMotion(const EyeModel& model, const TriangleMesh& posedShell) {
  const size_t n = model.restPositions.size();
  if (posedShell.positions.size() != n)
    throw InputError(fmt::format("eye: the posed shell has {} vertices, the rest shell {}", posedShell.positions.size(), n));
  // In double precision: millimetre motions of points 10 cm from the origin.
  Eigen::Matrix3Xd rest(3, n), posed(3, n);
  for (size_t i = 0; i < n; ++i) {
    rest.col(long(i)) = model.restPositions[i].cast<double>();
    posed.col(long(i)) = posedShell.positions[i].cast<double>();
  }
  const Eigen::Matrix4d motion = Eigen::umeyama(rest, posed, false);
  return Affine3(motion.cast<float>());
}

namespace {

// Copies the listed triangles of `shell` into a compact mesh, vertices renumbered through `remap`
// (the weld map for a closed cap, identity for the sclera); normals come with positions when present.
TriangleMesh extractTriangles(const TriangleMesh& shell, const std::vector<uint32_t>& triangles,
                              const std::vector<uint32_t>* weld, std::map<uint32_t, uint32_t>& index) {
  TriangleMesh out;
  const bool normals = shell.normals.size() == shell.positions.size();
  for (uint32_t t : triangles)
    for (int k = 0; k < 3; ++k) {
      uint32_t v = shell.indices[3 * t + k];
      if (weld) v = (*weld)[v];
      const auto [it, added] = index.emplace(v, uint32_t(out.positions.size()));
      if (added) {
        out.positions.push_back(shell.positions[v]);
        if (normals) out.normals.push_back(shell.normals[v]);
      }
      out.indices.push_back(it->second);
    }
  return out;
}

// A ring-and-segment surface about the axis: rings[r][s] is the (radial, height) of ring r at
// segment s (equal angles), front side towards +axis; placed by the eye's rest frame and its motion.
TriangleMesh revolve(const EyeModel& m, const Affine3& motion, const std::vector<std::vector<AxialPoint>>& rings) {
  TriangleMesh mesh;
  const uint32_t n = uint32_t(rings.front().size());
  for (const std::vector<AxialPoint>& ring : rings)
    for (uint32_t s = 0; s < n; ++s) {
      const float phi = 2.0f * kPi * float(s) / float(n);
      mesh.positions.push_back(
          motion * localToRest(m, ring[s].radial * std::cos(phi), ring[s].radial * std::sin(phi), ring[s].height));
    }
  for (uint32_t r = 0; r + 1 < rings.size(); ++r)
    for (uint32_t s = 0; s < n; ++s) {
      const uint32_t a = r * n + s, b = r * n + (s + 1) % n, c = a + n, d = b + n;
      // Rings run outward-in (decreasing radius): this winding faces +axis.
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  computeSmoothNormals(mesh, false);
  return mesh;
}

TriangleMesh pupilDisc(const EyeModel& m, const Affine3& motion, int segments) {
  const float radius = m.params.pupilRadius + kPupilSetBack, height = m.pupilHeight - kPupilSetBack;
  const std::vector<std::vector<AxialPoint>> rings{std::vector<AxialPoint>(size_t(segments), {radius, height}),
                                                   std::vector<AxialPoint>(size_t(segments), {0.5f * radius, height})};
  TriangleMesh mesh = revolve(m, motion, rings);
  const uint32_t centre = uint32_t(mesh.positions.size()), n = uint32_t(segments);
  mesh.positions.push_back(motion * localToRest(m, 0, 0, height));
  for (uint32_t s = 0; s < n; ++s) mesh.indices.insert(mesh.indices.end(), {n + s, n + (s + 1) % n, centre});
  computeSmoothNormals(mesh, false);
  return mesh;
}

// The iris's uvs (eye.hpp, kIrisUvPupilRadius): ring r of `rings` + 1, from the root (r = 0) to the
// pupil margin, sits at disc radius 1 - (1 - kIrisUvPupilRadius) r / rings, at the segment's
// angle from `right` towards `up`; v runs down the image (glTF), so the image's top is the eye's up.
std::vector<Vec2> irisSheetUvs(int rings, int segments) {
  std::vector<Vec2> uvs;
  for (int r = 0; r <= rings; ++r) {
    const float radius = 1.0f - (1.0f - kIrisUvPupilRadius) * float(r) / float(rings);
    for (int s = 0; s < segments; ++s) {
      const float phi = 2.0f * kPi * float(s) / float(segments);
      uvs.emplace_back(0.5f + 0.5f * radius * std::cos(phi), 0.5f - 0.5f * radius * std::sin(phi));
    }
  }
  return uvs;
}

// Closes the cap into the anterior chamber: a wall from the limbus loop straight back along the
// axis to backHeight and a flat back (both hidden behind the iris, inside the ball).
void closeChamber(const EyeModel& m, const Affine3& motion, const std::map<uint32_t, uint32_t>& capIndex,
                  TriangleMesh& cornea) {
  const bool normals = !cornea.normals.empty();
  const Vec3 back = -(motion.linear() * m.axis);
  const size_t n = m.limbusLoop.size();
  const uint32_t firstBack = uint32_t(cornea.positions.size());
  for (uint32_t v : m.limbusLoop) {
    const Vec3 p = cornea.positions[capIndex.at(v)];
    const float height = (motion.inverse() * p - m.center).dot(m.axis);
    cornea.positions.push_back(p + (height - m.backHeight) * back);
    if (normals) cornea.normals.push_back(back);
  }
  const uint32_t centre = uint32_t(cornea.positions.size());
  cornea.positions.push_back(motion * (m.center + m.backHeight * m.axis));
  if (normals) cornea.normals.push_back(back);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const uint32_t a = capIndex.at(m.limbusLoop[i]), b = capIndex.at(m.limbusLoop[j]);
    const uint32_t aBack = firstBack + uint32_t(i), bBack = firstBack + uint32_t(j);
    cornea.indices.insert(cornea.indices.end(), {b, a, aBack, b, aBack, bBack, bBack, aBack, centre});
  }
}

}  // namespace

EyeMeshes buildEye(const EyeModel& m, const TriangleMesh& posed) {
  const Affine3 motion = eyeMotion(m, posed);
  EyeMeshes eye;
  const TriangleMesh cut = cutAtLimbus(m, posed);
  std::map<uint32_t, uint32_t> capIndex, scleraIndex;
  eye.cornea = extractTriangles(cut, m.corneaTriangles, &m.weldMap, capIndex);
  closeChamber(m, motion, capIndex, eye.cornea);
  eye.sclera = extractTriangles(cut, m.scleraTriangles, nullptr, scleraIndex);
  // Rings from the root (following the limbus) to the pupil margin (a circle): a cone with depth.
  std::vector<std::vector<AxialPoint>> irisRings;
  for (int r = 0; r <= m.params.irisRings; ++r) {
    const float t = float(r) / float(m.params.irisRings);
    std::vector<AxialPoint>& ring = irisRings.emplace_back();
    for (const Vec2& root : m.irisRoot)
      ring.push_back({root.x() + t * (m.params.pupilRadius - root.x()), root.y() + t * (m.pupilHeight - root.y())});
  }
  eye.iris = revolve(m, motion, irisRings);
  eye.iris.uvs = irisSheetUvs(m.params.irisRings, m.params.irisSegments);
  eye.pupil = pupilDisc(m, motion, m.params.irisSegments);
  return eye;
}

}  // namespace lacrima
