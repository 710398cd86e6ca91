// Eyes for close-ups; see eye.hpp.
#include "lacrima/geometry/eye.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "lacrima/geometry/error.hpp"
#include "lacrima/geometry/sphere_fit.hpp"

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

Vec3 centroid(const TriangleMesh& mesh, uint32_t t) {
  const uint32_t* v = &mesh.indices[3 * size_t(t)];
  return (mesh.positions[v[0]] + mesh.positions[v[1]] + mesh.positions[v[2]]) / 3.0f;
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
  m.weldMap = findCoincidentVertices(shell);
  const FittedSphere ball = fitBall(shell.positions);
  m.center = ball.center;
  m.radius = ball.radius;
  m.axis = bulgeAxis(shell.positions, ball, what);
  const Vec3 worldUp = std::abs(m.axis.y()) < 0.9f ? Vec3(Vec3::UnitY()) : Vec3(Vec3::UnitZ());
  m.up = (worldUp - worldUp.dot(m.axis) * m.axis).normalized();
  for (const Vec3& p : shell.positions) m.apexHeight = std::max(m.apexHeight, (p - m.center).dot(m.axis));
  for (uint32_t t = 0; t < shell.triangleCount(); ++t) {
    const AxialPoint a = axial(m, centroid(shell, t));
    (a.height > 0.0f && a.radial < params.limbusRadius ? m.corneaTriangles : m.scleraTriangles).push_back(t);
  }
  if (m.corneaTriangles.empty())
    throw InputError(fmt::format("{}: no triangle of the eyeball shell lies within the limbus ({:.3g} mm)", what,
                                 params.limbusRadius / kMm));
  m.limbusLoop = capBoundaryLoop(shell, m, what);
  fitIris(shell, m, what);
  return m;
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
  std::map<uint32_t, uint32_t> capIndex, scleraIndex;
  eye.cornea = extractTriangles(posed, m.corneaTriangles, &m.weldMap, capIndex);
  closeChamber(m, motion, capIndex, eye.cornea);
  eye.sclera = extractTriangles(posed, m.scleraTriangles, nullptr, scleraIndex);
  // Rings from the root (following the limbus) to the pupil margin (a circle): a cone with depth.
  std::vector<std::vector<AxialPoint>> irisRings;
  for (int r = 0; r <= m.params.irisRings; ++r) {
    const float t = float(r) / float(m.params.irisRings);
    std::vector<AxialPoint>& ring = irisRings.emplace_back();
    for (const Vec2& root : m.irisRoot)
      ring.push_back({root.x() + t * (m.params.pupilRadius - root.x()), root.y() + t * (m.pupilHeight - root.y())});
  }
  eye.iris = revolve(m, motion, irisRings);
  eye.pupil = pupilDisc(m, motion, m.params.irisSegments);
  return eye;
}

}  // namespace lacrima
