// Specular manifold solver of MNEE; see lacrima/renderer/specular_manifold.hpp.
#include "specular_manifold.hpp"

#include <unsupported/Eigen/AutoDiff>

#include <Eigen/LU>
#include <type_traits>

namespace lacrima {

namespace {

// Forward-mode derivatives with respect to six parameters: (u, v) of the previous chain point,
// of the vertex itself and of the next one (for the last vertex: the endpoint's tangent
// coordinates a, b). A fixed size: no allocation.
using Derivatives = Eigen::Matrix<double, 6, 1>;
using Ad = Eigen::AutoDiffScalar<Derivatives>;
using Ad3 = Eigen::Matrix<Ad, 3, 1>;
constexpr int kPrevious = 0, kSelf = 2, kNext = 4;

template <class S>
Eigen::Matrix<S, 3, 1> unit(const Eigen::Matrix<S, 3, 1>& v) {
  using std::sqrt;
  return v / sqrt(v.dot(v));
}

// The patch's point and normal at its current parameters. With S = Ad both are differentiable
// in the two derivative slots starting at `slot`; with S = double they are plain values.
template <class S>
void evaluateAt(const SurfacePatch& patch, int slot, Eigen::Matrix<S, 3, 1>& position, Eigen::Matrix<S, 3, 1>& normal) {
  if constexpr (std::is_same_v<S, double>) {
    patch.evaluate(patch.uv.x(), patch.uv.y(), position, normal);
  } else {
    const S u(patch.uv.x(), 6, slot), v(patch.uv.y(), 6, slot + 1);
    patch.evaluate(u, v, position, normal);
  }
}

// The endpoint moved by (a, b) in its tangent frame, a and b differentiable in slots kNext (at
// a = b = 0, so the plain value is the endpoint itself).
template <class S>
Eigen::Matrix<S, 3, 1> endpointAt(const ManifoldEndpoint& end) {
  if constexpr (std::is_same_v<S, double>) {
    return end.point;
  } else {
    const S a(0.0, 6, kNext), b(0.0, 6, kNext + 1);
    const Eigen::Matrix<S, 3, 1> moved = end.point.cast<S>() + end.tangentS.cast<S>() * a + end.tangentT.cast<S>() * b;
    return end.atInfinity ? unit(moved) : moved;
  }
}

// The constraint of vertex i (Hanika et al. 2015 sec. 4, eq. 5, refraction with indices scaled
// as in Jakob & Marschner 2012 sec. 4.1): the tangential part of h = unit(w_in + eta w_out). The
// tangent frame is built from a fixed reference direction (the patch's edgeU) projected onto the
// tangent plane, so that it depends on the normal alone: h . s = h . t = 0 exactly when h is
// parallel to n, whatever the frame, and the frame's own derivative is exact.
template <class S>
Eigen::Matrix<S, 2, 1> vertexConstraint(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end, int i) {
  using V3 = Eigen::Matrix<S, 3, 1>;
  V3 previous, position, normal, next, unused;
  if (i == 0) previous = x0.cast<S>();
  else evaluateAt<S>(chain.vertices[i - 1].patch, kPrevious, previous, unused);
  evaluateAt<S>(chain.vertices[i].patch, kSelf, position, normal);
  V3 wOut;
  if (i + 1 < chain.count) {
    evaluateAt<S>(chain.vertices[i + 1].patch, kNext, next, unused);
    wOut = unit(V3(next - position));
  } else {
    next = endpointAt<S>(end);
    wOut = end.atInfinity ? next : unit(V3(next - position));
  }
  const V3 wIn = unit(V3(previous - position));
  const V3 h = unit(V3(wIn + wOut * S(chain.vertices[i].eta)));
  const V3 reference = chain.vertices[i].patch.edgeU.normalized().cast<S>();
  const V3 s = unit(V3(reference - normal * normal.dot(reference)));
  const V3 t = normal.cross(s);
  return {s.dot(h), t.dot(h)};
}

using ChainMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 2 * kMaxManifoldVertices, 2 * kMaxManifoldVertices>;
using ChainVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 2 * kMaxManifoldVertices, 1>;
using EndpointMatrix = Eigen::Matrix<double, Eigen::Dynamic, 2, 0, 2 * kMaxManifoldVertices, 2>;

// The constraints C (2k), their block-tridiagonal Jacobian A = dC/d(u1, v1 .. uk, vk) and
// B = dC/d(a, b) of the endpoint (nonzero in the last block row only), Hanika sec. 4.3.
struct Linearization {
  ChainVector constraints;
  ChainMatrix jacobian;
  EndpointMatrix endpoint;
};

Linearization linearize(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end) {
  const int n = 2 * chain.count;
  Linearization l{ChainVector::Zero(n), ChainMatrix::Zero(n, n), EndpointMatrix::Zero(n, 2)};
  for (int i = 0; i < chain.count; ++i) {
    const Eigen::Matrix<Ad, 2, 1> c = vertexConstraint<Ad>(x0, chain, end, i);
    for (int row = 0; row < 2; ++row) {
      const int r = 2 * i + row;
      const Derivatives& d = c[row].derivatives();
      l.constraints[r] = c[row].value();
      for (int col = 0; col < 2; ++col) {
        if (i > 0) l.jacobian(r, 2 * (i - 1) + col) = d[kPrevious + col];
        l.jacobian(r, 2 * i + col) = d[kSelf + col];
        if (i + 1 < chain.count) l.jacobian(r, 2 * (i + 1) + col) = d[kNext + col];
        else l.endpoint(r, col) = d[kNext + col];
      }
    }
  }
  return l;
}

// The chain after a Newton step of `scale` times `step`, each vertex projected back onto its
// surface in order (the projection of vertex i starts from the projected vertex i - 1).
std::optional<SpecularChain> steppedChain(const Vec3d& x0, const SpecularChain& chain, const ChainVector& step,
                                          double scale, const ManifoldProjection& projection) {
  SpecularChain moved = chain;
  Vec3d from = x0;
  for (int i = 0; i < chain.count; ++i) {
    SurfacePatch patch = chain.vertices[i].patch;
    patch.uv -= scale * step.segment<2>(2 * i);
    if (patch.kind == SurfacePatch::Kind::Sphere) {
      moved.vertices[i].patch = patch.rebased();
    } else {
      const std::optional<SurfacePatch> projected = projection.project(patch, from);
      if (!projected) return std::nullopt;
      moved.vertices[i].patch = *projected;
    }
    from = moved.vertices[i].patch.position();
  }
  return moved;
}

// The constraints' Euclidean norm: unlike the largest component, it does not depend on the
// tangent frames, which change when a sphere patch is rebased.
double constraintNorm(const ChainVector& v) { return v.norm(); }

// The same without derivatives (cheap: for trying steps).
double constraintNorm(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end) {
  double sum = 0.0;
  for (int i = 0; i < chain.count; ++i) sum += vertexConstraint<double>(x0, chain, end, i).squaredNorm();
  return std::sqrt(sum);
}

// A converged chain must refract at every vertex: w_in and w_out on opposite sides of the
// normal. (h parallel to n has "reflection-like" roots as well, which are not light paths.)
bool refractsEverywhere(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end) {
  Vec3d previous = x0;
  for (int i = 0; i < chain.count; ++i) {
    const Vec3d p = chain.vertices[i].patch.position(), n = chain.vertices[i].patch.shadingNormal();
    const Vec3d next = i + 1 < chain.count ? chain.vertices[i + 1].patch.position() : end.point;
    const Vec3d wOut = i + 1 < chain.count || !end.atInfinity ? Vec3d(next - p) : end.point;
    if ((previous - p).dot(n) * wOut.dot(n) >= 0.0) return false;
    previous = p;
  }
  return true;
}

}  // namespace

SurfacePatch SurfacePatch::sphere(const Vec3d& center, double radius, const Vec3d& unitNormal, unsigned surfaceId) {
  SurfacePatch p;
  p.kind = Kind::Sphere;
  p.origin = center;
  p.radius = radius;
  p.normal = unitNormal;
  // Any orthonormal tangents (Duff et al. 2017, as ShadingFrame).
  const ShadingFrame frame = ShadingFrame::fromNormal(unitNormal.cast<float>().normalized());
  p.edgeU = (frame.s.cast<double>() - unitNormal * unitNormal.dot(frame.s.cast<double>())).normalized();
  p.edgeV = unitNormal.cross(p.edgeU);
  p.surfaceId = surfaceId;
  return p;
}

Vec3d SurfacePatch::position() const {
  Vec3d p, n;
  evaluate(uv.x(), uv.y(), p, n);
  return p;
}

Vec3d SurfacePatch::shadingNormal() const {
  Vec3d p, n;
  evaluate(uv.x(), uv.y(), p, n);
  return n;
}

Vec3d SurfacePatch::geometricNormal() const {
  return kind == Kind::Triangle ? Vec3d(edgeU.cross(edgeV).normalized()) : shadingNormal();
}

SurfacePatch SurfacePatch::rebased() const {
  if (kind == Kind::Triangle) return *this;
  return sphere(origin, radius, shadingNormal(), surfaceId);
}

double manifoldConstraintError(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end) {
  return constraintNorm(x0, chain, end);
}

// Newton's method with step halving (Hanika et al. 2015 sec. 4.2, alg. 1): a step is accepted
// when the projection finds the surface and the constraints shrink; the scale then grows back.
bool solveSpecularChain(const Vec3d& x0, SpecularChain& chain, const ManifoldEndpoint& end,
                        const ManifoldProjection& projection, const ManifoldSolverOptions& options) {
  if (chain.count < 1 || chain.count > kMaxManifoldVertices) return false;
  double scale = 1.0;
  Linearization l = linearize(x0, chain, end);
  double error = constraintNorm(l.constraints);
  for (int iteration = 0; iteration < options.maxIterations; ++iteration) {
    if (!std::isfinite(error)) return false;
    if (error < options.tolerance) return refractsEverywhere(x0, chain, end);
    const Eigen::PartialPivLU<ChainMatrix> lu(l.jacobian);
    if (!(std::abs(lu.determinant()) > 1e-300)) return false;
    const ChainVector step = lu.solve(l.constraints);
    for (;;) {
      const std::optional<SpecularChain> moved = steppedChain(x0, chain, step, scale, projection);
      if (moved) {
        const double nextError = constraintNorm(x0, *moved, end);
        if (nextError < error) {
          chain = *moved;
          l = linearize(x0, chain, end);
          error = nextError;
          scale = std::min(1.0, 2.0 * scale);
          break;
        }
      }
      scale *= 0.5;
      if (scale < options.minStepScale) return false;
    }
  }
  return error < options.tolerance && refractsEverywhere(x0, chain, end);
}

// The generalized geometry term (Jakob & Marschner 2012 sec. 4.3 and 5.1, Hanika et al. 2015
// sec. 4.3), as the density of the direction w0 = unit(x1 - x0) per unit light area at y:
//   d w0     = |cos theta_1| dA(x1) / |x1 - x0|^2              (solid angle of an area element)
//   dA(x1)   = |dp1/du x dp1/dv| du1 dv1                       (x1's patch parametrisation)
//   so d w0  = |(dp1/du x dp1/dv) . w0| du1 dv1 / |x1 - x0|^2  (the cosine uses the true normal)
//   du1 dv1  = |det d(u1, v1)/d(a, b)| da db,  da db = dA(y)   ((a, b): orthonormal coordinates
//              in y's tangent plane; for a direction d, on the unit sphere's: da db = d omega(d))
//   d(U)/d(a, b) = -A^-1 B                                     (implicit function theorem on
//              C(U(a, b), a, b) = 0, A and B as in linearize(); the first two rows give u1, v1).
// With no specular vertex this reduces to the plain |cos theta_y| / |y - x0|^2.
double manifoldGeometryTerm(const Vec3d& x0, const SpecularChain& chain, const ManifoldEndpoint& end) {
  if (chain.count < 1) return 0.0;
  const Linearization l = linearize(x0, chain, end);
  const Eigen::PartialPivLU<ChainMatrix> lu(l.jacobian);
  if (!(std::abs(lu.determinant()) > 1e-300)) return 0.0;
  const EndpointMatrix dU = -lu.solve(l.endpoint);
  const double det = dU.topRows<2>().determinant();

  Ad3 p1, n1;
  evaluateAt<Ad>(chain.vertices[0].patch, kSelf, p1, n1);
  Vec3d dpdu, dpdv;
  for (int axis = 0; axis < 3; ++axis) {
    dpdu[axis] = p1[axis].derivatives()[kSelf];
    dpdv[axis] = p1[axis].derivatives()[kSelf + 1];
  }
  const Vec3d toX1 = chain.vertices[0].patch.position() - x0;
  const double distance2 = toX1.squaredNorm();
  const Vec3d w0 = toX1 / std::sqrt(distance2);
  return std::abs(det) * std::abs(dpdu.cross(dpdv).dot(w0)) / distance2;
}

}  // namespace lacrima
