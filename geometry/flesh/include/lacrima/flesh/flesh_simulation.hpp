#pragma once
// Time integration of the flesh: implicit, so that stiff flesh steps at film frame rates with a few
// substeps.
//
// Each step solves for the positions at its end, x, by Newton's method on the residual of
//   M (v1 - v0) / h = f(xm) - alpha M (v1 - vt) - beta K v1,
//   x = x0 + h ((1 - theta) v0 + theta v1),  xm = (1 - theta) x0 + theta x,
// theta = 1: backward Euler (Baraff & Witkin 1998, eq. 4; damps the fastest modes, the default),
// theta = 1/2: the implicit midpoint rule (symplectic: conserves energy without damping, which
// the tests check). Damping is Rayleigh's, alpha M + beta K, with the mass part acting on the
// velocity relative to the rig's (vt): flesh carried along by a turning head is not slowed by it.
// Each Newton step solves J dx = -r with J = M (1 + alpha h) / (theta h^2) +
// (theta + beta / h) K, by conjugate gradients preconditioned with J's 3x3 block diagonal; K is
// the positive semi-definite stiffness of FvmElasticity.
//
// Kinematic nodes (the skull's side of the flesh, and the flesh outside the simulated region)
// are placed on the target each step: the rig moves them, the simulation never does.
#include <vector>

#include "lacrima/flesh/fvm_elasticity.hpp"

namespace lacrima::flesh {

enum class FleshIntegrator { BackwardEuler, ImplicitMidpoint };

// Changes whenever a change to the solver or the materials alters the states a simulation reaches:
// states filed on disk (flesh_state_cache.hpp) are keyed by it, so a new binary does not continue
// from an old one's states.
constexpr int kFleshSolverRevision = 4;

struct FleshDynamicsParams {
  double density = 1100.0;         // kg/m^3 (soft tissue, ~1.05-1.1 times water)
  double massDamping = 0.0;        // alpha, 1/s
  double stiffnessDamping = 0.0;   // beta, s
  FleshIntegrator integrator = FleshIntegrator::BackwardEuler;
  int newtonIterations = 4;
  double newtonTolerance = 1e-6;   // of the residual, relative to the first Newton step's
  int cgIterations = 300;
  double cgTolerance = 1e-8;       // relative residual of each linear solve
  // Metres; 0: off. A linear solve also stops when its preconditioned residual (about the position
  // change still to come) is under this at every node, and Newton stops after an update that moved
  // no node further: a step the rig barely drives is solved to what can be seen, not to a ratio of
  // its own small residual.
  double positionTolerance = 0.0;
};

struct FleshStepReport {
  int newtonIterations = 0, cgIterations = 0;
  double residual = 0.0;  // the last Newton residual's norm, N
};

class FleshSimulation {
 public:
  // The mesh's nodes are its first rest shape and its first positions (at rest, not moving).
  FleshSimulation(const TetMesh& mesh, FleshMaterial material, LameParameters lame, FleshDynamicsParams params,
                  std::vector<bool> kinematic);

  // One step of h seconds. target: the rig's pose of every node at the step's end (the rest
  // shape from now on; where kinematic nodes go); targetVelocity: the rig's node velocities.
  FleshStepReport step(double h, const std::vector<Vec3d>& target, const std::vector<Vec3d>& targetVelocity);

  const std::vector<Vec3d>& positions() const { return x_; }
  const std::vector<Vec3d>& velocities() const { return v_; }
  void setState(std::vector<Vec3d> positions, std::vector<Vec3d> velocities);

  double kineticEnergy() const;
  double elasticEnergy() const { return elasticity_.energy(x_); }
  Vec3d momentum() const;
  const std::vector<double>& masses() const { return mass_; }
  const FvmElasticity& elasticity() const { return elasticity_; }

 private:
  double theta() const { return params_.integrator == FleshIntegrator::BackwardEuler ? 1.0 : 0.5; }
  // r(x) of the step (zero on kinematic nodes); leaves the elasticity linearized at the step's
  // evaluation point (x, or the midpoint) for the Newton step that follows.
  std::vector<Vec3d> residual(double h, const std::vector<Vec3d>& x, const std::vector<Vec3d>& targetVelocity);
  // Solves J dx = -r on the free nodes; returns the iterations taken.
  int solveNewtonStep(double h, const std::vector<Vec3d>& r, std::vector<Vec3d>& dx) const;
  void applyJacobian(double h, const std::vector<Vec3d>& in, std::vector<Vec3d>& out) const;
  std::vector<Vec3d> velocityAt(double h, const std::vector<Vec3d>& x) const;

  FvmElasticity elasticity_;
  FleshDynamicsParams params_;
  std::vector<bool> kinematic_;
  std::vector<double> mass_;
  std::vector<Vec3d> x_, v_;
  std::vector<Vec3d> x0_, v0_;  // the state at the start of the step being solved
};

}  // namespace lacrima::flesh
