#pragma once
// One-way coupling of crowd agents to a particle liquid (Schaffer et al. 2020, "Towards Animating
// Virtual Humans in Flooded Environments", MIG 2020, section 3). The liquid pushes the agents; the
// agents do not push the liquid.
// * Collision: fluid particles projected to the ground (y = 0) are discs of radius r_p, agents
//   discs of radius r_a; a particle collides with an agent when the distance d between their
//   centres on the ground is below r_p + r_a. Only particles in the 3 x 3 cells (2 m squares)
//   around the agent are tested.
// * Per agent and frame, the colliding particles' momentum and mass (eq. 5):
//     p_F = sum_i m_i v_i,   m_c = sum_i m_i.
// * The agent's velocity after the inelastic collision, attenuated by its endurance tau in [0, 1]
//   (eq. 9; eqs. 6-8 are tau = 1):
//     v_a(t + 1) = (p_B + tau p_F) / (m_a + tau m_c),   p_B = m_a v_B,
//   v_B the agent's walking velocity (biocrowds.hpp, eq. 4). tau = 0: the liquid is ignored;
//   tau = 1: the liquid acts at its full strength. Only the ground components are used.
// * Ragdoll (for the picture only): an agent with tau >= 0.8 hit by a liquid faster than 2 m/s is
//   drawn carried, its hip at the colliding particles' mean height.
#include <vector>

#include "lacrima/crowd/biocrowds.hpp"
#include "lacrima/base/math.hpp"

namespace lacrima::crowd {

struct CouplingParams {
  double particleRadius = 0.25;  // r_p, metres (Schaffer et al.'s)
  double agentRadius = 0.5;      // r_a, metres (Schaffer et al.'s)
  double cellSize = 2.0;         // metres (Schaffer et al.'s; BioCrowds' space discretisation)
  double ragdollEndurance = 0.8;  // tau at or above which an agent can be carried as a ragdoll
  double ragdollSpeed = 2.0;      // m/s: the liquid's speed above which it is
};

// What the liquid does to one agent in a frame (eq. 5).
struct FluidContact {
  Vec3d momentum = Vec3d::Zero();  // p_F, kg m/s
  double mass = 0.0;               // m_c, kg
  double meanHeight = 0.0;         // the colliding particles' mean y, metres
  int particles = 0;
  // The colliding particles' mean velocity's speed on the ground (|p_F| / m_c in x, z); 0 if none.
  double groundSpeed() const;
};

// Per agent (ground positions), the particles colliding with it. Particles all weigh
// `particleMass` (an SPH liquid's). Sums run in particle index order (deterministic).
std::vector<FluidContact> fluidContacts(const std::vector<Vec2d>& agentPositions, const std::vector<Vec3d>& particlePositions,
                                        const std::vector<Vec3d>& particleVelocities, double particleMass,
                                        const CouplingParams& params);

// Eq. 9: the agent's ground velocity after the collision.
Vec2d coupledVelocity(double agentMass, const Vec2d& walkingVelocity, double endurance, const FluidContact& contact);

// Whether the agent is drawn as a ragdoll carried by the liquid (tau >= 0.8, liquid faster than 2 m/s).
bool carriedAsRagdoll(double endurance, const FluidContact& contact, const CouplingParams& params);

}  // namespace lacrima::crowd
