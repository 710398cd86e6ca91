#pragma once
// Math base of lacrima: Eigen aliases, constants and the orthonormal shading frame.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima {

using Vec2 = Eigen::Vector2f;
using Vec3 = Eigen::Vector3f;
using Vec4 = Eigen::Vector4f;
using Vec3d = Eigen::Vector3d;
using Vec2i = Eigen::Vector2i;
using Mat3 = Eigen::Matrix3f;
using Mat4 = Eigen::Matrix4f;
using Affine3 = Eigen::Transform<float, 3, Eigen::Affine>;
// Linear RGB in the rendering working space (ACEScg primaries); radiance or reflectance.
using Color = Eigen::Array3f;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kInv2Pi = 0.5f / kPi;
inline constexpr float kInv4Pi = 0.25f / kPi;

inline float degreesToRadians(float d) { return d * (kPi / 180.0f); }
inline float clamp01(float x) { return std::clamp(x, 0.0f, 1.0f); }
inline float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
inline float luminance(const Color& c) { return 0.2722287f * c.x() + 0.6740818f * c.y() + 0.0536895f * c.z(); }
inline bool isFinite(const Color& c) { return std::isfinite(c.x()) && std::isfinite(c.y()) && std::isfinite(c.z()); }

// Orthonormal basis around a unit normal; z is the normal.
// Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017 (branchless).
struct ShadingFrame {
  Vec3 s, t, n;

  static ShadingFrame fromNormal(const Vec3& n) {
    const float sign = std::copysign(1.0f, n.z());
    const float a = -1.0f / (sign + n.z());
    const float b = n.x() * n.y() * a;
    ShadingFrame f;
    f.s = Vec3(1.0f + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
    f.t = Vec3(b, sign + n.y() * n.y() * a, -n.y());
    f.n = n;
    return f;
  }
  Vec3 toLocal(const Vec3& v) const { return Vec3(v.dot(s), v.dot(t), v.dot(n)); }
  Vec3 toWorld(const Vec3& v) const { return s * v.x() + t * v.y() + n * v.z(); }
};

// Helpers on directions in a local shading frame (z = normal), as in pbrt.
inline float cosTheta(const Vec3& w) { return w.z(); }
inline float absCosTheta(const Vec3& w) { return std::abs(w.z()); }
inline bool sameHemisphere(const Vec3& a, const Vec3& b) { return a.z() * b.z() > 0.0f; }

}  // namespace lacrima
