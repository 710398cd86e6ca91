#pragma once
// Detail pattern functions: animated wrinkles, dimples and eye-pouch trembling displaced onto a
// region of a face mesh (Lin & Cheng 2013, section 3: "Adding Detailed Animated Expressions").
//
// The paper writes every basic pattern as an implicit surface p = h(x, y, t) - z in a local frame
// (x, y tangent, z normal); the functions below return the displacement height h. Their
// parameters alpha, beta, gamma are those of the paper. A pattern is applied as
//   displacement = heightScale * damping(x, y) * P(x, y, t),   P = p1 + p2 + ...  (the paper's
// "primary function", a sum of heights), along each vertex's normal.
//
// Guards (where the paper's formulas are singular or undefined). Heights are computed in double
// precision; whatever remains NaN becomes 0 and whatever remains infinite or beyond the float
// range is clamped to +-FLT_MAX, so no function here returns NaN or inf (non-finite inputs give 0
// or a clamped value, never NaN).
//  * arctan(y / x) (eqs. 1, 2): we use theta = atan2(y, x), with theta = 0 at the origin
//    (x = y = 0, either sign of zero). This is the paper's angle where x > 0. Where x < 0 it
//    differs by +-pi (atan2 covers (-pi, pi], the paper's arctan(y/x) only (-pi/2, pi/2)), so the
//    patterns differ from the paper's in the half-plane x < 0: the paper's pattern is point
//    symmetric (h(-x, -y) = h(x, y)) and has a seam along the y axis (x = 0, where arctan(y/x)
//    jumps from pi/2 to -pi/2: the t * sin(theta) term of eq. 1 jumps by 2t). With atan2 the seam
//    moves to the negative x axis, and vanishes there when beta (eq. 1) / gamma (eq. 2) is an
//    integer; sin(theta) itself is continuous. On the y axis (x = +-0, y != 0) theta = +-pi/2
//    (sign of y), the limit of the paper's angle from the x > 0 side.
//  * eq. 1 rest level: e^(alpha * sin(...)^2) is >= 1 everywhere (for alpha >= 0), so the paper's
//    height would push the whole region out by at least 1. foreheadWrinkleHeight returns the
//    paper's value minus 1 (= e^0, the level where the sine vanishes: the minimum for alpha >= 0,
//    the maximum for alpha < 0). The result is 0 on the wrinkle lines and has the sign of alpha,
//    and the wrinkle shape itself is untouched at every t. Subtracting the value at t = 0 instead
//    was rejected: it would cancel the static wrinkles and leave only their change over time.
//    foreheadWrinklePaperHeight gives the unshifted value. The other patterns are the paper's as
//    written (their offsets, e.g. alpha in eq. 2, are part of the shape and fade with damping).
//  * log(x^2 + y^2 + t) (eq. 5): the argument is floored at kDetailPatternEpsilon (1e-6), so the
//    centre at t = 0 is log(1e-6) ~ -13.8 instead of -inf; negative t is handled by the same floor.
//  * / t (eq. 6): the divisor is max(t, kDetailPatternEpsilon); t is time and meant to be > 0,
//    negative t is treated as the epsilon. Heights near t = 0 are huge, as in the paper
//    (up to 2^gamma / 1e-6); start eye-pouch animations at t well above 0.
//  * / (beta + t) (eq. 4): a divisor with |beta + t| < kDetailPatternEpsilon is replaced by
//    +-kDetailPatternEpsilon with its sign (+ for 0). sin() of the huge argument stays within
//    [-alpha, alpha]; the paper's function has no limit there.
//  * |(c)^gamma| with c = cos(x + alpha t) + cos(y + beta t) (eq. 6): computed as |c|^gamma, the
//    modulus of the (principal, complex) power, so it is defined for negative c and fractional
//    gamma and equals the paper's |c^gamma| wherever that is real. 0^gamma: 0 for gamma > 0,
//    1 for gamma = 0; for gamma < 0, |c| is floored at kDetailPatternEpsilon (no 1/0).
//
// Damping: detailDamping is 1 for a normalised elliptical radius rho = sqrt((x/a)^2 + (y/b)^2) up
// to innerRadius, 0 for rho >= 1, and in between the quintic smootherstep 6s^5 - 15s^4 + 10s^3 of
// s = (1 - rho) / (1 - innerRadius) (Perlin 2002, "Improving noise"). Its first and second
// derivatives vanish at both ends, so the displaced surface keeps continuous slope (shading
// normals) and curvature (no highlight crease) across the inner ring and the border, where a
// C1 smoothstep would leave a curvature jump.
//
// Dynamic animation (section 3.1.5): the paper displaces only n randomly chosen "valid" vertices
// of the N in the region and keeps the others null. ValidVertexSelection picks each vertex
// independently with probability `fraction` by hashing (seed, vertex index) (SplitMix64): the same
// seed gives the same subset on every platform, the subset covers the region uniformly, and a
// vertex's validity does not depend on the region or the other vertices. The count is therefore
// binomial around fraction * N, not exactly n. Invalid vertices get no displacement at all (they
// stay bitwise unchanged). Vary the seed per frame for flickering detail.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

// Floor for the divisors and the log argument of the patterns (see the guards above).
inline constexpr double kDetailPatternEpsilon = 1e-6;

// Lin & Cheng 2013 eq. 1 (forehead wrinkles), the paper's value:
//   e^(alpha * |sin((x^2 + y^2) - t sin(theta) - sin(beta theta))^2|), theta = atan2(y, x).
// alpha: depth of the wrinkles; beta: their style.
float foreheadWrinklePaperHeight(float x, float y, float t, float alpha, float beta);
// Lin & Cheng 2013 eq. 1 minus its rest level 1 (see above): 0 on the wrinkle lines, sign of alpha.
float foreheadWrinkleHeight(float x, float y, float t, float alpha, float beta);

