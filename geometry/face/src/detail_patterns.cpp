// Detail pattern functions of Lin & Cheng 2013 section 3; guards and choices are documented in the header.
#include "lacrima/face/detail_patterns.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "lacrima/base/error.hpp"

namespace lacrima {
namespace {

constexpr double kFloatMax = std::numeric_limits<float>::max();

// NaN -> 0, everything else clamped to the float range (so +-inf -> +-FLT_MAX).
float toFiniteFloat(double v) {
  if (std::isnan(v)) return 0.0f;
  return static_cast<float>(std::clamp(v, -kFloatMax, kFloatMax));
}

// The paper's arctan(y / x), replaced by atan2 (0 at the origin, for either sign of zero).
double polarAngle(double x, double y) { return (x == 0.0 && y == 0.0) ? 0.0 : std::atan2(y, x); }

// d with |d| >= epsilon, keeping its sign (+ for 0).
double signedFloor(double d) {
  if (std::abs(d) >= kDetailPatternEpsilon) return d;
  return std::signbit(d) ? -kDetailPatternEpsilon : kDetailPatternEpsilon;
}

// Lin & Cheng 2013 eq. 1 in double, without the rest-level shift.
double foreheadPaper(double x, double y, double t, double alpha, double beta) {
  const double theta = polarAngle(x, y);
  const double s = std::sin((x * x + y * y) - t * std::sin(theta) - std::sin(beta * theta));
  return std::exp(alpha * std::abs(s * s));
}

uint64_t splitMix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

bool finite3(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

void validateEllipse(float a, float b, float innerRadius) {
  if (!(std::isfinite(a) && a > 0.0f) || !(std::isfinite(b) && b > 0.0f))
    throw InputError(fmt::format("detail pattern region: semi-axes must be positive and finite (a = {}, b = {})", a, b));
  if (!(innerRadius >= 0.0f && innerRadius < 1.0f))
    throw InputError(fmt::format("detail pattern region: innerRadius must be in [0, 1) (got {})", innerRadius));
}

}  // namespace

float foreheadWrinklePaperHeight(float x, float y, float t, float alpha, float beta) {
  return toFiniteFloat(foreheadPaper(x, y, t, alpha, beta));
}

float foreheadWrinkleHeight(float x, float y, float t, float alpha, float beta) {
  // expm1 form of e^(alpha s^2) - 1 keeps precision for shallow wrinkles.
  const double theta = polarAngle(x, y);
  const double dx = x, dy = y, dt = t;
  const double s = std::sin((dx * dx + dy * dy) - dt * std::sin(theta) - std::sin(double(beta) * theta));
  return toFiniteFloat(std::expm1(double(alpha) * std::abs(s * s)));
}

float eyeCornerWrinkleHeight(float x, float y, float t, float alpha, float beta, float gamma) {
  const double dx = x, dy = y;
  const double theta = polarAngle(dx, dy);
  const double r = std::sqrt(dx * dx + dy * dy);
  return toFiniteFloat(double(alpha) * std::exp(double(beta) * std::abs(r - double(t) * std::sin(double(gamma) * theta))));
}

float cheekWrinkleHeight(float x, float y, float t, float alpha, float beta) {
  const double dx = x, dy = y;
  return toFiniteFloat(double(alpha) * std::sin(double(beta) * std::sqrt(dx * dx + dy * dy) + double(t)));
}

float frownHeight(float x, float y, float t, float alpha, float beta) {
  const double divisor = signedFloor(double(beta) + double(t));
  return toFiniteFloat(double(alpha) * std::sin(double(x) * double(y) / divisor));
}

float dimpleHeight(float x, float y, float t) {
  const double dx = x, dy = y;
  const double argument = dx * dx + dy * dy + double(t);
  // std::max with NaN first returns NaN, which toFiniteFloat maps to 0.
  return toFiniteFloat(std::log(std::max(argument, kDetailPatternEpsilon)));
}

float eyePouchHeight(float x, float y, float t, float alpha, float beta, float gamma) {
  const double dt = t;
  const double c = std::cos(double(x) + double(alpha) * dt) + std::cos(double(y) + double(beta) * dt);
  double base = std::abs(c);
  if (gamma < 0.0f) base = std::max(base, kDetailPatternEpsilon);
  const double numerator = std::pow(base, double(gamma));
  return toFiniteFloat(numerator / std::max(dt, kDetailPatternEpsilon));
}

float detailPatternHeight(const BasicDetailPattern& p, float x, float y, float t) {
  switch (p.kind) {
    case DetailPatternKind::ForeheadWrinkles: return foreheadWrinkleHeight(x, y, t, p.alpha, p.beta);
    case DetailPatternKind::EyeCornerWrinkles: return eyeCornerWrinkleHeight(x, y, t, p.alpha, p.beta, p.gamma);
    case DetailPatternKind::CheekWrinkles: return cheekWrinkleHeight(x, y, t, p.alpha, p.beta);
    case DetailPatternKind::Frown: return frownHeight(x, y, t, p.alpha, p.beta);
    case DetailPatternKind::Dimple: return dimpleHeight(x, y, t);
    case DetailPatternKind::EyePouch: return eyePouchHeight(x, y, t, p.alpha, p.beta, p.gamma);
  }
  return 0.0f;
}

float detailPatternHeight(std::span<const BasicDetailPattern> patterns, float x, float y, float t) {
  double sum = 0.0;
  for (const BasicDetailPattern& p : patterns) sum += detailPatternHeight(p, x, y, t);
  return toFiniteFloat(sum);
}

float detailDamping(float x, float y, float a, float b, float innerRadius) {
  validateEllipse(a, b, innerRadius);
  const double u = double(x) / a, v = double(y) / b;
  const double rho = std::sqrt(u * u + v * v);
  if (!(rho < 1.0)) return 0.0f;  // also NaN
  if (rho <= innerRadius) return 1.0f;
  const double s = (1.0 - rho) / (1.0 - double(innerRadius));
  return static_cast<float>(s * s * s * (s * (s * 6.0 - 15.0) + 10.0));
}

bool isValidDetailVertex(size_t index, const ValidVertexSelection& selection) {
  if (selection.fraction >= 1.0f) return true;
  if (!(selection.fraction > 0.0f)) return false;
  const uint64_t h = splitMix64(selection.seed ^ splitMix64(static_cast<uint64_t>(index)));
  const double u = double(h >> 11) * 0x1.0p-53;  // uniform in [0, 1)
  return u < double(selection.fraction);
}

size_t applyDetailPattern(TriangleMesh& mesh, std::span<const Vec3> normals, const DetailRegion& region,
                          const DetailPatternApplication& application) {
  validateEllipse(region.semiAxisA, region.semiAxisB, region.innerRadius);
  if (!finite3(region.center))
    throw InputError("detail pattern region: centre is not finite");
  const Vec3& tx = region.tangentX;
  const Vec3& ty = region.tangentY;
  if (!finite3(tx) || !finite3(ty) || std::abs(tx.norm() - 1.0f) > 1e-3f || std::abs(ty.norm() - 1.0f) > 1e-3f ||
      std::abs(tx.dot(ty)) > 1e-3f)
    throw InputError("detail pattern region: tangentX and tangentY must be orthogonal unit vectors");
  if (std::isnan(region.maxNormalDistance) || region.maxNormalDistance < 0.0f)
    throw InputError(fmt::format("detail pattern region: maxNormalDistance must be >= 0 (got {})", region.maxNormalDistance));
  if (!(application.selection.fraction >= 0.0f && application.selection.fraction <= 1.0f))
    throw InputError(fmt::format("detail pattern: valid vertex fraction must be in [0, 1] (got {})",
                                 application.selection.fraction));
  if (!std::isfinite(application.patternOrigin.x()) || !std::isfinite(application.patternOrigin.y()))
    throw InputError("detail pattern: patternOrigin must be finite");
  if (!std::isfinite(application.heightScale) || !std::isfinite(application.coordinateScale) ||
      !std::isfinite(application.time))
    throw InputError(fmt::format("detail pattern: heightScale ({}), coordinateScale ({}) and time ({}) must be finite",
                                 application.heightScale, application.coordinateScale, application.time));
  if (normals.size() != mesh.vertexCount())
    throw std::invalid_argument(fmt::format("applyDetailPattern: {} normals for {} vertices", normals.size(),
                                            mesh.vertexCount()));

  const Vec3 tz = tx.cross(ty).normalized();
  size_t moved = 0;
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    Vec3& p = mesh.positions[i];
    const Vec3 d = p - region.center;
    const float x = d.dot(tx), y = d.dot(ty);
    if (!(std::abs(d.dot(tz)) <= region.maxNormalDistance)) continue;
    const float damping = detailDamping(x, y, region.semiAxisA, region.semiAxisB, region.innerRadius);
    if (damping == 0.0f) continue;  // outside the ellipse (or non-finite position)
    if (!isValidDetailVertex(i, application.selection)) continue;
    const Vec3& n = normals[i];
    if (!finite3(n)) continue;
    const double length = n.cast<double>().norm();
    if (!(length > 0.0) || !std::isfinite(length)) continue;
    const float height = detailPatternHeight(application.patterns,
                                             application.coordinateScale * (x - application.patternOrigin.x()),
                                             application.coordinateScale * (y - application.patternOrigin.y()),
                                             application.time);
    const double amount = double(application.heightScale) * double(damping) * double(height);
    if (amount == 0.0) continue;
    const Eigen::Vector3d moved3 = p.cast<double>() + n.cast<double>() * (amount / length);
    for (int k = 0; k < 3; ++k) p[k] = toFiniteFloat(moved3[k]);
    ++moved;
  }
  return moved;
}

}  // namespace lacrima
