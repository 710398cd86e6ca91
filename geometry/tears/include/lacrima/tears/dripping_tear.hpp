#pragma once
// The dripping tear of Lin & Cheng 2013 section 4.1 (a drop that leaves the face and falls), as a closed,
// outward-oriented, watertight triangle mesh whose shape changes with time.
//
// Lin & Cheng 2013 eq. 7:
//   x = alpha sin(u) cos(v) / (t cos(u)),   y = alpha sin(u) sin(v) / (t cos(u)),
//   z = beta t cos(u) + lambda t.
//
// Why eq. 7 alone is not a closed surface (derivation)
// ----------------------------------------------------
// Write the surface as one of revolution around z: radius r = (alpha / t) tan(u) at angle v
// (tan(u) < 0 just means angle v + pi), height above the moving centre h = z - lambda t =
// beta t cos(u). In the scaled coordinates rho = r t / alpha and eta = h / (beta t) the profile is
//   rho = tan(u), eta = cos(u),  i.e.  eta = 1 / sqrt(1 + rho^2)   (independent of t).
// For u in [0, pi/2) this is a dome: a round apex at eta = 1 (u = 0, curvature 1 in scaled units,
// eta ~ 1 - rho^2 / 2) that flares out to infinite radius as u -> pi/2 (eta -> 0). The branch
// u in (pi/2, pi] is its mirror image through eta = 0 (apex eta = -1 at u = pi). So over any
// u range eq. 7 is either an open cup or two open cups joined only "at infinity": the paper's
// picture must come from a u range that stops short of pi/2, closed off by something else.
//
// The interpretation used here
// ----------------------------
// * Head (leading end, exactly eq. 7): u in [0, uHead] with 0 < uHead < pi/2
//   (DrippingTearParams::headAngle, default pi/4). Its rim has scaled radius T = tan(uHead) at
//   eta_rim = cos(uHead) and slope d rho / d(-eta) = K = 1 / (sin(uHead) cos^2(uHead)).
// * Tail (trailing end, our closure): from the rim down to eq. 7's other pole, u = pi
//   (eta = -1, on the axis), with s in [0, 1]:
//     eta(s) = cos(uHead) - s (1 + cos(uHead)),
//     rho(s) = T + K L s - (T + K L) s^2,     L = 1 + cos(uHead) (the tail's scaled length).
//   rho(0) = T and rho'(0) matches the head's slope (a C1 join, no crease at the rim), rho(1) = 0
//   with rho'(1) = -(2T + K L) < 0 (the pointed tip of a teardrop), and rho > 0 in between
//   (a concave quadratic that is positive at 0 and zero at 1). eta decreases strictly along the
//   whole profile, so the surface is embedded (no self-intersection) for every t.
// * Both ends keep eq. 7's scaling: every vertex is (rho alpha / t cos v, rho alpha / t sin v,
//   eta beta t + lambda t). So the drop is one fixed shape stretched by alpha / t across and by
//   beta t along the axis: its width / height ratio is proportional to alpha / (beta t^2) and
//   strictly decreases as t grows (it narrows and elongates, as in the paper's figure 8), while
//   the frame centre (eta = 0, where eq. 7's two branches mirror) falls at speed lambda.
//   With the default headAngle the widest point (scaled radius 2) is at eta = 0 and the leading
//   apex is at eta = 1, the tip at eta = -1.
//
// Axis, direction and units
// -------------------------
// Local coordinates: the axis is +z and the drop falls towards +z (for lambda > 0). The round
// head (u = 0) leads at z = (beta + lambda) t, the pointed tip (u = pi) trails at
// z = (lambda - beta) t. With lambda = beta the tip stays at the origin while the drop grows
// (a drop hanging from the lid); with lambda > beta the whole drop leaves the origin.
// Units: t in seconds since the drop's start frame; alpha in metres * seconds (scaled radius 1 is
// alpha / t metres), beta and lambda in metres per second. The enclosed volume's centroid is at
// z = lambda t + c beta t for a constant c of the shape (c depends on headAngle only), so it falls
// at the constant speed lambda + c beta: eq. 7 has no acceleration. For the default headAngle
// c ~ 0.003 (the centroid practically rides on the eq. 7 centre) and the volume is about
// 13.45 alpha^2 beta / t (numerical integration of the profile): eq. 7 does not conserve volume,
// the drop loses volume as 1/t, which we keep rather than renormalise.
//
// Guards
// ------
// eq. 7 divides by t. The shape uses ts = max(t, minTime) (minTime > 0, default 0.25 s): before
// minTime the shape is frozen at its minTime shape, which also avoids the arbitrarily flat disc
// eq. 7 gives as t -> 0. The fall term uses tf = max(t, 0): the centre still moves with
// lambda t in [0, minTime], and before the start frame (t < 0) the drop waits at the origin.
// NaN or infinite t, non-positive or non-finite alpha / beta / minTime, non-finite lambda,
// a headAngle outside (0, 1.5] (1.5 rad keeps tan and the slope finite and sane), fewer than
// 2 rings or 3 segments throw InputError.
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

struct DrippingTearParams {
  float alpha = 0.0005f;        // metres * seconds: radius scale is alpha / t
  float beta = 0.004f;          // metres / second: half-length along the axis is beta t
  float lambda = 0.1f;          // metres / second: fall speed of the eq. 7 frame centre
  float headAngle = kPi / 4.0f; // radians, the u range [0, headAngle] taken exactly from eq. 7
  float minTime = 0.25f;        // seconds: the shape uses max(t, minTime) (division guard)
};

// eq. 7 itself at (u, v, t) with no guard (Lin & Cheng 2013 eq. 7); the caller keeps t != 0 and
// cos(u) != 0. Used by makeDrippingTear for the head and handy for checking it.
Vec3 drippingTearEq7(const DrippingTearParams& p, float u, float v, float t);

// The time the shape is evaluated at: max(t, p.minTime).
float drippingTearShapeTime(const DrippingTearParams& p, float t);

// Closed, outward-oriented drop in local coordinates (see above) with smooth vertex normals.
// Vertex layout, as makeEllipsoid: vertex 0 = leading apex (u = 0); then rings - 1 circles of
// `segments` vertices (circle i, segment j at angle v = 2 pi j / segments); last = trailing tip
// (u = pi). The first headRings = max(1, rings / 3) circles are the head: circle i has
// u = headAngle * i / headRings exactly as in eq. 7 (circle headRings is the rim); the other
// circles are the tail at s = (i - headRings) / (rings - headRings). No seam copies, no duplicate
// vertices, no degenerate triangles. The mesh depends only on its inputs (bitwise repeatable).
TriangleMesh makeDrippingTear(const DrippingTearParams& p, float t, int rings = 32, int segments = 48);

// Places a local-coordinate drop in the world, in place: rotates local +z onto the unit
// `gravity` direction (so the drop falls along gravity and its tip trails against it) and moves
// the local origin to `startPoint` (where the drop leaves the face). Throws InputError for a zero
// or non-finite gravity or a non-finite start point.
void placeDrippingTear(TriangleMesh& mesh, const Vec3& startPoint, const Vec3& gravity);

}  // namespace lacrima
