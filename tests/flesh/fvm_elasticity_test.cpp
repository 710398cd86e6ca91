// The finite-volume forces of a tetrahedral mesh: the energy's negative gradient, zero net force
// and zero interior residual under an affine map (the patch test), the stiffness as the forces'
// derivative, and a compressed block's load against the analytic one.
#include "lacrima/flesh/fvm_elasticity.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

namespace lacrima::flesh {
namespace fvm_elasticity_test {

const LameParameters kLame = LameParameters::fromYoung(5000.0, 0.4);
constexpr FleshMaterial kMaterials[] = {FleshMaterial::StVenantKirchhoff, FleshMaterial::FixedCorotated};

std::vector<Vec3d> jiggled(const std::vector<Vec3d>& nodes, double amplitude, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  std::vector<Vec3d> out = nodes;
  for (Vec3d& p : out) p += Vec3d(u(random), u(random), u(random));
  return out;
}

std::vector<Vec3d> forces(const FvmElasticity& e, const std::vector<Vec3d>& x) {
  std::vector<Vec3d> f(x.size(), Vec3d::Zero());
  e.addForces(x, f);
  return f;
}

TEST(FvmElasticity, ForcesAreTheNegativeEnergyGradient) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.02), 2, 2, 2);
  for (FleshMaterial m : kMaterials) {
    const FvmElasticity e(mesh, m, kLame);
    std::vector<Vec3d> x = jiggled(mesh.nodes, 0.002, 7);
    const std::vector<Vec3d> f = forces(e, x);
    double worst = 0.0, scale = 0.0;
    const double eps = 1e-8;
    for (size_t n = 0; n < x.size(); ++n)
      for (int axis = 0; axis < 3; ++axis) {
        const double keep = x[n][axis];
        x[n][axis] = keep + eps;
        const double up = e.energy(x);
        x[n][axis] = keep - eps;
        const double down = e.energy(x);
        x[n][axis] = keep;
        worst = std::max(worst, std::abs(f[n][axis] + (up - down) / (2 * eps)));
        scale = std::max(scale, std::abs(f[n][axis]));
      }
    EXPECT_GT(scale, 1e-3);
    EXPECT_LT(worst, 1e-5 * scale) << int(m);
  }
}

TEST(FvmElasticity, PatchTestAffineMapLeavesNoInteriorForceAndNoNetForce) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.03, 0.02, 0.02), 3, 3, 3);
  Mat3d a;
  a << 1.1, 0.1, 0.0, -0.05, 0.9, 0.1, 0.02, 0.0, 1.05;
  std::vector<Vec3d> x;
  for (const Vec3d& p : mesh.nodes) x.push_back(a * p + Vec3d(0.3, -0.1, 0.2));
  for (FleshMaterial m : kMaterials) {
    const FvmElasticity e(mesh, m, kLame);
    const std::vector<Vec3d> f = forces(e, x);
    Vec3d net = Vec3d::Zero();
    double largest = 0.0, interior = 0.0;
    for (size_t n = 0; n < x.size(); ++n) {
      net += f[n];
      largest = std::max(largest, f[n].norm());
      const Vec3d& p = mesh.nodes[n];
      const bool inside = p.x() > 1e-9 && p.x() < 0.03 - 1e-9 && p.y() > 1e-9 && p.y() < 0.02 - 1e-9 &&
                          p.z() > 1e-9 && p.z() < 0.02 - 1e-9;
      if (inside) interior = std::max(interior, f[n].norm());
    }
    EXPECT_GT(largest, 0.01);
    EXPECT_LT(interior, 1e-9 * largest) << int(m);
    EXPECT_LT(net.norm(), 1e-9 * largest) << int(m);
  }
}

TEST(FvmElasticity, RigidMotionHasNoForce) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.02), 2, 2, 2);
  const Mat3d r = Eigen::AngleAxisd(1.2, Vec3d(0.3, 1, 0.2).normalized()).toRotationMatrix();
  std::vector<Vec3d> x;
  for (const Vec3d& p : mesh.nodes) x.push_back(r * p + Vec3d(1, 2, 3));
  for (FleshMaterial m : kMaterials) {
    const FvmElasticity e(mesh, m, kLame);
    for (const Vec3d& f : forces(e, x)) EXPECT_LT(f.norm(), 1e-9);
    EXPECT_NEAR(e.energy(x), 0.0, 1e-12);
  }
}

