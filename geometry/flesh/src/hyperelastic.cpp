#include "lacrima/flesh/hyperelastic.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

namespace lacrima::flesh {

LameParameters LameParameters::fromYoung(double youngsModulus, double poissonRatio) {
  const double e = youngsModulus, nu = poissonRatio;
  return {e / (2.0 * (1.0 + nu)), e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))};
}

Mat3d cofactor(const Mat3d& f) {
  Mat3d c;
  c.col(0) = f.col(1).cross(f.col(2));
  c.col(1) = f.col(2).cross(f.col(0));
  c.col(2) = f.col(0).cross(f.col(1));
  return c;
}

Mat3d polarRotation(const Mat3d& f) {
  const Eigen::JacobiSVD<Mat3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3d u = svd.matrixU(), v = svd.matrixV();
  // Irving, Teran & Fedkiw 2004, section 5: make U and V rotations; the sign goes to the smallest
  // singular value (the last column: JacobiSVD sorts them in decreasing order).
  if (u.determinant() < 0.0) u.col(2) *= -1.0;
  if (v.determinant() < 0.0) v.col(2) *= -1.0;
  return u * v.transpose();
}

namespace {

Mat3d secondPiolaStVK(const LameParameters& lame, const Mat3d& f) {
  const Mat3d g = greenStrain(f);
  return 2.0 * lame.mu * g + lame.lambda * g.trace() * Mat3d::Identity();
}

Mat3d positivePart(const Mat3d& symmetric) {
  const Eigen::SelfAdjointEigenSolver<Mat3d> eigen(symmetric);
  const Eigen::Vector3d clamped = eigen.eigenvalues().cwiseMax(0.0);
  return eigen.eigenvectors() * clamped.asDiagonal() * eigen.eigenvectors().transpose();
}

}  // namespace

double energyDensity(FleshMaterial material, const LameParameters& lame, const Mat3d& f) {
  if (material == FleshMaterial::StVenantKirchhoff) {
    const Mat3d g = greenStrain(f);
    return lame.mu * g.squaredNorm() + 0.5 * lame.lambda * g.trace() * g.trace();
  }
  const double j = f.determinant();
  return lame.mu * (f - polarRotation(f)).squaredNorm() + 0.5 * lame.lambda * (j - 1.0) * (j - 1.0);
}

Mat3d firstPiolaStress(FleshMaterial material, const LameParameters& lame, const Mat3d& f) {
  if (material == FleshMaterial::StVenantKirchhoff) return f * secondPiolaStVK(lame, f);
  return 2.0 * lame.mu * (f - polarRotation(f)) + lame.lambda * (f.determinant() - 1.0) * cofactor(f);
}

Mat3d cauchyStress(const Mat3d& p, const Mat3d& f) { return p * f.transpose() / f.determinant(); }

StressLinearization linearizeStress(FleshMaterial material, const LameParameters& lame, const Mat3d& f) {
  if (material == FleshMaterial::StVenantKirchhoff) return {f, positivePart(secondPiolaStVK(lame, f))};
  return {f, cofactor(f)};
}

Mat3d stressDifferential(FleshMaterial material, const LameParameters& lame, const StressLinearization& at,
                         const Mat3d& df) {
  if (material == FleshMaterial::StVenantKirchhoff) {
    const Mat3d dG = 0.5 * (df.transpose() * at.f + at.f.transpose() * df);
    const Mat3d dS = 2.0 * lame.mu * dG + lame.lambda * dG.trace() * Mat3d::Identity();
    return df * at.held + at.f * dS;
  }
  return 2.0 * lame.mu * df + lame.lambda * at.held.cwiseProduct(df).sum() * at.held;
}

}  // namespace lacrima::flesh
