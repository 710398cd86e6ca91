// The MNEE specular manifold solver (specular_manifold.hpp) on analytic surfaces: a flat water
// surface, where Snell's law has a one-dimensional solution and the paraxial geometry term a
// closed form, and a water sphere, checked against an independent 2-D ray shooting solution and
// against finite differences of re-solved chains.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lacrima/materials/material.hpp"
#include "specular_manifold.hpp"

namespace lacrima {
namespace specular_manifold_test {

constexpr double kWater = kTearIor;

// The plane z = 0 as one big triangle patch, seeded at (x, y).
SurfacePatch waterPlane(double x, double y) {
  SurfacePatch p;
  p.origin = Vec3d(-10, -10, 0);
  p.edgeU = Vec3d(20, 0, 0);
  p.edgeV = Vec3d(0, 20, 0);
  p.normal = Vec3d(0, 0, 1);
  p.uv = Vec2d((x + 10) / 20, (y + 10) / 20);
  return p;
}

ManifoldEndpoint lightPoint(const Vec3d& y) {
  ManifoldEndpoint end;
  end.point = y;
  end.tangentS = Vec3d(1, 0, 0);
  end.tangentT = Vec3d(0, 1, 0);
  return end;
}

// x0 under water at depth h1, the light point y at height h2 in the air, offset D along x.
struct FlatSetup {
  double h1 = 0.3, h2 = 0.7, D = 0.5;
  Vec3d x0() const { return Vec3d(0, 0, -h1); }
  Vec3d y() const { return Vec3d(D, 0, h2); }
  SpecularChain seed() const {
    SpecularChain chain;
    chain.count = 1;
    chain.vertices[0] = {waterPlane(D * h1 / (h1 + h2), 0.0), 1.0 / kWater};  // the straight line's crossing
    return chain;
  }
};

// Snell's law along x for the flat setup, solved by bisection: n_w sin(theta_w) = sin(theta_a).
double flatRefractionPoint(const FlatSetup& s) {
  double lo = 0.0, hi = s.D;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.5 * (lo + hi);
    const double snell = kWater * x / std::hypot(x, s.h1) - (s.D - x) / std::hypot(s.D - x, s.h2);
    (snell > 0.0 ? hi : lo) = x;
  }
  return 0.5 * (lo + hi);
}

TEST(SpecularManifold, FlatWaterSurfaceConvergesToSnellsPoint) {
  const FlatSetup s;
  SpecularChain chain = s.seed();
  ManifoldSolverOptions tight;
  tight.tolerance = 1e-12;
  ASSERT_TRUE(solveSpecularChain(s.x0(), chain, lightPoint(s.y()), StayOnPatch{}, tight));
  const Vec3d x1 = chain.vertices[0].patch.position();
  EXPECT_NEAR(x1.x(), flatRefractionPoint(s), 1e-9);
  EXPECT_NEAR(x1.y(), 0.0, 1e-9);
  EXPECT_NEAR(x1.z(), 0.0, 1e-12);
  // The seed (the straight line) is far from it: the solver did move the vertex.
  EXPECT_GT(std::abs(s.seed().vertices[0].patch.position().x() - x1.x()), 0.02);
}

// Straight above at normal incidence, paraxial optics: a ray leaving x0 at a small angle t
// meets the surface at h1 t and reaches height h2 at r = t (h1 + n h2), n = n_water / n_air, so
// d omega_0 = t dt dphi maps to dA(y) = r dr dphi: G = 1 / (h1 + n h2)^2 (exact in the limit).
TEST(SpecularManifold, FlatWaterGeometryTermMatchesParaxialOptics) {
  FlatSetup s;
  s.D = 0.0;
  SpecularChain chain = s.seed();
  ASSERT_TRUE(solveSpecularChain(s.x0(), chain, lightPoint(s.y()), StayOnPatch{}));
  const double expected = 1.0 / ((s.h1 + kWater * s.h2) * (s.h1 + kWater * s.h2));
  EXPECT_NEAR(manifoldGeometryTerm(s.x0(), chain, lightPoint(s.y())), expected, 1e-9 * expected);
  // Without refraction it would be 1 / (h1 + h2)^2, 25% higher: the test tells them apart.
  EXPECT_GT(1.0 / ((s.h1 + s.h2) * (s.h1 + s.h2)), 1.2 * expected);
}

// --- the water sphere ------------------------------------------------------------------------

constexpr double kRadius = 1.0;

SurfacePatch sphereAt(const Vec3d& point) { return SurfacePatch::sphere(Vec3d::Zero(), kRadius, point.normalized(), 7); }

// Both crossings of the straight segment x0 -> y with the unit sphere at the origin.
SpecularChain sphereSeed(const Vec3d& x0, const Vec3d& y) {
  const Vec3d d = (y - x0).normalized();
  const double b = x0.dot(d), c = x0.squaredNorm() - kRadius * kRadius;
  const double root = std::sqrt(b * b - c);
  SpecularChain chain;
  chain.count = 2;
  chain.vertices[0] = {sphereAt(x0 + (-b - root) * d), kWater};        // air -> water
  chain.vertices[1] = {sphereAt(x0 + (-b + root) * d), 1.0 / kWater};  // water -> air
  return chain;
}

// Where a ray from x0 at angle phi (in the z = 0 plane) leaves the sphere after two
// refractions, and its direction; nothing when it misses or is totally reflected.
struct Ray2 {
  Vec3d exit, direction, entry;
};
std::optional<Ray2> shootThroughSphere(const Vec3d& x0, double phi) {
  const Vec3d d(std::cos(phi), std::sin(phi), 0.0);
  const double b = x0.dot(d), c = x0.squaredNorm() - 1.0;
  if (b * b - c <= 0.0) return std::nullopt;
  const Vec3d entry = x0 + (-b - std::sqrt(b * b - c)) * d;
  // Refraction in double precision, so that the reference is not limited by float: Snell in vector form.
  const auto refractD = [](const Vec3d& wi, Vec3d n, double eta) -> std::optional<Vec3d> {
    double cosI = n.dot(wi);
    if (cosI < 0) { eta = 1 / eta; cosI = -cosI; n = -n; }
    const double sin2T = (1 - cosI * cosI) / (eta * eta);
    if (sin2T >= 1) return std::nullopt;
    return Vec3d(-wi / eta + (cosI / eta - std::sqrt(1 - sin2T)) * n);
  };
  const auto inside = refractD(-d, entry.normalized(), kWater);
  if (!inside) return std::nullopt;
  const double b2 = entry.dot(*inside);
  const Vec3d exit = entry + (-2.0 * b2) * *inside;  // the other root of |entry + t w| = 1
  const auto out = refractD(-*inside, exit.normalized(), kWater);
  if (!out) return std::nullopt;
  return Ray2{exit, *out, entry};
}

// The signed side of y relative to the ray leaving the sphere (zero when it passes through y).
double missBy(const Vec3d& x0, const Vec3d& y, double phi) {
  const auto r = shootThroughSphere(x0, phi);
  if (!r) return std::nan("");
  return r->direction.cross(y - r->exit).z();
}

TEST(SpecularManifold, WaterSphereConvergesToTheShotRefractionPath) {
  const Vec3d x0(0.1, -3.0, 0.0), y(-0.1, 4.0, 0.0);
  SpecularChain chain = sphereSeed(x0, y);
  ManifoldSolverOptions tight;
  tight.tolerance = 1e-12;
  ASSERT_TRUE(solveSpecularChain(x0, chain, lightPoint(y), StayOnPatch{}, tight));
  const Vec3d x1 = chain.vertices[0].patch.position(), x2 = chain.vertices[1].patch.position();
  EXPECT_NEAR(x1.norm(), 1.0, 1e-12);
  EXPECT_NEAR(x2.norm(), 1.0, 1e-12);

  // The reference: the ray from x0 whose refracted path passes through y, by bisection on its
  // angle near the solver's direction (a bracket of +-2 degrees).
  const double phi = std::atan2((x1 - x0).y(), (x1 - x0).x());
  double lo = phi - 0.035, hi = phi + 0.035;
  ASSERT_LT(missBy(x0, y, lo) * missBy(x0, y, hi), 0.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (missBy(x0, y, mid) * missBy(x0, y, lo) > 0.0 ? lo : hi) = mid;
  }
  const auto reference = shootThroughSphere(x0, 0.5 * (lo + hi));
  ASSERT_TRUE(reference);
  EXPECT_LT((x1 - reference->entry).norm(), 1e-5);
  EXPECT_LT((x2 - reference->exit).norm(), 1e-5);
  // The seed was the straight line, well away from the solution.
  EXPECT_GT((sphereSeed(x0, y).vertices[0].patch.position() - x1).norm(), 0.02);
}

// The geometry term against finite differences: move the endpoint by +-delta along its tangents,
// solve again, and measure the solid angle swept by w0 = unit(x1 - x0) per unit endpoint measure.
double finiteDifferenceGeometry(const Vec3d& x0, const SpecularChain& solved, const ManifoldEndpoint& end) {
  const double delta = 1e-5;
  ManifoldSolverOptions tight;
  tight.tolerance = 1e-13;
  const auto w0 = [&](double a, double b) {
    ManifoldEndpoint moved = end;
    moved.point = end.point + a * end.tangentS + b * end.tangentT;
    if (end.atInfinity) moved.point.normalize();
    SpecularChain chain = solved;
    EXPECT_TRUE(solveSpecularChain(x0, chain, moved, StayOnPatch{}, tight));
    return Vec3d((chain.vertices[0].patch.position() - x0).normalized());
  };
  const Vec3d dA = (w0(delta, 0) - w0(-delta, 0)) / (2 * delta);
  const Vec3d dB = (w0(0, delta) - w0(0, -delta)) / (2 * delta);
  return dA.cross(dB).norm();
}

TEST(SpecularManifold, SphereGeometryTermMatchesFiniteDifferences) {
  const Vec3d x0(0.04, -3.0, 0.03), y(-0.05, 4.0, 0.02);
  ManifoldEndpoint end = lightPoint(y);
  end.tangentS = Vec3d(1, 0, 0);
  end.tangentT = Vec3d(0, 0, 1);  // a light facing -y
  SpecularChain chain = sphereSeed(x0, y);
  ASSERT_TRUE(solveSpecularChain(x0, chain, end, StayOnPatch{}));
  const double g = manifoldGeometryTerm(x0, chain, end);
  EXPECT_NEAR(g, finiteDifferenceGeometry(x0, chain, end), 1e-4 * g);
  // The focusing is real: far more than the unrefracted 1 / |y - x0|^2 (a defocused or
  // doubled term fails the finite-difference check above; this one shows what is at stake).
  EXPECT_GT(g, 2.0 / (y - x0).squaredNorm());
}

TEST(SpecularManifold, DirectionAtInfinityGeometryTermMatchesFiniteDifferences) {
  const Vec3d x0(0.3, -2.5, -0.2);
  ManifoldEndpoint end;
  end.atInfinity = true;
  end.point = Vec3d(-0.1, 1.0, 0.05).normalized();
  end.tangentS = end.point.cross(Vec3d(0, 0, 1)).normalized();
  end.tangentT = end.point.cross(end.tangentS);
  const Vec3d far = x0 + 10.0 * end.point;
  SpecularChain chain = sphereSeed(x0, far);
  ASSERT_TRUE(solveSpecularChain(x0, chain, end, StayOnPatch{}));
  EXPECT_LT(manifoldConstraintError(x0, chain, end), 1e-7);
  // The ray leaves along d.
  const Vec3d x1 = chain.vertices[0].patch.position();
  const double g = manifoldGeometryTerm(x0, chain, end);
  EXPECT_NEAR(g, finiteDifferenceGeometry(x0, chain, end), 1e-4 * g);
  EXPECT_GT((x1 - x0).normalized().dot(end.point), 0.9);
}

// Both ends under the water: h = w_in + eta w_out can still be parallel to the normal (a
// "reflection-like" root), but no refraction connects them: the solver must say so.
TEST(SpecularManifold, EndsOnTheSameSideHaveNoRefractionPath) {
  const FlatSetup s;
  const Vec3d yUnderWater(s.D, 0.0, -s.h2);
  SpecularChain chain = s.seed();
  EXPECT_FALSE(solveSpecularChain(s.x0(), chain, lightPoint(yUnderWater), StayOnPatch{}));
}

}  // namespace specular_manifold_test
}  // namespace lacrima
