#pragma once
// Hyperelastic flesh: the strain measures of the deformation gradient and two materials.
//
// F = Ds Dm^-1 maps a tetrahedron's rest edges to its current ones; the Green strain
// G = 1/2 (F^T F - I) is zero for any rotation (Teran, Blemker, Ng & Fedkiw 2003, eq. 1; the
// anatomical face model of Sifakis, Neverov & Fedkiw 2005 measures its flesh this way).
//
// - St. Venant-Kirchhoff: psi = mu G:G + lambda/2 tr(G)^2, P = F S, S = 2 mu G + lambda tr(G) I.
//   The material of the Green strain, exact for large rotations and small strains, but it
//   softens under strong compression (its energy falls again past ~58 % compression) and can
//   invert a tetrahedron and keep it inverted.
// - Fixed corotated (Stomakhin, Howes, Schroeder & Teran 2012, eq. 2):
//   psi = mu |F - R|^2 + lambda/2 (J - 1)^2, P = 2 mu (F - R) + lambda (J - 1) cof(F), with R the
//   rotation of F's polar decomposition taken through the SVD with the inversion fix of Irving,
//   Teran & Fedkiw 2004 (a reflection moved onto the smallest singular value). Its energy grows
//   for any compression and through inversion, so a pinched cheek comes back: the default.
#include <Eigen/Dense>

#include "lacrima/flesh/tet_mesh.hpp"

namespace lacrima::flesh {

enum class FleshMaterial { StVenantKirchhoff, FixedCorotated };

struct LameParameters {
  double mu = 0.0, lambda = 0.0;
  // From Young's modulus (Pa) and Poisson's ratio (in (-1, 0.5)).
  static LameParameters fromYoung(double youngsModulus, double poissonRatio);
};

inline Mat3d deformationGradient(const Mat3d& ds, const Mat3d& dmInverse) { return ds * dmInverse; }
inline Mat3d greenStrain(const Mat3d& f) { return 0.5 * (f.transpose() * f - Mat3d::Identity()); }

// cof(F) = det(F) F^-T, written without the inverse so that it holds for a flat F too.
Mat3d cofactor(const Mat3d& f);

// The rotation of F's polar decomposition, a proper rotation even for det(F) <= 0.
Mat3d polarRotation(const Mat3d& f);

double energyDensity(FleshMaterial material, const LameParameters& lame, const Mat3d& f);

// The first Piola-Kirchhoff stress dpsi/dF.
Mat3d firstPiolaStress(FleshMaterial material, const LameParameters& lame, const Mat3d& f);

// The Cauchy stress sigma = P F^T / det(F).
Mat3d cauchyStress(const Mat3d& p, const Mat3d& f);

// A positive semi-definite approximation of the stress differential dP = (d^2 psi / dF^2) : dF,
// which the implicit solver's conjugate gradients need:
// - St. Venant-Kirchhoff: dP = dF S+ + F dS with S+ the second Piola stress with its negative
//   eigenvalues clamped to zero (exact while S is positive semi-definite, i.e. in tension);
// - fixed corotated: dP = 2 mu (dF - dR) + lambda (cof(F):dF) cof(F). The rotation's differential
//   in F's singular frame (F = U Sigma V^T, dF^ = U^T dF V) turns each pair's skew part
//   b = (dF^_ij - dF^_ji) / 2 by 2 b / (s_i + s_j) (the polar decomposition's differential, as in
//   Twigg & Kacic-Alesic 2010), so 2 mu (dF - dR) keeps (1 - 2 / (s_i + s_j)) of it, clamped at
//   zero where compression makes that negative (in the manner of Teran, Sifakis, Irving & Fedkiw
//   2005's definiteness fix). The cofactor's own
//   differential, lambda (J - 1) dcof, is left out: indefinite, and small wherever the flesh keeps
//   its volume (J near 1). Exact at rest and under pure rotation.
// What the differential needs of F, computed once per Newton iterate and tetrahedron (the
// conjugate gradients then apply it many times): F, and S+ (St. Venant-Kirchhoff) or cof(F), the
// rotation R and the twist map M (fixed corotated). In world terms the rotation's differential is
// dR = R [M a]x with a the axial vector of skew(R^T dF) and M = V diag(removed fractions) V^T.
struct StressLinearization {
  Mat3d f, held;
  Mat3d rotation = Mat3d::Identity(), twist = Mat3d::Zero();
};
StressLinearization linearizeStress(FleshMaterial material, const LameParameters& lame, const Mat3d& f);
// The first Piola stress at the linearization's F, from what it holds (no second decomposition).
Mat3d firstPiolaStress(FleshMaterial material, const LameParameters& lame, const StressLinearization& at);
Mat3d stressDifferential(FleshMaterial material, const LameParameters& lame, const StressLinearization& at,
                         const Mat3d& df);

// The 3x3 block B with B e_a = stressDifferential(e_a g^T) g for each axis a: how dP g answers a
// node's move along each axis when F moves by e_a g^T (g the node's gradient row of F; the
// implicit solver's block-Jacobi preconditioner sums V0 B over a node's tetrahedra). In closed
// form, from the differentials above with dF = e_a g^T, u = F g, w = cof(F) g and [g]x the
// cross-product matrix of g:
// - St. Venant-Kirchhoff: (g . S+ g) I + (mu + lambda) u u^T + mu |g|^2 F F^T;
// - fixed corotated: 2 mu |g|^2 I + mu R [g]x M [g]x R^T + lambda w w^T (the rotation's part:
//   a = (g x R^T e_a) / 2, so dR g = -R [g]x M [g]x R^T e_a / 2).
// Equal to the twelve stressDifferential products to rounding, computed as one (the flesh step is
// ~12 % faster for it: docs/performance.md).
Mat3d stiffnessBlock(FleshMaterial material, const LameParameters& lame, const StressLinearization& at, const Vec3d& g);

}  // namespace lacrima::flesh
