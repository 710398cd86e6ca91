// Strain measures and materials of the flesh: known affine maps, stress as the energy's
// derivative, and the stiffness as the stress's derivative.
#include "lacrima/flesh/hyperelastic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

namespace lacrima::flesh {
namespace hyperelastic_test {

const LameParameters kLame = LameParameters::fromYoung(5000.0, 0.45);
constexpr FleshMaterial kMaterials[] = {FleshMaterial::StVenantKirchhoff, FleshMaterial::FixedCorotated};

Mat3d someRotation() { return Eigen::AngleAxisd(0.7, Vec3d(1, 2, -0.5).normalized()).toRotationMatrix(); }

TEST(Hyperelastic, RotationHasNoGreenStrainNoEnergyAndNoStress) {
  const Mat3d r = someRotation();
  EXPECT_LT(greenStrain(r).norm(), 1e-14);
  for (FleshMaterial m : kMaterials) {
    EXPECT_NEAR(energyDensity(m, kLame, r), 0.0, 1e-9);
    EXPECT_LT(firstPiolaStress(m, kLame, r).norm(), 1e-9);
  }
}

TEST(Hyperelastic, GreenStrainOfAStretchIsHalfTheSquaredStretchLessOne) {
  const Mat3d f = Vec3d(1.2, 0.9, 1.0).asDiagonal();
  const Mat3d g = greenStrain(someRotation() * f);  // rotated afterwards: the same strain
  EXPECT_NEAR(g(0, 0), 0.5 * (1.44 - 1.0), 1e-14);
  EXPECT_NEAR(g(1, 1), 0.5 * (0.81 - 1.0), 1e-14);
  EXPECT_NEAR(g(2, 2), 0.0, 1e-14);
  EXPECT_NEAR(g(0, 1), 0.0, 1e-14);
}

TEST(Hyperelastic, DeformationGradientOfAnAffineMapIsItsMatrix) {
  Mat3d a;
  a << 1.1, 0.2, 0.0, -0.1, 0.95, 0.3, 0.05, 0.0, 1.2;
  Mat3d dm;
  dm << 1, 0.2, 0.1, 0, 1, 0.3, 0.1, 0, 0.8;
  EXPECT_LT((deformationGradient(a * dm, dm.inverse()) - a).norm(), 1e-13);
}

TEST(Hyperelastic, LameParametersFromYoungsModulus) {
  const LameParameters lame = LameParameters::fromYoung(1000.0, 0.25);
  EXPECT_NEAR(lame.mu, 400.0, 1e-9);
  EXPECT_NEAR(lame.lambda, 400.0, 1e-9);
}

Mat3d energyGradientByDifferences(FleshMaterial m, const Mat3d& f) {
  Mat3d g;
  const double eps = 1e-6;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Mat3d up = f, down = f;
      up(i, j) += eps;
      down(i, j) -= eps;
      g(i, j) = (energyDensity(m, kLame, up) - energyDensity(m, kLame, down)) / (2 * eps);
    }
  return g;
}

TEST(Hyperelastic, FirstPiolaStressIsTheEnergysDerivative) {
  Mat3d f;
  f << 1.1, 0.2, 0.0, -0.1, 0.85, 0.3, 0.05, 0.0, 1.2;
  for (FleshMaterial m : kMaterials) {
    const Mat3d p = firstPiolaStress(m, kLame, f);
    EXPECT_LT((p - energyGradientByDifferences(m, f)).norm(), 1e-5 * p.norm()) << int(m);
  }
}

TEST(Hyperelastic, CorotatedStressStaysRestoringThroughInversion) {
  // A tetrahedron squashed along z to thickness s, through flat (s = 0) to inverted (s < 0): the
  // corotated energy keeps rising as s falls, so its stress P_zz = dpsi/ds pushes back everywhere.
  const FleshMaterial m = FleshMaterial::FixedCorotated;
  const auto squash = [](double s) { return Mat3d(Vec3d(1.0, 1.0, s).asDiagonal()); };
  for (double s : {0.9, 0.5, 0.2, 0.0, -0.2, -0.5}) {
    EXPECT_LT(firstPiolaStress(m, kLame, squash(s))(2, 2), 0.0) << s;
    EXPECT_GT(energyDensity(m, kLame, squash(s - 0.05)), energyDensity(m, kLame, squash(s))) << s;
  }
  EXPECT_LT((firstPiolaStress(m, kLame, squash(-0.2)) - energyGradientByDifferences(m, squash(-0.2))).norm(), 1e-3);
}

TEST(Hyperelastic, StVenantKirchhoffSoftensUnderStrongCompression) {
  // Why the corotated material is the default: squashed along z, StVK's resisting stress peaks at
  // s = 1/sqrt(3) (~58 % of the thickness) and falls to zero when flat; inverted is as good as upright.
  const FleshMaterial m = FleshMaterial::StVenantKirchhoff;
  const auto squash = [](double s) { return Mat3d(Vec3d(1.0, 1.0, s).asDiagonal()); };
  const auto resisting = [&](double s) { return -firstPiolaStress(m, kLame, squash(s))(2, 2); };
  EXPECT_GT(resisting(1.0 / std::sqrt(3.0)), resisting(0.8));
  EXPECT_GT(resisting(1.0 / std::sqrt(3.0)), resisting(0.3));
  EXPECT_NEAR(resisting(0.0), 0.0, 1e-9);
  EXPECT_NEAR(energyDensity(m, kLame, squash(-0.5)), energyDensity(m, kLame, squash(0.5)), 1e-9);
}

TEST(Hyperelastic, CauchyStressIsPFTransposeOverJ) {
  const Mat3d f = Vec3d(1.1, 0.9, 1.05).asDiagonal();
  const Mat3d p = firstPiolaStress(FleshMaterial::FixedCorotated, kLame, f);
  const Mat3d sigma = cauchyStress(p, f);
  EXPECT_LT((sigma - sigma.transpose()).norm(), 1e-9);  // symmetric, as a Cauchy stress must be
  EXPECT_LT((sigma * f.determinant() - p * f.transpose()).norm(), 1e-9);
}

TEST(Hyperelastic, PolarRotationIsTheRotationThatLeavesASymmetricStretch) {
  // F = R S with R a rotation and S symmetric, for stretched, sheared, nearly flat and inverted F.
  std::vector<Mat3d> cases{Mat3d::Identity(), someRotation(), Vec3d(1.0, 1.0, 1.0 + 1e-12).asDiagonal()};
  srand(7);
  for (int i = 0; i < 200; ++i) cases.push_back(Mat3d::Identity() + 0.05 * Mat3d::Random());
  for (int i = 0; i < 200; ++i) cases.push_back(Mat3d::Random());
  cases.push_back(someRotation() * Vec3d(1.0, 0.5, -0.3).asDiagonal());   // inverted
  cases.push_back(someRotation() * Vec3d(1.0, 1e-5, 1e-6).asDiagonal());  // squashed to a line
  for (const Mat3d& f : cases) {
    const Mat3d r = polarRotation(f);
    EXPECT_LT((r.transpose() * r - Mat3d::Identity()).norm(), 1e-10);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-10);
    const Mat3d s = r.transpose() * f;
    EXPECT_LT((s - s.transpose()).norm(), 1e-9 * std::max(1.0, f.norm())) << f;
  }
}

