// Sessile, sliding and hanging tear drops: fluid constants, the Young-Laplace drop
// against its two closed-form limits (spherical cap, gravity puddle) and its own first integral
// (vertical force balance), the spherical-cap bead model, the Furmidge sliding criterion and
// Tate's law with the Harkins-Brown correction.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/sessile_drop.hpp"

namespace lacrima {
namespace sessile_drop_test {

constexpr double kPiD = std::numbers::pi;
double deg(double degrees) { return degrees * kPiD / 180.0; }
double sphereVolume(double radius) { return 4.0 / 3.0 * kPiD * radius * radius * radius; }

const SessileSolveOptions kNoProfile{.keepProfile = false};

// ---- Fluid -------------------------------------------------------------------------------------

TEST(TearFluid, DefaultsGiveTheArchitectureDocCapillaryLengthAndBondNumbers) {
  const TearFluid tears;
  // sqrt(0.044 / (1000 * 9.81)) = 2.1178 mm (the doc's "about 2.1 mm").
  EXPECT_NEAR(tears.capillaryLength(), 2.1178e-3, 1e-7);
  EXPECT_NEAR(tears.bondNumber(tears.capillaryLength()), 1.0, 1e-12);
  // The doc: a 1.5-2 mm drop has Bond number 0.5-0.9.
  EXPECT_NEAR(tears.bondNumber(1.5e-3), 0.5017, 1e-3);
  EXPECT_NEAR(tears.bondNumber(2.0e-3), 0.8918, 1e-3);
  EXPECT_NEAR(equivalentSphereRadius(sphereVolume(1.5e-3)), 1.5e-3, 1e-15);
}

TEST(TearFluid, RejectsNonPhysicalConstants) {
  TearFluid fluid;
  fluid.surfaceTension = 0.0;
  EXPECT_THROW(validateTearFluid(fluid), InputError);
  fluid = {};
  fluid.density = -1.0;
  EXPECT_THROW(validateTearFluid(fluid), InputError);
  fluid = {};
  fluid.gravity = std::nan("");
  EXPECT_THROW(validateTearFluid(fluid), InputError);
  EXPECT_NO_THROW(validateTearFluid(TearFluid{}));
}

// ---- Spherical cap -----------------------------------------------------------------------------

TEST(SphericalCap, VolumeRoundTripAndHemisphere) {
  for (double angle : {20.0, 60.0, 90.0, 130.0, 170.0}) {
    const SphericalCap cap = sphericalCapFromVolume(7e-9, deg(angle));
    EXPECT_NEAR(sphericalCapVolume(cap.sphereRadius, deg(angle)), 7e-9, 1e-21) << angle;
    EXPECT_NEAR(cap.baseRadius, cap.sphereRadius * std::sin(deg(angle)), 1e-15);
  }
  const SphericalCap hemisphere = sphericalCapFromVolume(2.0 / 3.0 * kPiD, deg(90.0));
  EXPECT_NEAR(hemisphere.sphereRadius, 1.0, 1e-12);
  EXPECT_NEAR(hemisphere.baseRadius, 1.0, 1e-12);
  EXPECT_NEAR(hemisphere.height, 1.0, 1e-12);
}

// ---- Young-Laplace sessile drop ---------------------------------------------------------------------

TEST(SessileDrop, NinetyDegreesAtTinyBondIsAHemisphere) {
  const double b = 1.0;
  const SessileDrop drop = integrateSessileDrop(b, deg(90.0), 1e4 * b);  // Bo = (b / lc)^2 = 1e-8
  ASSERT_GT(drop.profile.size(), 100u);
  for (const SessileProfilePoint& p : drop.profile)
    ASSERT_NEAR(p.x * p.x + (p.z - b) * (p.z - b), b * b, 1e-6 * b) << "s = " << p.s;
  EXPECT_NEAR(drop.contactRadius, b, 1e-6 * b);
  EXPECT_NEAR(drop.height, b, 1e-6 * b);
  EXPECT_NEAR(drop.volume, 2.0 / 3.0 * kPiD * b * b * b, 1e-6);
  EXPECT_NEAR(drop.profile.back().phi, deg(90.0), 1e-12);
}

TEST(SessileDrop, WithoutGravityTheProfileIsTheExactCapEvenPastTheEquator) {
  for (double angle : {40.0, 120.0, 160.0}) {
    const SessileDrop drop = integrateSessileDrop(2.0, deg(angle), std::numeric_limits<double>::infinity());
    for (const SessileProfilePoint& p : drop.profile) ASSERT_NEAR(std::hypot(p.x, p.z - 2.0), 2.0, 1e-9) << angle;
    EXPECT_NEAR(drop.volume, sphericalCapVolume(2.0, deg(angle)), 1e-9) << angle;
    EXPECT_NEAR(drop.maxRadius, angle > 90.0 ? 2.0 : drop.contactRadius, 1e-9) << angle;
  }
}

TEST(SessileDrop, ProfilePastNinetyDegreesWidensThenNarrows) {
  const TearFluid tears;
  const SessileDrop drop = solveSessileDrop(20e-9, deg(130.0), tears.capillaryLength());
  EXPECT_GT(drop.maxRadius, drop.contactRadius * 1.05);
  size_t widest = 0;
  for (size_t i = 0; i < drop.profile.size(); ++i)
    if (drop.profile[i].x > drop.profile[widest].x) widest = i;
  EXPECT_NEAR(drop.profile[widest].x, drop.maxRadius, 1e-15);
  EXPECT_NEAR(drop.profile[widest].phi, deg(90.0), 1e-9);
  EXPECT_LT(widest + 10, drop.profile.size());  // the profile goes on, narrowing, after the equator
}

TEST(SessileDrop, SolvesForTheRequestedVolume) {
  const TearFluid tears;
  for (double angle : {30.0, 90.0, 150.0})
    for (double microlitres : {0.01, 1.0, 10.0, 100.0}) {
      const SessileDrop drop = solveSessileDrop(microlitres * kMicrolitre, deg(angle), tears.capillaryLength());
      EXPECT_NEAR(drop.volume / (microlitres * kMicrolitre), 1.0, 1e-10) << angle << " " << microlitres;
    }
}

// Independent of the integrator: cutting the drop at depth z, the weight of the part above is
// carried by the pressure across the cut minus the surface tension pulling down along the cut
// circle, pi x^2 (2 gamma / b + rho g z) - 2 pi x gamma sin(phi) = rho g V(z); divided by gamma:
// pi x^2 (2 / b + z / lc^2) - 2 pi x sin(phi) = V(z) / lc^2. Every profile point must satisfy it.
TEST(SessileDrop, ProfileSatisfiesTheVerticalForceBalance) {
  const TearFluid tears;
  const double lc = tears.capillaryLength();
  for (double angle : {60.0, 120.0}) {
    SessileSolveOptions options;
    const double volume = 30e-9;
    const SessileDrop drop = solveSessileDrop(volume, deg(angle), lc, options);
    // V(z) from the discs between the apex and each point, integrated by the trapezoid rule on
    // the stored profile (a different integral than the solver's RK4 volume).
    double discs = 0.0;
    double worst = 0.0;
    for (size_t i = 1; i < drop.profile.size(); ++i) {
      const SessileProfilePoint& a = drop.profile[i - 1];
      const SessileProfilePoint& p = drop.profile[i];
      discs += 0.5 * kPiD * (a.x * a.x + p.x * p.x) * (p.z - a.z);
      const double lhs = kPiD * p.x * p.x * (2.0 / drop.apexRadius + p.z / (lc * lc)) - 2.0 * kPiD * p.x * std::sin(p.phi);
      worst = std::max(worst, std::abs(lhs - discs / (lc * lc)) / (volume / (lc * lc)));
    }
    EXPECT_LT(worst, 1e-4) << angle;
    EXPECT_NEAR(discs / volume, 1.0, 1e-4) << angle;
  }
}

TEST(SessileDrop, ContactAngleReadFromTheProfileGeometry) {
  const TearFluid tears;
  for (double angle : {55.0, 65.0, 110.0}) {
    const SessileDrop drop = solveSessileDrop(10e-9, deg(angle), tears.capillaryLength());
    const SessileProfilePoint& last = drop.profile.back();
    // Two steps back: the last step may be arbitrarily short (it is cut to land on theta).
    const SessileProfilePoint& before = drop.profile[drop.profile.size() - 3];
    // The chord's slope is the tangent angle about a step before the contact line.
    const double chordAngle = std::atan2(last.z - before.z, last.x - before.x);
    EXPECT_NEAR(chordAngle, deg(angle), deg(0.5)) << angle;
    EXPECT_NEAR(last.z, drop.height, 1e-15);
    EXPECT_NEAR(last.x, drop.contactRadius, 1e-15);
  }
}

TEST(SessileDrop, SmallBondApproachesTheSphericalCap) {
  const TearFluid tears;
  const double lc = tears.capillaryLength();
  const double volume = sphereVolume(1e-2 * lc);  // Bo = 1e-4
  ASSERT_NEAR(tears.bondNumber(equivalentSphereRadius(volume)), 1e-4, 1e-12);
  for (double angle : {30.0, 60.0, 90.0, 120.0, 150.0}) {
    const SessileDrop drop = solveSessileDrop(volume, deg(angle), lc);
    const SphericalCap cap = sphericalCapFromVolume(volume, deg(angle));
    EXPECT_NEAR(drop.contactRadius / cap.baseRadius, 1.0, 1e-3) << angle;
    EXPECT_NEAR(drop.height / cap.height, 1.0, 1e-3) << angle;
    EXPECT_NEAR(drop.apexRadius / cap.sphereRadius, 1.0, 1e-3) << angle;
  }
}

TEST(SessileDrop, LargeDropApproachesThePuddleHeight) {
  const TearFluid tears;
  const double lc = tears.capillaryLength();
  for (double angle : {60.0, 90.0, 120.0}) {
    const double hInf = puddleHeight(lc, deg(angle));
    const SessileDrop puddle = solveSessileDrop(sphereVolume(20.0 * lc), deg(angle), lc, kNoProfile);
    EXPECT_NEAR(puddle.height / hInf, 1.0, 0.01) << angle;
    EXPECT_GT(puddle.contactRadius, 70.0 * lc);
    // The finite-size excess shrinks as the puddle grows.
    const SessileDrop smaller = solveSessileDrop(sphereVolume(5.0 * lc), deg(angle), lc, kNoProfile);
    EXPECT_GT(smaller.height / hInf - 1.0, 2.0 * (puddle.height / hInf - 1.0)) << angle;
  }
}

TEST(SessileDrop, GravityFlattensBiggerDropsMore) {
  const TearFluid tears;
  for (double angle : {60.0, 90.0}) {
    const SphericalCap cap = sphericalCapFromVolume(1e-9, deg(angle));
    double previous = cap.height / (2.0 * cap.baseRadius);
    for (double microlitres : {0.1, 1.0, 5.0, 10.0, 33.5, 100.0}) {
      const double ratio = solveSessileDrop(microlitres * kMicrolitre, deg(angle), tears.capillaryLength(), kNoProfile).aspectRatio();
      EXPECT_LT(ratio, previous) << angle << " " << microlitres;
      previous = ratio;
    }
  }
}

TEST(SessileDrop, StepRefinementChangesNothingVisible) {
  const TearFluid tears;
  SessileSolveOptions coarse = kNoProfile, fine = kNoProfile;
  coarse.stepsPerLength = 50;
  fine.stepsPerLength = 1600;
  const SessileDrop a = solveSessileDrop(10e-9, deg(75.0), tears.capillaryLength(), coarse);
  const SessileDrop b = solveSessileDrop(10e-9, deg(75.0), tears.capillaryLength(), fine);
  EXPECT_NEAR(a.height / b.height, 1.0, 1e-8);
  EXPECT_NEAR(a.contactRadius / b.contactRadius, 1.0, 1e-8);
}

// Regression numbers of this solver for the tear drops (lc = 2.118 mm), reported in the
// branch notes: 10 uL (Bo 0.40) and a 2 mm equivalent-radius drop (33.5 uL, Bo 0.89).
TEST(SessileDrop, TearDropAspectRatios) {
  const TearFluid tears;
  const double lc = tears.capillaryLength();
  const double twoMillimetre = sphereVolume(2e-3);
  EXPECT_NEAR(solveSessileDrop(10e-9, deg(60.0), lc, kNoProfile).aspectRatio(), 0.2600, 5e-4);
  EXPECT_NEAR(solveSessileDrop(10e-9, deg(90.0), lc, kNoProfile).aspectRatio(), 0.4391, 5e-4);
  EXPECT_NEAR(solveSessileDrop(twoMillimetre, deg(60.0), lc, kNoProfile).aspectRatio(), 0.2316, 5e-4);
  EXPECT_NEAR(solveSessileDrop(twoMillimetre, deg(90.0), lc, kNoProfile).aspectRatio(), 0.3853, 5e-4);
}

TEST(SessileDrop, RejectsBadInput) {
  EXPECT_THROW(solveSessileDrop(0.0, deg(60.0), 2e-3), InputError);
  EXPECT_THROW(solveSessileDrop(-1e-9, deg(60.0), 2e-3), InputError);
  EXPECT_THROW(solveSessileDrop(1e-9, 0.0, 2e-3), InputError);
  EXPECT_THROW(solveSessileDrop(1e-9, kPiD, 2e-3), InputError);
  EXPECT_THROW(solveSessileDrop(1e-9, std::nan(""), 2e-3), InputError);
  EXPECT_THROW(solveSessileDrop(1e-9, deg(60.0), 0.0), InputError);
  EXPECT_THROW(integrateSessileDrop(0.0, deg(60.0), 2e-3), InputError);
  try {
    solveSessileDrop(1e-9, deg(190.0), 2e-3);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "contact angle must be strictly between 0 and 180 degrees, got 190 degrees");
  }
}

// ---- Bead on a tilted surface -------------------------------------------------------------------

// A cap scaled by (halfLength / a0, halfWidth / a0, height / h0) keeps the volume iff the product is 1.
double volumeScale(const BeadShape& bead) {
  return bead.halfLength / bead.cap.baseRadius * bead.halfWidth / bead.cap.baseRadius * bead.height / bead.cap.height;
}

TEST(BeadShape, FloorFlattensWallElongatesVolumeKept) {
  const TearFluid tears;
  const BeadShape floor = beadShape(tears, 10e-9, deg(60.0), 0.0);
  const SessileDrop drop = solveSessileDrop(10e-9, deg(60.0), tears.capillaryLength(), kNoProfile);
  EXPECT_NEAR(floor.height, drop.height, 1e-12);
  EXPECT_LT(floor.flattening, 0.95);
  EXPECT_DOUBLE_EQ(floor.elongation, 1.0);
  EXPECT_DOUBLE_EQ(floor.halfLength, floor.halfWidth);

  const BeadShape wall = beadShape(tears, 10e-9, deg(60.0), deg(90.0));
  EXPECT_DOUBLE_EQ(wall.flattening, 1.0);
  EXPECT_GT(wall.elongation, 1.02);
  EXPECT_GT(wall.halfLength, wall.halfWidth);
  for (const BeadShape& bead : {floor, wall, beadShape(tears, 10e-9, deg(60.0), deg(40.0))})
    EXPECT_NEAR(volumeScale(bead), 1.0, 1e-12);
}

TEST(BeadShape, SteeperAndBiggerBeadsStretchMore) {
  const TearFluid tears;
  double previousElongation = 1.0, previousFlattening = 0.0;
  for (double tilt : {0.0, 20.0, 45.0, 70.0, 90.0}) {
    const BeadShape bead = beadShape(tears, 10e-9, deg(100.0), deg(tilt));
    EXPECT_GE(bead.elongation, previousElongation) << tilt;
    EXPECT_GT(bead.flattening, previousFlattening) << tilt;
    previousElongation = bead.elongation;
    previousFlattening = bead.flattening;
  }
  EXPECT_GT(beadShape(tears, 30e-9, deg(100.0), deg(90.0)).elongation, beadShape(tears, 3e-9, deg(100.0), deg(90.0)).elongation);
  EXPECT_THROW(beadShape(tears, 10e-9, deg(60.0), deg(95.0)), InputError);
}

// ---- Stick and slide -------------------------------------------------------------------------------

SlidingModel tearModel(double advancing, double receding) {
  SlidingModel model;
  model.hysteresis = {deg(advancing), deg(receding)};
  return model;
}

double weightAlongSlope(const SlidingModel& model, double volume, double tilt) {
  return model.fluid.density * volume * model.fluid.gravity * std::sin(tilt);
}

TEST(Sliding, CriticalVolumeAndTiltBalanceTheRetentionForce) {
  const SlidingModel model = tearModel(95.0, 65.0);
  for (double tilt : {10.0, 45.0, 90.0, 135.0}) {
    const double volume = criticalSlidingVolume(model, deg(tilt));
    EXPECT_NEAR(weightAlongSlope(model, volume, deg(tilt)) / retentionForce(model, volume), 1.0, 1e-12) << tilt;
    EXPECT_FALSE(dropSlides(model, volume * 0.999, deg(tilt)));
    EXPECT_TRUE(dropSlides(model, volume * 1.001, deg(tilt)));
  }
  const double volume = 20e-9;
  const std::optional<double> tilt = criticalTiltAngle(model, volume);
  ASSERT_TRUE(tilt.has_value());
  EXPECT_NEAR(weightAlongSlope(model, volume, *tilt) / retentionForce(model, volume), 1.0, 1e-12);
  EXPECT_FALSE(dropSlides(model, volume, *tilt - 1e-3));
  EXPECT_TRUE(dropSlides(model, volume, *tilt + 1e-3));
}

TEST(Sliding, FurmidgeForceByHand) {
  SlidingModel model = tearModel(90.0, 60.0);
  model.retentionFactor = kFurmidgeRetentionFactor;
  const double volume = 10e-9;
  // Base width: the 10 uL cap at the mean angle, 75 degrees.
  const double w = 2.0 * sphericalCapFromVolume(volume, deg(75.0)).baseRadius;
  EXPECT_NEAR(slidingBaseWidth(model, volume), w, 1e-15);
  EXPECT_NEAR(retentionForce(model, volume), 0.044 * w * (0.5 - 0.0), 1e-15);
  model.retentionFactor = kElSherbiniJacobiRetentionFactor;
  EXPECT_NEAR(kElSherbiniJacobiRetentionFactor, 0.7740, 1e-4);
  EXPECT_NEAR(retentionForce(model, volume), 0.7740 * 0.044 * w * 0.5, 1e-4 * 0.044 * w);
}

TEST(Sliding, BiggerDropsAndSteeperTiltsSlideSooner) {
  const SlidingModel model = tearModel(95.0, 65.0);
  double previousTilt = kPiD;
  for (double microlitres : {8.0, 10.0, 20.0, 50.0, 200.0}) {
    const std::optional<double> tilt = criticalTiltAngle(model, microlitres * kMicrolitre);
    ASSERT_TRUE(tilt.has_value()) << microlitres;
    EXPECT_LT(*tilt, previousTilt) << microlitres;
    previousTilt = *tilt;
  }
  double previousVolume = std::numeric_limits<double>::infinity();
  for (double tilt : {5.0, 15.0, 30.0, 60.0, 89.0}) {
    const double volume = criticalSlidingVolume(model, deg(tilt));
    EXPECT_LT(volume, previousVolume) << tilt;
    previousVolume = volume;
  }
  // The vertical wall holds the least: overhangs (tilt > 90) behave like their mirror tilt.
  const double wall = criticalSlidingVolume(model, deg(90.0));
  for (double tilt : {30.0, 80.0, 100.0, 150.0}) EXPECT_GT(criticalSlidingVolume(model, deg(tilt)), wall) << tilt;
  // A small drop is held even by a wall.
  EXPECT_FALSE(criticalTiltAngle(model, 0.5 * wall).has_value());
  EXPECT_FALSE(dropSlides(model, 0.5 * wall, deg(90.0)));
}

TEST(Sliding, WithoutHysteresisAnyTiltSlides) {
  const SlidingModel model = tearModel(70.0, 70.0);
  EXPECT_EQ(retentionForce(model, 5e-9), 0.0);
  EXPECT_TRUE(dropSlides(model, 1e-12, deg(0.01)));
  EXPECT_FALSE(dropSlides(model, 5e-9, 0.0));  // flat: nothing drives it
  EXPECT_EQ(*criticalTiltAngle(model, 1e-12), 0.0);
  EXPECT_EQ(criticalSlidingVolume(model, deg(1.0)), 0.0);
  EXPECT_EQ(criticalBondSinTilt(model), 0.0);
}

TEST(Sliding, CriticalBondNumberFormAgreesWithTheVolumeForm) {
  for (const SlidingModel& model : {tearModel(95.0, 65.0), tearModel(110.0, 55.0), tearModel(60.0, 58.0)}) {
    const double boSin = criticalBondSinTilt(model);
    for (double tilt : {15.0, 50.0, 90.0}) {
      const double radius = equivalentSphereRadius(criticalSlidingVolume(model, deg(tilt)));
      EXPECT_NEAR(model.fluid.bondNumber(radius) * std::sin(deg(tilt)) / boSin, 1.0, 1e-12);
    }
  }
  // Furmidge's k = 1 holds (1 / k)^(3/2) times more volume than ElSherbini-Jacobi's k.
  SlidingModel furmidge = tearModel(95.0, 65.0);
  furmidge.retentionFactor = kFurmidgeRetentionFactor;
  EXPECT_NEAR(criticalSlidingVolume(furmidge, deg(90.0)) / criticalSlidingVolume(tearModel(95.0, 65.0), deg(90.0)),
              std::pow(1.0 / kElSherbiniJacobiRetentionFactor, 1.5), 1e-12);
}

// The skin numbers, 95/65 degrees with k = 24 / pi^3: Bo_c sin(alpha) = 0.2582. A 5 uL tear
// (Bo 0.2509) is held even on a vertical wall; a 10 uL tear (Bo 0.3983) slides from
// asin(0.2582 / 0.3983) = 40.4 degrees.
TEST(Sliding, SkinTearNumbers) {
  const SlidingModel model = tearModel(95.0, 65.0);
  EXPECT_NEAR(criticalBondSinTilt(model), 0.2582, 1e-4);
  EXPECT_FALSE(criticalTiltAngle(model, 5e-9).has_value());
  EXPECT_NEAR(criticalSlidingVolume(model, deg(90.0)) / kMicrolitre, 5.22, 0.01);
  const std::optional<double> tilt = criticalTiltAngle(model, 10e-9);
  ASSERT_TRUE(tilt.has_value());
  EXPECT_NEAR(*tilt, deg(40.41), deg(0.02));
}

// Plausibility, not a published-number match: the brief quotes 10-40 uL for water drops sliding
// off vertical surfaces at moderate hysteresis (not verified against a paper here). Water
// (72 mN/m, lc 2.7 mm) with 90/60 degrees lands in that range for both k; tears, with the lower
// surface tension, slide at about half that volume.
TEST(Sliding, VerticalWallCriticalVolumesArePlausible) {
  SlidingModel tears = tearModel(90.0, 60.0);
  const double tearVolume = criticalSlidingVolume(tears, deg(90.0)) / kMicrolitre;
  EXPECT_NEAR(tearVolume, 5.39, 0.01);
  SlidingModel water = tears;
  water.fluid.surfaceTension = 0.072;
  water.fluid.density = 998.0;
  for (double k : {kElSherbiniJacobiRetentionFactor, kFurmidgeRetentionFactor}) {
    water.retentionFactor = k;
    const double microlitres = criticalSlidingVolume(water, deg(90.0)) / kMicrolitre;
    EXPECT_GT(microlitres, 10.0) << k;
    EXPECT_LT(microlitres, 40.0) << k;
  }
}

TEST(Sliding, RejectsBadHysteresisAndTilt) {
  EXPECT_THROW(retentionForce(tearModel(60.0, 80.0), 5e-9), InputError);
  EXPECT_THROW(retentionForce(tearModel(180.0, 80.0), 5e-9), InputError);
  EXPECT_THROW(criticalSlidingVolume(tearModel(90.0, 60.0), 0.0), InputError);
  EXPECT_THROW(dropSlides(tearModel(90.0, 60.0), 5e-9, deg(-1.0)), InputError);
  SlidingModel model = tearModel(90.0, 60.0);
  model.retentionFactor = 0.0;
  EXPECT_THROW(criticalBondSinTilt(model), InputError);
}

// ---- Hanging drop ---------------------------------------------------------------------------------

TEST(HangingDrop, TateVolumeForOneMillimetre) {
  const TearFluid tears;
  // 2 pi 1e-3 m 0.044 N/m / (1000 kg/m^3 9.81 m/s^2) = 2.8181e-8 m^3.
  EXPECT_NEAR(hangingDropMaxVolume(tears, 1e-3) / kMicrolitre, 28.181, 1e-3);
  EXPECT_NEAR(hangingDropMaxVolume(tears, 3e-3) / hangingDropMaxVolume(tears, 1e-3), 3.0, 1e-12);
  EXPECT_THROW(hangingDropMaxVolume(tears, 0.0), InputError);
}

TEST(HangingDrop, HarkinsBrownCorrection) {
  EXPECT_DOUBLE_EQ(harkinsBrownFactor(0.3), 0.7256);
  EXPECT_NEAR(harkinsBrownFactor(0.8), 0.6000, 1e-12);
  EXPECT_NEAR(harkinsBrownFactor(0.85), 0.5999, 1e-12);
  EXPECT_NEAR(harkinsBrownFactor(1.2), 0.6535, 1e-12);
  EXPECT_THROW(harkinsBrownFactor(0.2), InputError);
  EXPECT_THROW(harkinsBrownFactor(1.3), InputError);

  const TearFluid tears;
  for (double radius : {0.8e-3, 1e-3, 2e-3, 3e-3}) {
    const double tate = hangingDropMaxVolume(tears, radius);
    const double detached = hangingDropMaxVolume(tears, radius, DetachmentCorrection::HarkinsBrown);
    EXPECT_LT(detached, 0.73 * tate) << radius;
    EXPECT_GT(detached, 0.59 * tate) << radius;
    // The returned volume is self-consistent with the table: V = psi(r / V^(1/3)) V_Tate.
    EXPECT_NEAR(detached / (harkinsBrownFactor(radius / std::cbrt(detached)) * tate), 1.0, 1e-12) << radius;
  }
  EXPECT_NEAR(hangingDropMaxVolume(tears, 1e-3, DetachmentCorrection::HarkinsBrown) / kMicrolitre, 19.59, 0.01);
  EXPECT_THROW(hangingDropMaxVolume(tears, 0.1e-3, DetachmentCorrection::HarkinsBrown), InputError);
  EXPECT_THROW(hangingDropMaxVolume(tears, 10e-3, DetachmentCorrection::HarkinsBrown), InputError);
}

}  // namespace sessile_drop_test
}  // namespace lacrima
