// Keyframe interpolation: step, linear, Catmull-Rom, monotone cubic; hold outside the keys.
#include <gtest/gtest.h>

#include "lacrima/base/animation_curve.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima {
namespace animation_curve_test {

const std::vector<ScalarKey> kKeys = {{0.0f, 1.0f}, {1.0f, 3.0f}, {3.0f, 2.0f}, {4.0f, 5.0f}};
constexpr Interpolation kAll[] = {Interpolation::Step, Interpolation::Linear, Interpolation::CatmullRom,
                                  Interpolation::MonotoneCubic};

TEST(AnimationCurve, EveryInterpolationPassesThroughTheKeys) {
  for (Interpolation mode : kAll) {
    const ScalarCurve curve(kKeys, mode);
    for (const ScalarKey& k : kKeys) EXPECT_FLOAT_EQ(curve.evaluate(k.time), k.value) << int(mode);
  }
}

TEST(AnimationCurve, HoldsTheEndValuesOutsideTheKeys) {
  for (Interpolation mode : kAll) {
    const ScalarCurve curve(kKeys, mode);
    EXPECT_EQ(curve.evaluate(-5.0f), 1.0f) << int(mode);
    EXPECT_EQ(curve.evaluate(4.0001f), 5.0f) << int(mode);
    EXPECT_EQ(curve.evaluate(1e6f), 5.0f) << int(mode);
  }
  EXPECT_EQ(ScalarCurve({{2.0f, 7.0f}}, Interpolation::CatmullRom).evaluate(3.0f), 7.0f);  // a single key
}

// A monotone curve holds between two equal keys: every time inside the hold gives the key's value
// exactly, so a held camera, weight or joint does not move by rounding between shutter open and
// close (a mesh whose positions differ at all is motion-blurred).
TEST(AnimationCurve, MonotoneCubicHoldsEqualKeysExactly) {
  for (const float value : {0.8f, -0.104f, 0.307f, 1.0f / 3.0f}) {
    const ScalarCurve curve({{1.0f, 0.0f}, {38.0f, value}, {47.0f, value}, {49.7f, 2.0f * value}},
                            Interpolation::MonotoneCubic);
    for (int i = 0; i <= 900; ++i) {
      const float t = 38.0f + 9.0f * float(i) / 900.0f;
      ASSERT_EQ(curve.evaluate(t), value) << "t " << t;
    }
  }
}

TEST(AnimationCurve, StepHoldsTheLastKeyBeforeT) {
  const ScalarCurve curve(kKeys, Interpolation::Step);
  EXPECT_EQ(curve.evaluate(0.999f), 1.0f);
  EXPECT_EQ(curve.evaluate(2.5f), 3.0f);
  EXPECT_EQ(curve.evaluate(3.0f), 2.0f);
}

TEST(AnimationCurve, LinearIsTheChordBetweenKeys) {
  const ScalarCurve curve(kKeys, Interpolation::Linear);
  EXPECT_FLOAT_EQ(curve.evaluate(0.25f), 1.5f);
  EXPECT_FLOAT_EQ(curve.evaluate(2.0f), 2.5f);
  EXPECT_FLOAT_EQ(curve.evaluate(3.5f), 3.5f);
}

TEST(AnimationCurve, CatmullRomMatchesTheHermiteFormWithNeighbourSlopes) {
  const ScalarCurve curve(kKeys, Interpolation::CatmullRom);
  // Midpoint of [1, 3]: h = 2, m1 = (2 - 1) / 3, m3 = (5 - 3) / 3; Hermite at s = 1/2 is
  // (v1 + v3) / 2 + h (m1 - m3) / 8.
  const float m1 = 1.0f / 3.0f, m3 = 2.0f / 3.0f;
  EXPECT_FLOAT_EQ(curve.evaluate(2.0f), 2.5f + 2.0f * (m1 - m3) / 8.0f);
  // Reproduces a straight line exactly (linear precision), on uneven key spacing too.
  const ScalarCurve line({{0, 0}, {0.5f, 1}, {2, 4}, {2.5f, 5}}, Interpolation::CatmullRom);
  for (float t : {0.1f, 0.7f, 1.3f, 2.2f}) EXPECT_NEAR(line.evaluate(t), 2.0f * t, 1e-5f);
}

TEST(AnimationCurve, MonotoneCubicDoesNotOvershootWhereCatmullRomDoes) {
  // Monotone data with a sharp step: the eyelid closing in a blink.
  const std::vector<ScalarKey> blink = {{0, 0}, {1, 0}, {1.2f, 1}, {3, 1}, {4, 1}};
  const ScalarCurve monotone(blink, Interpolation::MonotoneCubic), catmullRom(blink, Interpolation::CatmullRom);
  float monotoneMin = 1e9f, monotoneMax = -1e9f, catmullMin = 1e9f, catmullMax = -1e9f, previous = -1.0f;
  for (int i = 0; i <= 4000; ++i) {
    const float t = 0.001f * float(i);
    const float m = monotone.evaluate(t), c = catmullRom.evaluate(t);
    EXPECT_GE(m, previous - 1e-6f) << t;  // non-decreasing like the data
    previous = m;
    monotoneMin = std::min(monotoneMin, m), monotoneMax = std::max(monotoneMax, m);
    catmullMin = std::min(catmullMin, c), catmullMax = std::max(catmullMax, c);
  }
  EXPECT_GE(monotoneMin, 0.0f);
  EXPECT_LE(monotoneMax, 1.0f);
  EXPECT_TRUE(catmullMin < -0.01f || catmullMax > 1.01f) << catmullMin << " " << catmullMax;
}

TEST(AnimationCurve, MonotoneCubicIsSmoothAndHitsMidpointsOfSymmetricData) {
  const ScalarCurve curve({{0, 0}, {1, 1}, {2, 2}}, Interpolation::MonotoneCubic);
  EXPECT_NEAR(curve.evaluate(0.5f), 0.5f, 1e-6f);  // collinear data: tangents equal the secant
  EXPECT_NEAR(curve.evaluate(1.5f), 1.5f, 1e-6f);
}

TEST(AnimationCurve, Vec3CurvesInterpolatePerComponent) {
  const Vec3Curve curve({{0.0f, Vec3(0, 1, 2)}, {2.0f, Vec3(2, 1, 0)}}, Interpolation::Linear);
  EXPECT_TRUE(curve.evaluate(0.5f).isApprox(Vec3(0.5f, 1.0f, 1.5f)));
  EXPECT_EQ(curve.evaluate(-1.0f), Vec3(0, 1, 2));
  EXPECT_EQ(curve.evaluate(9.0f), Vec3(2, 1, 0));
}

TEST(AnimationCurve, RejectsKeysNotStrictlyIncreasingAndNonFiniteInput) {
  EXPECT_THROW(ScalarCurve({}, Interpolation::Linear), InputError);
  EXPECT_THROW(ScalarCurve({{0, 0}, {0, 1}}, Interpolation::Linear), InputError);
  EXPECT_THROW(ScalarCurve({{1, 0}, {0, 1}}, Interpolation::Step), InputError);
  EXPECT_THROW(ScalarCurve({{0, NAN}}, Interpolation::Step), InputError);
  EXPECT_THROW(ScalarCurve(kKeys, Interpolation::Linear).evaluate(NAN), InputError);
  try {
    ScalarCurve({{0, 0}, {2, 1}, {1, 1}}, Interpolation::Linear);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "animation curve key 2 at time 1 is not after key 1 at time 2");
  }
}

}  // namespace animation_curve_test
}  // namespace lacrima
