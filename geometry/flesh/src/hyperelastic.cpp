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

namespace {

// F = U diag(s) V^T with U and V rotations (Irving, Teran & Fedkiw 2004, section 5): the sign
// goes to the smallest singular value (the last: JacobiSVD sorts them in decreasing order).
struct RotationSvd {
  Mat3d u, v;
  Vec3d s;
};

RotationSvd jacobiRotationSvd(const Mat3d& f) {
  const Eigen::JacobiSVD<Mat3d> svd(f, Eigen::ComputeFullU | Eigen::ComputeFullV);
  RotationSvd r{svd.matrixU(), svd.matrixV(), svd.singularValues()};
  if (r.u.determinant() < 0.0) r.u.col(2) *= -1.0, r.s[2] *= -1.0;
  if (r.v.determinant() < 0.0) r.v.col(2) *= -1.0, r.s[2] *= -1.0;
  return r;
}

// The same from the closed-form eigen-decomposition of F^T F (V and the squared singular values)
// and U's first two columns from F V, orthonormalized; several times faster than the Jacobi
// sweeps, which the solver pays once per tetrahedron and Newton iterate. Where the middle
// singular value is not well above zero (a tetrahedron squashed towards a line) the columns of
// F V carry too little of U, and the Jacobi decomposition answers instead.
RotationSvd rotationSvd(const Mat3d& f) {
  Eigen::SelfAdjointEigenSolver<Mat3d> eigen;
  eigen.computeDirect(f.transpose() * f);
  RotationSvd r;
  for (int k = 0; k < 3; ++k) {  // decreasing order, as JacobiSVD's
    r.v.col(k) = eigen.eigenvectors().col(2 - k);
    r.s[k] = std::sqrt(std::max(eigen.eigenvalues()[2 - k], 0.0));
  }
  if (!(r.s[1] > 1e-3 * r.s[0])) return jacobiRotationSvd(f);
  if (r.v.determinant() < 0.0) r.v.col(2) *= -1.0;
  const Vec3d u0 = (f * r.v.col(0)).normalized();
  Vec3d u1 = f * r.v.col(1);
  u1 = (u1 - u0.dot(u1) * u0).normalized();
  r.u.col(0) = u0;
  r.u.col(1) = u1;
  r.u.col(2) = u0.cross(u1);
  r.s[2] = r.u.col(2).dot(f * r.v.col(2));  // negative where F inverts the tetrahedron
  return r;
}

}  // namespace

Mat3d polarRotation(const Mat3d& f) {
  const RotationSvd r = rotationSvd(f);
  return r.u * r.v.transpose();
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
  const RotationSvd r = rotationSvd(f);
  // The skew component about V's axis k lies in the pair of the other two singular values.
  Vec3d removed;
  for (int k = 0; k < 3; ++k) {
    const double sum = r.s[(k + 1) % 3] + r.s[(k + 2) % 3];
    removed[k] = sum > 2.0 ? 2.0 / sum : 1.0;
  }
  return {f, cofactor(f), r.u * r.v.transpose(), r.v * removed.asDiagonal() * r.v.transpose()};
}

Mat3d firstPiolaStress(FleshMaterial material, const LameParameters& lame, const StressLinearization& at) {
  if (material == FleshMaterial::StVenantKirchhoff) return firstPiolaStress(material, lame, at.f);
  return 2.0 * lame.mu * (at.f - at.rotation) + lame.lambda * (at.f.determinant() - 1.0) * at.held;
}

Mat3d stressDifferential(FleshMaterial material, const LameParameters& lame, const StressLinearization& at,
                         const Mat3d& df) {
  if (material == FleshMaterial::StVenantKirchhoff) {
    const Mat3d dG = 0.5 * (df.transpose() * at.f + at.f.transpose() * df);
    const Mat3d dS = 2.0 * lame.mu * dG + lame.lambda * dG.trace() * Mat3d::Identity();
    return df * at.held + at.f * dS;
  }
  // 2 mu (dF - dR) + lambda (cof(F):dF) cof(F), dR = R [M a]x (see StressLinearization).
  const Mat3d& r = at.rotation;
  const Vec3d a = 0.5 * Vec3d(r.col(2).dot(df.col(1)) - r.col(1).dot(df.col(2)), r.col(0).dot(df.col(2)) - r.col(2).dot(df.col(0)),
                              r.col(1).dot(df.col(0)) - r.col(0).dot(df.col(1)));
  const Vec3d w = at.twist * a;
  Mat3d rotationPart;
  rotationPart.col(0) = w.z() * r.col(1) - w.y() * r.col(2);
  rotationPart.col(1) = w.x() * r.col(2) - w.z() * r.col(0);
  rotationPart.col(2) = w.y() * r.col(0) - w.x() * r.col(1);
  return 2.0 * lame.mu * (df - rotationPart) + lame.lambda * at.held.cwiseProduct(df).sum() * at.held;
}

namespace {

Mat3d crossProductMatrix(const Vec3d& g) {
  Mat3d m;
  m << 0.0, -g.z(), g.y(), g.z(), 0.0, -g.x(), -g.y(), g.x(), 0.0;
  return m;
}

}  // namespace

Mat3d stiffnessBlock(FleshMaterial material, const LameParameters& lame, const StressLinearization& at, const Vec3d& g) {
  if (material == FleshMaterial::StVenantKirchhoff) {
    const Vec3d u = at.f * g;
    return g.dot(at.held * g) * Mat3d::Identity() + (lame.mu + lame.lambda) * u * u.transpose() +
           lame.mu * g.squaredNorm() * at.f * at.f.transpose();
  }
  const Vec3d w = at.held * g;
  const Mat3d cross = crossProductMatrix(g);
  return 2.0 * lame.mu * g.squaredNorm() * Mat3d::Identity() +
         lame.mu * at.rotation * (cross * at.twist * cross) * at.rotation.transpose() + lame.lambda * w * w.transpose();
}

}  // namespace lacrima::flesh
