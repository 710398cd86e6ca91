#pragma once
// Divergence-free SPH (Bender & Koschier 2015, "Divergence-Free Smoothed Particle Hydrodynamics",
// SCA; 2017, "Divergence-Free SPH for Incompressible and Viscous Fluids", IEEE TVCG 23(3),
// Algorithm 1): per step, the non-pressure forces give predicted velocities, a constant-density
// solve corrects them so that the positions they lead to have the rest density (eqs. 8-12), the
// particles move, and a divergence-free solve corrects the velocities so that the density does
// not change (eqs. 13-15). Both solves are Jacobi iterations on a per-particle stiffness
//   kappa_i = (rho*_i - rho0) / dt^2 * alpha_i      (density),
//   kappa_i = (D rho_i / D t) / dt * alpha_i        (divergence),
//   alpha_i = rho_i / (|sum_j m_j grad W_ij + sum_b Psi_b grad W_ib|^2 + sum_j |m_j grad W_ij|^2),
// applied as v_i -= dt [sum_j m_j (kappa_i / rho_i + kappa_j / rho_j) grad W_ij
//                       + sum_b Psi_b (kappa_i / rho_i) grad W_ib],
// kappa having the units of p / rho (so p_i = rho_i times the sum of the density solve's kappas).
// Only compression is corrected (rho* and D rho / D t clamped at 0 from below), as for a free surface.
//
// Boundaries are static particles (Akinci et al. 2012, "Versatile Rigid-Fluid Coupling for
// Incompressible SPH", ACM TOG 31(4), eqs. 4-5 and 10): each carries Psi_b = rho0 V_b,
// V_b = 1 / sum_k W_bk over its boundary neighbours, in the fluid's density and, with the fluid
// particle's own pressure, in the pressure force.
// Surface tension and adhesion: Akinci, Akinci & Teschner 2013 (surface_tension.hpp), with the
// non-pressure forces.
// Viscosity: XSPH (Schechter & Bridson 2012, "Ghost SPH for Animating Water", ACM TOG 31(4), eq. 11:
// v_i += c sum_j (m_j / rho_j) (v_j - v_i) W_ij). Time step: the CFL condition
// dt = cfl * 2 r / max |v| (Bender & Koschier 2017, section 5), clamped to [minTimeStep, maxTimeStep].
// Kernel: the cubic spline with support radius 4 r (sph_kernel.hpp). Every sum runs over neighbours
// in ascending order and every average in particle order: bitwise the same for any thread count.
#include <cstdint>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/sph/neighbour_grid.hpp"
#include "lacrima/sph/sph_kernel.hpp"

namespace lacrima::sph {

struct FluidParams {
  double particleRadius = 0.0025;  // metres; particles start 2 r apart, the kernel reaches 4 r
  double restDensity = 1000.0;     // kg / m^3
  double xsphViscosity = 0.01;     // c above, dimensionless
  double surfaceTension = 0.0;     // Akinci et al. 2013's gamma; from N/m: akinciGammaForSigma; 0 = none
  double adhesion = 0.0;           // Akinci et al. 2013's beta, towards boundary particles; 0 = none
  Vec3d gravity = Vec3d(0.0, -9.81, 0.0);
  double cflFactor = 0.4;
  double minTimeStep = 1e-5, maxTimeStep = 2e-3;  // seconds
  double maxDensityError = 1e-3;     // average relative compression after the density solve (0.1 %)
  double maxDivergenceError = 1e-3;  // average relative density change a step after the divergence solve
  int minIterations = 2, maxIterations = 500;
};

// The longest step Akinci et al. 2013's cohesion and curvature forces (surface_tension.hpp) allow:
// a stiff pairwise force integrated explicitly diverges when the step is long against its period,
// whatever the particles' speed (the CFL condition does not see it), as Brackbill, Kothe & Zemach
// 1992 (section 4) found for surface tension on a grid. The force per unit mass between two
// particles is of order gamma rho0 over the support h, so the step is bounded by
// kCapillaryStepFactor sqrt(h / (gamma rho0)). Measured (a 1 mm drop of 0.1 or 0.05 mm particles
// in zero gravity, swinging in its second mode at 0.2 m/s, gamma 20 and 80): particles are thrown
// out of the drop above 1.6-1.9 sqrt(h / (gamma rho0)) and not at or below 1.4; the factor keeps
// half of that. Infinite without surface tension.
inline constexpr double kCapillaryStepFactor = 0.8;
double capillaryTimeStep(const FluidParams& params);

// Static boundary particles and their volumes V_b (Akinci et al. 2012 eq. 4).
struct BoundaryParticles {
  std::vector<Vec3d> positions;
  std::vector<double> volumes;
};
BoundaryParticles boundaryFromSamples(std::vector<Vec3d> samples, double particleRadius);

// Points on a lattice of spacing `spacing` filling [lo, hi] (from lo + spacing / 2).
std::vector<Vec3d> latticeBlock(const Vec3d& lo, const Vec3d& hi, double spacing);
// How many points latticeBlock(lo, hi, spacing) makes, without making them (as a double: a shot's
// slip can ask for more than fit in memory, or in an int).
double latticeBlockCount(const Vec3d& lo, const Vec3d& hi, double spacing);

// Boundary samples on the surface of a triangle mesh, one layer (Akinci et al. 2012 section 3.1:
// a single layer of boundary particles suffices, their volumes V_b making up for the missing
// ones): each triangle's barycentric grid fine enough that no two neighbours are farther apart
// than `spacing`; samples that neighbouring triangles share (vertices, edges) kept once. Fluid
// must start at least a particle spacing (2 r) from such a surface: at r, where two or three
// walls meet, the boundary alone makes the density twice the rest density.
std::vector<Vec3d> meshSurfaceSamples(const TriangleMesh& mesh, double spacing);

// Where meshSurfaceSamples puts its samples: a triangle and the fractions along its edges from its
// first corner to the other two. The same sites on the mesh deformed (a posed face, a moved shape,
// the same triangles) are the moving boundary's particles.
struct SurfaceSite {
  uint32_t triangle;
  double towardsSecond, towardsThird;
};
// Only the triangles `selected` marks, when it has one entry per triangle (a stretch of a face).
std::vector<SurfaceSite> meshSurfaceSites(const TriangleMesh& mesh, double spacing,
                                          const std::vector<bool>& selected = {});
// How many sites meshSurfaceSites tries on the (selected) triangles before merging those that
// neighbouring triangles share: what sampling a mesh would cost, without sampling it.
double meshSurfaceSiteCandidates(const TriangleMesh& mesh, double spacing, const std::vector<bool>& selected = {});
// The sites' positions on `mesh` (meshSurfaceSamples(mesh, s) is sitePositions(mesh,
// meshSurfaceSites(mesh, s)), bitwise).
std::vector<Vec3d> sitePositions(const TriangleMesh& mesh, const std::vector<SurfaceSite>& sites);

// `layers` layers of boundary samples (spacing `spacing`) outside the walls and floor of the
// open-top box [lo, hi] (the fluid's container).
std::vector<Vec3d> openBoxWalls(const Vec3d& lo, const Vec3d& hi, double spacing, int layers);

struct StepStats {
  double timeStep = 0.0;
  int densityIterations = 0, divergenceIterations = 0;
  double densityError = 0.0;     // average relative compression after the density solve
  double divergenceError = 0.0;  // dt times the average relative density rate after the divergence solve
};

class DfsphSolver {
 public:
  DfsphSolver(const FluidParams& params, std::vector<Vec3d> fluid, BoundaryParticles boundary);

