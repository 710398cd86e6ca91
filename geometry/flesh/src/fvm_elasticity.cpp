#include "lacrima/flesh/fvm_elasticity.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace lacrima::flesh {

namespace {

// The faces of a positively oriented tetrahedron, each ordered so that (b - a) x (c - a) points out
// of it (for any deformation: the orientation is kept by the ordering, so an inverted
// tetrahedron's faces turn with it, as Nanson's formula needs).
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

template <typename Body>
void forEachTet(size_t count, Body body) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t t = r.begin(); t != r.end(); ++t) body(t);
  });
}

}  // namespace

FvmElasticity::FvmElasticity(const TetMesh& mesh, FleshMaterial material, LameParameters lame)
    : nodeCount_(mesh.nodes.size()),
      tets_(mesh.tets),
      material_(material),
      lame_(lame),
      dmInverse_(mesh.tets.size(), Mat3d::Identity()),
      restVolume_(mesh.tets.size(), 0.0),
      linearization_(mesh.tets.size()) {
  setRestShape(mesh.nodes);
  firstDmInverse_ = dmInverse_;
  firstRestVolume_ = restVolume_;
  incidenceOffset_.assign(nodeCount_ + 1, 0);
  for (const Tet& t : tets_)
    for (int n : t) ++incidenceOffset_[size_t(n) + 1];
  for (size_t n = 0; n < nodeCount_; ++n) incidenceOffset_[n + 1] += incidenceOffset_[n];
  incidence_.resize(tets_.size() * 4);
  std::vector<int> fill(incidenceOffset_.begin(), incidenceOffset_.end() - 1);
  for (size_t t = 0; t < tets_.size(); ++t)
    for (int c = 0; c < 4; ++c) incidence_[size_t(fill[size_t(tets_[t][c])]++)] = int(4 * t + c);
}

void FvmElasticity::setRestShape(const std::vector<Vec3d>& rest) {
  forEachTet(tets_.size(), [&](size_t t) {
    const Mat3d dm = edgeMatrix(rest, tets_[t]);
    const double volume = dm.determinant() / 6.0;
    // A flat or inverted rest tetrahedron has no inverse to measure strain by: it takes its first
    // rest shape. (Not the last one it had: that would be history a simulation's filed state
    // does not hold, and a frame continued from a filed state would differ from the same frame
    // simulated in one run.) Before the first rest shape is known, it keeps the identity.
    if (!(volume > 1e-18)) {
      if (!firstDmInverse_.empty()) {
        dmInverse_[t] = firstDmInverse_[t];
        restVolume_[t] = firstRestVolume_[t];
      }
      return;
    }
    dmInverse_[t] = dm.inverse();
    restVolume_[t] = volume;
  });
}

double FvmElasticity::energy(const std::vector<Vec3d>& x) const {
  double sum = 0.0;
  for (size_t t = 0; t < tets_.size(); ++t)
    sum += restVolume_[t] * energyDensity(material_, lame_, edgeMatrix(x, tets_[t]) * dmInverse_[t]);
  return sum;
}

void FvmElasticity::tetCornerForces(size_t t, const std::vector<Vec3d>& x, const Mat3d& p, const Mat3d& deformation,
                                    std::vector<Vec3d>& corners) const {
  const Tet& tet = tets_[t];
  const double j = deformation.determinant();
  for (int c = 0; c < 4; ++c) corners[4 * t + size_t(c)].setZero();
  if (std::abs(j) < 1e-12) {
    // Flat: no Cauchy stress (J = 0); the same forces by Nanson's formula, -P Dm^-T V0 per corner.
    const Mat3d h = -restVolume_[t] * p * dmInverse_[t].transpose();
    for (int c = 1; c < 4; ++c) corners[4 * t + size_t(c)] = h.col(c - 1);
    corners[4 * t] = -(h.col(0) + h.col(1) + h.col(2));
    return;
  }
  const Mat3d sigma = cauchyStress(p, deformation);  // step 1
  for (const auto& face : kFaces) {
    const Vec3d& a = x[size_t(tet[face[0]])];
    const Vec3d areaNormal = 0.5 * (x[size_t(tet[face[1]])] - a).cross(x[size_t(tet[face[2]])] - a);
    const Vec3d force = -sigma * areaNormal;                         // steps 2-3: -sigma a n
    for (int corner : face) corners[4 * t + size_t(corner)] += force / 3.0;  // step 4
  }
}