TEST(Hyperelastic, StressDifferentialMatchesDifferencesInTension) {
  // Exact for StVK while S >= 0 (tension).
  Mat3d f;
  f << 1.15, 0.05, 0.0, 0.02, 1.1, 0.03, 0.0, 0.01, 1.2;
  Mat3d df;
  df << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.0, -0.3;
  const double eps = 1e-6;
  const FleshMaterial stvk = FleshMaterial::StVenantKirchhoff;
  const Mat3d byDifferences =
      (firstPiolaStress(stvk, kLame, f + eps * df) - firstPiolaStress(stvk, kLame, f - eps * df)) / (2 * eps);
  const Mat3d analytic = stressDifferential(stvk, kLame, linearizeStress(stvk, kLame, f), df);
  EXPECT_LT((analytic - byDifferences).norm(), 1e-5 * byDifferences.norm());
}

Mat3d corotatedByDifferences(const Mat3d& f, const Mat3d& df) {
  const double eps = 1e-6;
  const FleshMaterial co = FleshMaterial::FixedCorotated;
  return (firstPiolaStress(co, kLame, f + eps * df) - firstPiolaStress(co, kLame, f - eps * df)) / (2 * eps);
}

Mat3d corotatedDifferential(const Mat3d& f, const Mat3d& df) {
  const FleshMaterial co = FleshMaterial::FixedCorotated;
  return stressDifferential(co, kLame, linearizeStress(co, kLame, f), df);
}