  void step();
  // Steps until `time`, the last step shortened to land on it.
  void advanceTo(double time);

  // Replaces the fluid by `positions` moving at `velocities` (the same count) at `time`: initial
  // velocities, or a state read back from disk. The boundary stays.
  void setState(std::vector<Vec3d> positions, std::vector<Vec3d> velocities, double time);
  // Adds particles (an emitted drop) at the current time, after the existing ones.
  void addParticles(const std::vector<Vec3d>& positions, const std::vector<Vec3d>& velocities);
  // Moving boundaries (a keyed collider, the posed face): puts the boundary particles at
  // `positions` now, moving at `velocities` (metres per second, the same count as the boundary)
  // until the next call: each step moves them with the fluid, and the density's rate of change
  // counts the fluid's velocity relative to theirs (Akinci et al. 2012 eq. 10 with v_b). Their
  // volumes V_b stay those of the start (the boundary is assumed to move locally rigidly).
  void moveBoundary(std::vector<Vec3d> positions, std::vector<Vec3d> velocities);
  // The step the next step() takes (the CFL condition).
  double nextTimeStep() const { return adaptedTimeStep(); }

  double time() const { return time_; }
  double particleMass() const { return mass_; }
  const FluidParams& params() const { return params_; }
  const std::vector<Vec3d>& positions() const { return x_; }
  const std::vector<Vec3d>& velocities() const { return v_; }
  const std::vector<double>& densities() const { return rho_; }
  // p_i = rho_i times the density solve's stiffness summed over the last step's iterations.
  std::vector<double> pressures() const;
  const StepStats& lastStep() const { return stats_; }

 private:
  void advanceBy(double dt);  // one step of dt
  void updateNeighbours();
  void computeDensitiesAndFactors();
  double adaptedTimeStep() const;
  void applyNonPressureForces(double dt);
  // Akinci et al. 2013's cohesion, curvature and adhesion accelerations (surface_tension.hpp).
  std::vector<Vec3d> surfaceAccelerations() const;
  int solveDensity(double dt);
  int solveDivergence(double dt);
  // v_i -= dt [sum_j m (k_i/rho_i + k_j/rho_j) grad W_ij + sum_b Psi_b (k_i/rho_i) grad W_ib].
  void applyStiffness(const std::vector<double>& kappa, double dt);
  // sum_j m (v_i - v_j) . grad W_ij + sum_b Psi_b v_i . grad W_ib: the density's rate of change.
  double densityRate(size_t i) const;

  FluidParams params_;
  CubicSplineKernel kernel_;
  double mass_;
  std::vector<Vec3d> x_, v_;
  std::vector<double> rho_, alpha_, pressureKappa_;
  BoundaryParticles boundary_;
  std::vector<Vec3d> boundaryVelocities_;  // empty: a static boundary
  std::vector<double> boundaryPsi_;
  NeighbourGrid fluidGrid_, boundaryGrid_;
  std::vector<std::vector<uint32_t>> fluidNeighbours_, boundaryNeighbours_;
  // grad W(x_i - x_j) per neighbour entry (and Psi_b grad W(x_i - x_b) per boundary entry), at the
  // positions of the last neighbour update: both solves use them in every iteration.
  std::vector<std::vector<Vec3d>> fluidGradients_, boundaryGradients_;
  double time_ = 0.0;
  StepStats stats_;
};

}  // namespace lacrima::sph
