#include "lacrima/flesh/flesh_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lacrima::flesh {

namespace {

double dot(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) sum += a[i].dot(b[i]);
  return sum;
}

double largestNorm(const std::vector<Vec3d>& values) {
  double largest = 0.0;
  for (const Vec3d& value : values) largest = std::max(largest, value.squaredNorm());
  return std::sqrt(largest);
}

void zero(std::vector<Vec3d>& values) {
  for (Vec3d& value : values) value.setZero();
}

}  // namespace

FleshSimulation::FleshSimulation(const TetMesh& mesh, FleshMaterial material, LameParameters lame,
                                 FleshDynamicsParams params, std::vector<bool> kinematic)
    : elasticity_(mesh, material, lame),
      params_(params),
      kinematic_(std::move(kinematic)),
      mass_(elasticity_.lumpedMasses(params.density)),
      x_(mesh.nodes),
      v_(mesh.nodes.size(), Vec3d::Zero()) {
  if (kinematic_.size() != x_.size()) throw std::invalid_argument("FleshSimulation: one kinematic flag per node");
}

void FleshSimulation::setState(std::vector<Vec3d> positions, std::vector<Vec3d> velocities) {
  if (positions.size() != x_.size() || velocities.size() != x_.size())
    throw std::invalid_argument("FleshSimulation::setState: one position and velocity per node");
  x_ = std::move(positions);
  v_ = std::move(velocities);
}

std::vector<Vec3d> FleshSimulation::velocityAt(double h, const std::vector<Vec3d>& x) const {
  const double th = theta();
  std::vector<Vec3d> v(x.size());
  for (size_t i = 0; i < x.size(); ++i) v[i] = (x[i] - x0_[i] - h * (1.0 - th) * v0_[i]) / (th * h);
  return v;
}

std::vector<Vec3d> FleshSimulation::residual(double h, const std::vector<Vec3d>& x,
                                             const std::vector<Vec3d>& targetVelocity) {
  const double th = theta();
  const std::vector<Vec3d> v = velocityAt(h, x);
  std::vector<Vec3d> xm(x.size());
  for (size_t i = 0; i < x.size(); ++i) xm[i] = (1.0 - th) * x0_[i] + th * x[i];
  std::vector<Vec3d> r(x.size(), Vec3d::Zero());
  elasticity_.linearizeAndAddForces(xm, r);  // the Newton step's stiffness is taken at xm too
  for (Vec3d& value : r) value = -value;
  if (params_.stiffnessDamping > 0.0) {
    std::vector<Vec3d> kv(x.size(), Vec3d::Zero());
    elasticity_.addStiffnessProduct(v, kv);
    for (size_t i = 0; i < x.size(); ++i) r[i] += params_.stiffnessDamping * kv[i];
  }
  for (size_t i = 0; i < x.size(); ++i) {
    r[i] += mass_[i] * ((v[i] - v0_[i]) / h + params_.massDamping * (v[i] - targetVelocity[i]));
    if (kinematic_[i]) r[i].setZero();
  }
  return r;
}

void FleshSimulation::applyJacobian(double h, const std::vector<Vec3d>& in, std::vector<Vec3d>& out) const {
  const double th = theta();
  const double massScale = (1.0 + params_.massDamping * h) / (th * h * h);
  zero(out);
  elasticity_.addStiffnessProduct(in, out);
  const double stiffnessScale = th + params_.stiffnessDamping / h;
  for (size_t i = 0; i < in.size(); ++i)
    out[i] = kinematic_[i] ? Vec3d::Zero() : Vec3d(stiffnessScale * out[i] + massScale * mass_[i] * in[i]);
}