// Lin & Cheng 2013 eq. 2 (eye-corner wrinkles): alpha * e^(beta * |sqrt(x^2 + y^2) - t sin(gamma theta)|).
// alpha: depth; beta: a preset constant; gamma: number of wrinkles.
float eyeCornerWrinkleHeight(float x, float y, float t, float alpha, float beta, float gamma);

// Lin & Cheng 2013 eq. 3 (cheek wrinkles): alpha * sin(beta * sqrt(x^2 + y^2) + t).
// alpha: depth; beta: number of wrinkles.
float cheekWrinkleHeight(float x, float y, float t, float alpha, float beta);

// Lin & Cheng 2013 eq. 4 (frown): alpha * sin(x y / (beta + t)). alpha: depth; beta: wrinkle spacing.
float frownHeight(float x, float y, float t, float alpha, float beta);

// Lin & Cheng 2013 eq. 5 (dimple): log(x^2 + y^2 + t) (natural log; no parameters in the paper).
float dimpleHeight(float x, float y, float t);

// Lin & Cheng 2013 eq. 6 (eye-pouch trembling): |(cos(x + alpha t) + cos(y + beta t))^gamma| / t.
// alpha, beta: trembling style; gamma: height of the skin sticking out.
float eyePouchHeight(float x, float y, float t, float alpha, float beta, float gamma);

enum class DetailPatternKind { ForeheadWrinkles, EyeCornerWrinkles, CheekWrinkles, Frown, Dimple, EyePouch };

// One basic pattern p_i with the paper's parameters (unused ones are ignored; Dimple uses none).
// ForeheadWrinkles uses foreheadWrinkleHeight (rest level removed).
struct BasicDetailPattern {
  DetailPatternKind kind = DetailPatternKind::CheekWrinkles;
  float alpha = 1.0f;
  float beta = 1.0f;
  float gamma = 1.0f;
};

float detailPatternHeight(const BasicDetailPattern& pattern, float x, float y, float t);

// The primary function P = p1 + p2 + ... (sum of the heights, in double; 0 for no patterns).
float detailPatternHeight(std::span<const BasicDetailPattern> patterns, float x, float y, float t);

// Damping over the ellipse with semi-axes a, b (local x, y), see above. 1 for rho <= innerRadius,
// 0 for rho >= 1 (and for non-finite x or y). Throws InputError unless a, b > 0 and finite and
// 0 <= innerRadius < 1.
float detailDamping(float x, float y, float a, float b, float innerRadius);

// Where a pattern sits on the mesh. The caller gives the local frame: centre, tangent x, tangent y
// (unit length and orthogonal within 1e-3) and the ellipse. A vertex is in the region when its
// local (x, y) = ((p - centre).tangentX, (p - centre).tangentY) has rho < 1 and its distance along
// tangentX x tangentY, |(p - centre).normal|, is at most maxNormalDistance (keeps the far side of
// a head out of a cheek region; infinite by default).
struct DetailRegion {
  Vec3 center = Vec3::Zero();
  Vec3 tangentX = Vec3::UnitX();
  Vec3 tangentY = Vec3::UnitY();
  float semiAxisA = 1.0f;    // ellipse semi-axis along tangentX, world units
  float semiAxisB = 1.0f;    // ellipse semi-axis along tangentY, world units
  float innerRadius = 0.5f;  // damping is 1 up to this normalised elliptical radius
  float maxNormalDistance = std::numeric_limits<float>::infinity();
};

struct ValidVertexSelection {
  float fraction = 1.0f;  // probability that a vertex is valid, in [0, 1]
  uint64_t seed = 0;
};

// Whether vertex `index` is valid under the selection (deterministic hash of seed and index).
// fraction >= 1 makes every vertex valid, fraction <= 0 none.
bool isValidDetailVertex(size_t index, const ValidVertexSelection& selection);

struct DetailPatternApplication {
  std::span<const BasicDetailPattern> patterns;  // P = sum of these
  float time = 0.0f;                             // t
  float heightScale = 1.0f;       // world units per unit of pattern height
  float coordinateScale = 1.0f;   // pattern units per world unit in the tangent plane
  // Where the pattern's origin (x = y = 0) lies in the region's local (x, y), world units. The
  // damping stays centred on the region: an origin outside it shows only an outer part of the
  // pattern (e.g. eq. 1's rings centred below the forehead read as horizontal wrinkle arcs).
  Vec2 patternOrigin = Vec2::Zero();
  ValidVertexSelection selection;  // fraction 1: every vertex in the region is valid
};

// Displaces each valid vertex in the region along its normal (normalised; one per vertex) by
//   heightScale * detailDamping(x, y, a, b, innerRadius) * P(coordinateScale (x - ox), coordinateScale (y - oy), t)
// with (x, y) its local coordinates and (ox, oy) the patternOrigin. Vertices outside the region, invalid ones, ones whose normal
// is zero or not finite and ones whose displacement is exactly 0 are left bitwise unchanged; a
// displaced coordinate is clamped to the float range. Only positions change (recompute normals
// afterwards if needed). `normals` may be mesh.normals. Returns the number of vertices moved.
// Throws InputError for a bad region, selection fraction or scale, and std::invalid_argument when
// normals.size() != mesh.vertexCount().
size_t applyDetailPattern(TriangleMesh& mesh, std::span<const Vec3> normals, const DetailRegion& region,
                          const DetailPatternApplication& application);

}  // namespace lacrima
