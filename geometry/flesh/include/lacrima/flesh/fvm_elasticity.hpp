#pragma once
// The elastic forces of a tetrahedral flesh mesh by the finite volume method (Teran, Blemker, Ng &
// Fedkiw 2003, section 4; the five steps of the anatomical face model's notes): per tetrahedron,
//   1. the Cauchy stress sigma (from F = Ds Dm^-1 and the material) pushes outward as -sigma,
//   2. each face's traction is -sigma n,
//   3. times the face's area, -sigma a n,
//   4. one third of it goes to each of the face's three nodes,
//   5. so a node gets f = -1/3 sigma (a1 n1 + a2 n2 + a3 n3) from its three faces of the
//      tetrahedron,
// with the faces' areas and normals in the deformed configuration. By Nanson's formula
// (a n = J F^-T A N) this equals -1/3 P (A1 N1 + A2 N2 + A3 N3) with the rest faces, which is
// -dE/dx of E = sum V0 psi(F) (tests/flesh: forces against finite differences of the energy).
//
// The rest shape (Dm) can change from step to step: the rig's pose of the flesh is its rest shape
// at that time, so the simulation only adds what inertia makes of the pose's motion.
#include <vector>

#include "lacrima/flesh/hyperelastic.hpp"
#include "lacrima/flesh/tet_mesh.hpp"

namespace lacrima::flesh {

class FvmElasticity {
 public:
  // mesh: the topology and the first rest shape (its tetrahedra positively oriented).
  FvmElasticity(const TetMesh& mesh, FleshMaterial material, LameParameters lame);

  // A new rest shape for every tetrahedron (node positions in the mesh's numbering). A
  // tetrahedron the new shape makes flat or inverted takes its first rest shape (the mesh's), so
  // the rest shape depends on `rest` alone, never on the calls before.
  void setRestShape(const std::vector<Vec3d>& rest);

  double energy(const std::vector<Vec3d>& x) const;
  // The nodal forces of the deformed shape x (the five steps above), added to f.
  void addForces(const std::vector<Vec3d>& x, std::vector<Vec3d>& f) const;

  // Holds the stress linearization at x for the products below.
  void linearizeAt(const std::vector<Vec3d>& x);

  // Both at once: the forces of x added to f, and x's linearization held (one singular value
  // decomposition per tetrahedron serves both).
  void linearizeAndAddForces(const std::vector<Vec3d>& x, std::vector<Vec3d>& f);
  // out += K dx, with K ~ -df/dx the positive semi-definite stiffness at the linearized shape.
  void addStiffnessProduct(const std::vector<Vec3d>& dx, std::vector<Vec3d>& out) const;
  // blocks += the 3x3 blocks on K's diagonal (per node, its three axes coupled): the conjugate
  // gradients' preconditioner.
  void addStiffnessBlockDiagonal(std::vector<Mat3d>& blocks) const;

  // rho V0 / 4 per node over its tetrahedra's first rest volumes (lumped mass).
  std::vector<double> lumpedMasses(double density) const;

  size_t nodeCount() const { return nodeCount_; }
  const std::vector<Tet>& tets() const { return tets_; }
  FleshMaterial material() const { return material_; }

 private:
  // Tetrahedron t's share of the forces of x given its first Piola stress and F (steps 1-4) into
  // corners[4t .. 4t+3].
  void tetCornerForces(size_t t, const std::vector<Vec3d>& x, const Mat3d& p, const Mat3d& deformation,
                       std::vector<Vec3d>& corners) const;

  // Per-tetrahedron corner vectors into per-node sums, in a fixed order (deterministic for any
  // thread count).
  void gatherCorners(const std::vector<Vec3d>& corners, std::vector<Vec3d>& out) const;

  size_t nodeCount_;
  std::vector<Tet> tets_;
  FleshMaterial material_;
  LameParameters lame_;
  std::vector<Mat3d> dmInverse_;
  std::vector<double> restVolume_, firstRestVolume_;
  std::vector<Mat3d> firstDmInverse_;  // the mesh's own rest shape: flat or inverted rest tetrahedra fall back to it
  std::vector<StressLinearization> linearization_;
  // Node n's corners (4 * tetrahedron + corner) are incidence_[offset_[n], offset_[n + 1]).
  std::vector<int> incidenceOffset_, incidence_;
  // The stiffness product's per-corner buffer, kept between the conjugate gradients' many calls.
  mutable std::vector<Vec3d> cornerScratch_;
};

}  // namespace lacrima::flesh