int FleshSimulation::solveNewtonStep(double h, const std::vector<Vec3d>& r, std::vector<Vec3d>& dx) const {
  const size_t n = r.size();
  const double th = theta();
  // Block-Jacobi: each node's 3x3 block of J, inverted (the near-incompressible flesh couples a
  // node's axes; per-axis Jacobi took about an eighth more iterations on the default shot).
  std::vector<Mat3d> blocks(n, Mat3d::Zero());
  elasticity_.addStiffnessBlockDiagonal(blocks);
  const double massScale = (1.0 + params_.massDamping * h) / (th * h * h);
  const double stiffnessScale = th + params_.stiffnessDamping / h;
  for (size_t i = 0; i < n; ++i) blocks[i] = (stiffnessScale * blocks[i] + massScale * mass_[i] * Mat3d::Identity()).inverse();
  // Preconditioned conjugate gradients from dx = 0 on -r (zero on kinematic nodes).
  dx.assign(n, Vec3d::Zero());
  std::vector<Vec3d> residual(n), z(n), p(n), jp(n);
  for (size_t i = 0; i < n; ++i) residual[i] = -r[i];
  for (size_t i = 0; i < n; ++i) z[i] = blocks[i] * residual[i];
  p = z;
  double rz = dot(residual, z);
  const double stop = params_.cgTolerance * params_.cgTolerance * dot(residual, residual);
  int iteration = 0;
  const auto closeEnough = [&] { return params_.positionTolerance > 0.0 && largestNorm(z) <= params_.positionTolerance; };
  for (; iteration < params_.cgIterations && dot(residual, residual) > stop && rz > 0.0 && !closeEnough(); ++iteration) {
    applyJacobian(h, p, jp);
    const double curvature = dot(p, jp);
    if (!(curvature > 0.0)) break;
    const double alpha = rz / curvature;
    for (size_t i = 0; i < n; ++i) {
      dx[i] += alpha * p[i];
      residual[i] -= alpha * jp[i];
      z[i] = blocks[i] * residual[i];
    }
    const double rzNext = dot(residual, z);
    const double beta = rzNext / rz;
    rz = rzNext;
    for (size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
  }
  return iteration;
}

FleshStepReport FleshSimulation::step(double h, const std::vector<Vec3d>& target,
                                      const std::vector<Vec3d>& targetVelocity) {
  if (!(h > 0.0)) throw std::invalid_argument("FleshSimulation::step: the time step must be positive");
  if (target.size() != x_.size() || targetVelocity.size() != x_.size())
    throw std::invalid_argument("FleshSimulation::step: one target position and velocity per node");
  x0_ = x_;
  v0_ = v_;
  // The kinematic nodes' velocities over the step are those that land them on the target.
  for (size_t i = 0; i < x_.size(); ++i)
    if (kinematic_[i]) v0_[i] = (target[i] - x0_[i]) / h;
  elasticity_.setRestShape(target);
  std::vector<Vec3d> x(x_.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = kinematic_[i] ? target[i] : Vec3d(x0_[i] + h * v0_[i]);
  FleshStepReport report;
  double firstResidual = 0.0;
  std::vector<Vec3d> dx;
  for (int k = 0; k < params_.newtonIterations; ++k) {
    const std::vector<Vec3d> r = residual(h, x, targetVelocity);
    report.residual = std::sqrt(dot(r, r));
    if (k == 0) firstResidual = report.residual;
    if (report.residual == 0.0 || (k > 0 && report.residual <= params_.newtonTolerance * firstResidual)) break;
    report.cgIterations += solveNewtonStep(h, r, dx);
    for (size_t i = 0; i < x.size(); ++i) x[i] += dx[i];
    report.newtonIterations = k + 1;
    if (params_.positionTolerance > 0.0 && largestNorm(dx) <= params_.positionTolerance) break;
  }
  v_ = velocityAt(h, x);
  x_ = std::move(x);
  // Kinematic nodes move with the rig's velocity (the residual ignores theirs).
  for (size_t i = 0; i < x_.size(); ++i)
    if (kinematic_[i]) v_[i] = targetVelocity[i];
  return report;
}

double FleshSimulation::kineticEnergy() const {
  double sum = 0.0;
  for (size_t i = 0; i < x_.size(); ++i) sum += 0.5 * mass_[i] * v_[i].squaredNorm();
  return sum;
}

Vec3d FleshSimulation::momentum() const {
  Vec3d sum = Vec3d::Zero();
  for (size_t i = 0; i < x_.size(); ++i) sum += mass_[i] * v_[i];
  return sum;
}

}  // namespace lacrima::flesh