TEST(FvmElasticity, StiffnessIsTheForcesDerivativeInTension) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.02), 2, 2, 2);
  FvmElasticity e(mesh, FleshMaterial::StVenantKirchhoff, kLame);
  std::vector<Vec3d> x;
  for (const Vec3d& p : mesh.nodes) x.push_back(Vec3d(1.2 * p.x(), 1.15 * p.y(), 1.1 * p.z()));  // stretched
  x = jiggled(x, 0.0002, 3);
  e.linearizeAt(x);
  const std::vector<Vec3d> dx = jiggled(std::vector<Vec3d>(x.size(), Vec3d::Zero()), 1.0, 11);
  std::vector<Vec3d> kdx(x.size(), Vec3d::Zero());
  e.addStiffnessProduct(dx, kdx);
  const double eps = 1e-7;
  std::vector<Vec3d> up = x, down = x;
  for (size_t n = 0; n < x.size(); ++n) {
    up[n] += eps * dx[n];
    down[n] -= eps * dx[n];
  }
  const std::vector<Vec3d> fUp = forces(e, up), fDown = forces(e, down);
  double worst = 0.0, scale = 0.0;
  for (size_t n = 0; n < x.size(); ++n) {
    worst = std::max(worst, (kdx[n] + (fUp[n] - fDown[n]) / (2 * eps)).norm());
    scale = std::max(scale, kdx[n].norm());
  }
  EXPECT_LT(worst, 1e-5 * scale);
  // The block diagonal is the product's own: node n's block holds what moving n does to n.
  std::vector<Mat3d> blocks(x.size(), Mat3d::Zero());
  e.addStiffnessBlockDiagonal(blocks);
  for (size_t n : {size_t(0), size_t(13), x.size() - 1})
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Vec3d> unit(x.size(), Vec3d::Zero()), column(x.size(), Vec3d::Zero());
      unit[n][axis] = 1.0;
      e.addStiffnessProduct(unit, column);
      EXPECT_LT((blocks[n].col(axis) - column[n]).norm(), 1e-9 * column[n].norm()) << n << " " << axis;
    }
}

TEST(FvmElasticity, CompressedBlockCarriesYoungsModulusTimesStrain) {
  // Uniaxial stress: squeezed by 0.2 % along z, free to bulge by nu times that sideways, a block's top
  // carries E * strain * area (linear elasticity; the finite-strain materials agree to O(strain)).
  const double young = 5000.0, nu = 0.4, strain = -0.002;
  const Vec3d size(0.02, 0.03, 0.04);
  const TetMesh mesh = makeBoxTetMesh(size, 2, 3, 4);
  std::vector<Vec3d> x;
  for (const Vec3d& p : mesh.nodes)
    x.push_back(Vec3d((1 - nu * strain) * p.x(), (1 - nu * strain) * p.y(), (1 + strain) * p.z()));
  const double expected = young * strain * size.x() * size.y();
  for (FleshMaterial m : kMaterials) {
    const FvmElasticity e(mesh, m, LameParameters::fromYoung(young, nu));
    const std::vector<Vec3d> f = forces(e, x);
    Vec3d top = Vec3d::Zero();
    for (size_t n = 0; n < x.size(); ++n)
      if (mesh.nodes[n].z() > size.z() - 1e-9) top += f[n];
    // The force the block exerts on its top nodes pulls them back up: -(load) = -E strain A.
    EXPECT_NEAR(top.z(), -expected, 0.01 * std::abs(expected)) << int(m);
    EXPECT_NEAR(top.x(), 0.0, 1e-9);
  }
}

TEST(FvmElasticity, AFlatOrInvertedRestShapeFallsBackToTheFirstWhateverCameBefore) {
  // The rest shape may depend only on the shape given: a simulation continued from a filed state
  // (positions and velocities) must step as the one that ran all along. Before, a flattened
  // tetrahedron kept the rest shape of the call before, and two histories differed here.
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.01, 0.01, 0.01), 1, 1, 1);
  for (FleshMaterial m : kMaterials) {
    FvmElasticity fresh(mesh, m, kLame), stretchedFirst(mesh, m, kLame);
    std::vector<Vec3d> stretched = mesh.nodes;
    for (Vec3d& p : stretched) p.x() *= 1.3;
    stretchedFirst.setRestShape(stretched);
    std::vector<Vec3d> flat = mesh.nodes;
    for (Vec3d& p : flat) p.z() = 0.0;
    fresh.setRestShape(flat);
    stretchedFirst.setRestShape(flat);
    EXPECT_NEAR(fresh.energy(mesh.nodes), 0.0, 1e-15) << int(m);  // the mesh's own shape is the rest
    const std::vector<Vec3d> x = jiggled(mesh.nodes, 0.001, 3);
    EXPECT_EQ(forces(fresh, x), forces(stretchedFirst, x)) << int(m);
    EXPECT_GT(stretchedFirst.energy(x), 0.0) << int(m);
  }
}

TEST(FvmElasticity, MassesAddUpToTheBlocksMass) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.03, 0.04), 2, 3, 4);
  const FvmElasticity e(mesh, FleshMaterial::FixedCorotated, kLame);
  double sum = 0.0;
  for (double m : e.lumpedMasses(1100.0)) sum += m;
  EXPECT_NEAR(sum, 1100.0 * 0.02 * 0.03 * 0.04, 1e-12);
  EXPECT_NEAR(totalVolume(mesh), 0.02 * 0.03 * 0.04, 1e-15);
  EXPECT_EQ(findTetMeshDefect(mesh), "");
}

}  // namespace fvm_elasticity_test
}  // namespace lacrima::flesh