void FvmElasticity::addForces(const std::vector<Vec3d>& x, std::vector<Vec3d>& f) const {
  std::vector<Vec3d> corners(tets_.size() * 4);
  forEachTet(tets_.size(), [&](size_t t) {
    const Mat3d deformation = edgeMatrix(x, tets_[t]) * dmInverse_[t];
    tetCornerForces(t, x, firstPiolaStress(material_, lame_, deformation), deformation, corners);
  });
  gatherCorners(corners, f);  // step 5: each node's three faces of each of its tetrahedra
}

void FvmElasticity::linearizeAt(const std::vector<Vec3d>& x) {
  forEachTet(tets_.size(), [&](size_t t) {
    linearization_[t] = linearizeStress(material_, lame_, edgeMatrix(x, tets_[t]) * dmInverse_[t]);
  });
}

void FvmElasticity::linearizeAndAddForces(const std::vector<Vec3d>& x, std::vector<Vec3d>& f) {
  std::vector<Vec3d>& corners = cornerScratch_;
  corners.resize(tets_.size() * 4);
  forEachTet(tets_.size(), [&](size_t t) {
    const Mat3d deformation = edgeMatrix(x, tets_[t]) * dmInverse_[t];
    linearization_[t] = linearizeStress(material_, lame_, deformation);
    tetCornerForces(t, x, firstPiolaStress(material_, lame_, linearization_[t]), deformation, corners);
  });
  gatherCorners(corners, f);
}

void FvmElasticity::addStiffnessProduct(const std::vector<Vec3d>& dx, std::vector<Vec3d>& out) const {
  std::vector<Vec3d>& corners = cornerScratch_;  // every entry written below
  corners.resize(tets_.size() * 4);
  forEachTet(tets_.size(), [&](size_t t) {
    const Mat3d dF = edgeMatrix(dx, tets_[t]) * dmInverse_[t];
    const Mat3d dP = stressDifferential(material_, lame_, linearization_[t], dF);
    // df = -V0 dP Dm^-T (columns: corners 1-3); K dx = -df.
    const Mat3d h = restVolume_[t] * dP * dmInverse_[t].transpose();
    for (int c = 1; c < 4; ++c) corners[4 * t + size_t(c)] = h.col(c - 1);
    corners[4 * t] = -(h.col(0) + h.col(1) + h.col(2));
  });
  gatherCorners(corners, out);
}

void FvmElasticity::addStiffnessBlockDiagonal(std::vector<Mat3d>& blocks) const {
  std::vector<Mat3d> corners(tets_.size() * 4);
  forEachTet(tets_.size(), [&](size_t t) {
    const Mat3d& dmInv = dmInverse_[t];
    // d(F)/d(x_corner) along an axis: corner c > 0 moves column c-1 of Ds, corner 0 all three back.
    Eigen::Matrix<double, 4, 3> gradients;
    gradients.row(0) = -(dmInv.row(0) + dmInv.row(1) + dmInv.row(2));
    for (int c = 1; c < 4; ++c) gradients.row(c) = dmInv.row(c - 1);
    for (int c = 0; c < 4; ++c)
      corners[4 * t + size_t(c)] =
          restVolume_[t] * stiffnessBlock(material_, lame_, linearization_[t], gradients.row(c).transpose());
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nodeCount_, 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t n = r.begin(); n != r.end(); ++n)
      for (int i = incidenceOffset_[n]; i < incidenceOffset_[n + 1]; ++i) blocks[n] += corners[size_t(incidence_[size_t(i)])];
  });
}

std::vector<double> FvmElasticity::lumpedMasses(double density) const {
  std::vector<double> mass(nodeCount_, 0.0);
  for (size_t t = 0; t < tets_.size(); ++t)
    for (int n : tets_[t]) mass[size_t(n)] += density * firstRestVolume_[t] / 4.0;
  return mass;
}

void FvmElasticity::gatherCorners(const std::vector<Vec3d>& corners, std::vector<Vec3d>& out) const {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nodeCount_, 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t n = r.begin(); n != r.end(); ++n) {
      Vec3d sum = Vec3d::Zero();
      for (int i = incidenceOffset_[n]; i < incidenceOffset_[n + 1]; ++i) sum += corners[size_t(incidence_[size_t(i)])];
      out[n] += sum;
    }
  });
}

}  // namespace lacrima::flesh
