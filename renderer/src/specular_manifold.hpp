#pragma once
// Manifold next-event estimation (MNEE): Hanika, Droske & Fascione 2015, "Manifold Next Event
// Estimation", CGF 34(4), built on Jakob & Marschner 2012, "Manifold Exploration", SIGGRAPH.
//
// A chain x0 -> x1 .. xk -> y connects a fixed non-specular point x0 to a fixed light point y
// (or a fixed direction d at infinity) through k smooth refracting interfaces. Each specular
// vertex xi must satisfy Snell's law: the generalized half vector of refraction
//     h_i = normalize(w_in + eta_i w_out),  w_in = unit(x_{i-1} - x_i), w_out = unit(x_{i+1} - x_i),
// eta_i = n(x_{i+1} side) / n(x_{i-1} side), is parallel to the surface normal there, so its
// projection onto the vertex's tangent frame vanishes (Hanika et al. 2015 sec. 4, eq. 5; Jakob &
// Marschner 2012 sec. 4.1, eq. 4 and fig. 6, with the indices scaled). Newton's method on these
// 2k constraints over the vertices' surface parameters finds the chain (Hanika sec. 4.2).
//
// Each vertex lives on a SurfacePatch: a triangle with interpolated shading normals (the normal
// varies linearly in the barycentrics and is normalised) or an exact sphere; the derivatives of
// the constraints are exact (forward-mode automatic differentiation in double precision).
#include <array>
#include <optional>

#include "lacrima/base/math.hpp"

namespace lacrima {

using Vec2d = Eigen::Vector2d;

// A local parametrisation (u, v) -> (position, shading normal) of the surface around a vertex.
struct SurfacePatch {
  enum class Kind { Triangle, Sphere };
  Kind kind = Kind::Triangle;
  // Triangle: p = origin + u edgeU + v edgeV, n = unit(normal + u normalU + v normalV), (u, v)
  //           the barycentrics of Embree (p = (1-u-v) P0 + u P1 + v P2).
  // Sphere:   n = unit(normal + u edgeU + v edgeV) (edgeU, edgeV unit tangents at normal),
  //           p = origin + radius n; (0, 0) is the point where the patch was made.
  Vec3d origin = Vec3d::Zero();
  Vec3d edgeU = Vec3d::UnitX(), edgeV = Vec3d::UnitY();
  Vec3d normal = Vec3d::UnitZ(), normalU = Vec3d::Zero(), normalV = Vec3d::Zero();
  double radius = 0.0;
  Vec2d uv = Vec2d::Zero();  // the vertex's current parameters
  unsigned surfaceId = 0;    // which surface (Embree geometry) the patch lies on

  static SurfacePatch sphere(const Vec3d& center, double radius, const Vec3d& unitNormal, unsigned surfaceId);

  template <class S>
  void evaluate(const S& u, const S& v, Eigen::Matrix<S, 3, 1>& position, Eigen::Matrix<S, 3, 1>& unitNormal) const {
    using V3 = Eigen::Matrix<S, 3, 1>;
    if (kind == Kind::Triangle) {
      position = origin.cast<S>() + edgeU.cast<S>() * u + edgeV.cast<S>() * v;
      const V3 n = normal.cast<S>() + normalU.cast<S>() * u + normalV.cast<S>() * v;
      unitNormal = n / n.norm();
    } else {
      const V3 n = normal.cast<S>() + edgeU.cast<S>() * u + edgeV.cast<S>() * v;
      unitNormal = n / n.norm();
      position = origin.cast<S>() + unitNormal * S(radius);
    }
  }
  Vec3d position() const;
  Vec3d shadingNormal() const;
  // Unit; a triangle's winding normal (as EmbreeScene's), a sphere's outward normal.
  Vec3d geometricNormal() const;
  // A sphere patch made again around its current point (uv = 0 there), so that Newton steps
  // stay well conditioned however far the vertex moves.
  SurfacePatch rebased() const;
};

// The fixed end of the chain: a point on a light with an orthonormal tangent frame of the light
// surface there, or a direction (towards the environment) with two unit vectors orthogonal to it.
struct ManifoldEndpoint {
  Vec3d point = Vec3d::Zero();  // or the unit direction when atInfinity
  Vec3d tangentS = Vec3d::UnitX(), tangentT = Vec3d::UnitY();
  bool atInfinity = false;
};

inline constexpr int kMaxManifoldVertices = 2;

struct ManifoldVertex {
  SurfacePatch patch;
  double eta = 1.0;  // n(next side) / n(previous side), the relative index crossed towards the light
};

struct SpecularChain {
  std::array<ManifoldVertex, kMaxManifoldVertices> vertices;
  int count = 0;
};

// Moves a triangle vertex onto the scene's surface after a Newton step (Hanika sec. 4.2: the
// step is taken in the tangent plane and projected back). `moved` is the vertex's patch at its
// new parameters, `from` the (already projected) previous chain point. Nothing when the surface
// is not found there, which halves the step.
class ManifoldProjection {
 public:
  virtual ~ManifoldProjection() = default;
  virtual std::optional<SurfacePatch> project(const SurfacePatch& moved, const Vec3d& from) const = 0;
};

// Keeps a moved vertex on its own patch: exact for planes and for spheres (unit tests).
class StayOnPatch final : public ManifoldProjection {
 public:
  std::optional<SurfacePatch> project(const SurfacePatch& moved, const Vec3d&) const override { return moved; }
};

struct ManifoldSolverOptions {
  int maxIterations = 20;
  double tolerance = 1e-7;     // on |h_tangent|, i.e. about the angle (radians) Snell's law is off
  double minStepScale = 1.0 / 64;  // give up when step halving gets below this
};

// Solves the chain's constraints by Newton's method from the seed `chain` (its vertices' patches
// at their seed parameters); on success the chain holds the solution. Sphere patches move
// analytically; triangle patches go through `projection`.
bool solveSpecularChain(const Vec3d& x0, SpecularChain& chain, const ManifoldEndpoint& end,
                        const ManifoldProjection& projection, const ManifoldSolverOptions& options = {});

// The constraint vector's Euclidean norm at the chain as it is (0 at an exact solution).
double manifoldConstraintError(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end);

// The generalized geometry term of the solved chain, without the cosine at x0: the density
// |d omega_0 / d A(y)| of the direction leaving x0 per unit area of the light at y (per unit
// solid angle of the direction d when the end is at infinity). See specular_manifold.cpp.
double manifoldGeometryTerm(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end);

}  // namespace lacrima