TEST(Hyperelastic, CorotatedDifferentialIsExactAtRestAndUnderRotation) {
  Mat3d df;
  df << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.0, -0.3;
  for (const Mat3d& f : {Mat3d(Mat3d::Identity()), someRotation()}) {
    const Mat3d expected = corotatedByDifferences(f, df);
    EXPECT_LT((corotatedDifferential(f, df) - expected).norm(), 1e-6 * expected.norm());
  }
  // A rotation's own direction costs nothing: dF = W F with W skew.
  Mat3d w;
  w << 0, -0.2, 0.1, 0.2, 0, -0.3, -0.1, 0.3, 0;
  EXPECT_LT(corotatedDifferential(someRotation(), w * someRotation()).norm(), 1e-9);
}

TEST(Hyperelastic, CorotatedDifferentialInTensionLacksOnlyTheCofactorsTerm) {
  // Stretched on every axis (each pair of singular values sums past 2, so no clamping): the
  // differential is exact but for lambda (J - 1) dcof(F), which it leaves out.
  const Mat3d f = someRotation() * Vec3d(1.2, 1.15, 1.1).asDiagonal();
  Mat3d df;
  df << 0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.0, -0.3;
  Mat3d dcof;
  dcof.col(0) = df.col(1).cross(f.col(2)) + f.col(1).cross(df.col(2));
  dcof.col(1) = df.col(2).cross(f.col(0)) + f.col(2).cross(df.col(0));
  dcof.col(2) = df.col(0).cross(f.col(1)) + f.col(0).cross(df.col(1));
  const Mat3d expected = corotatedByDifferences(f, df) - kLame.lambda * (f.determinant() - 1.0) * dcof;
  EXPECT_LT((corotatedDifferential(f, df) - expected).norm(), 1e-6 * expected.norm());
}

TEST(Hyperelastic, StressDifferentialIsPositiveSemiDefinite) {
  // Under compression StVK's true Hessian is indefinite; the solver's approximation is not.
  const Mat3d compressed = Vec3d(0.6, 1.0, 0.8).asDiagonal() * someRotation();
  for (FleshMaterial m : kMaterials) {
    const StressLinearization at = linearizeStress(m, kLame, compressed);
    for (int trial = 0; trial < 50; ++trial) {
      const Mat3d df = Mat3d::Random();
      EXPECT_GE(stressDifferential(m, kLame, at, df).cwiseProduct(df).sum(), -1e-9) << int(m);
    }
  }
}

// The preconditioner's block by its definition: column a is dP(e_a g^T) g.
Mat3d stiffnessBlockByDefinition(FleshMaterial m, const StressLinearization& at, const Vec3d& g) {
  Mat3d block;
  for (int axis = 0; axis < 3; ++axis)
    block.col(axis) = stressDifferential(m, kLame, at, Vec3d::Unit(axis) * g.transpose()) * g;
  return block;
}

TEST(Hyperelastic, StiffnessBlockEqualsTheStressDifferentialsItStandsFor) {
  std::vector<Mat3d> shapes = {Mat3d::Identity(), someRotation(), Vec3d(0.6, 1.0, 0.8).asDiagonal() * someRotation(),
                               Vec3d(1.4, 0.9, 1.1).asDiagonal() * someRotation(),
                               Vec3d(-0.5, 1.0, 1.0).asDiagonal() * someRotation()};  // inverted
  for (int i = 0; i < 40; ++i) shapes.push_back(Mat3d::Identity() + 0.4 * Mat3d::Random());
  for (FleshMaterial m : kMaterials)
    for (const Mat3d& f : shapes) {
      const StressLinearization at = linearizeStress(m, kLame, f);
      for (int trial = 0; trial < 8; ++trial) {
        const Vec3d g = 30.0 * Vec3d::Random();  // a gradient row of Dm^-1 (1/m)
        const Mat3d expected = stiffnessBlockByDefinition(m, at, g);
        const Mat3d block = stiffnessBlock(m, kLame, at, g);
        EXPECT_LE((block - expected).norm(), 1e-12 * expected.norm()) << int(m) << "\n" << block << "\n" << expected;
      }
    }
}

}  // namespace hyperelastic_test
}  // namespace lacrima::flesh
