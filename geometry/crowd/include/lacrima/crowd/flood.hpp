#pragma once
// Schaffer et al. 2020's flood scenario (section 4.1): a river of SPH water streaming across a
// field, crowds of BioCrowds agents trying to cross it, pushed one way by the water (eqs. 5-9,
// fluid_coupling.hpp). The river is a channel `width` wide and `depth` deep along x, from x =
// `length` (upstream, where an emitter feeds it particles at the stream speed v_F) to
// x = 0, past which it streams off the floor's end and its particles are recycled (an emitter
// half a spacing from the upstream wall fills every lattice place the flow has cleared; the water
// in an inflow and an outflow zone is held at v_F, an open boundary in the manner of Tafuni et al.
// 2018's buffer zones, so that the river keeps its depth). It starts
// full and flowing at v_F, or dry, the water entering at the emitter at t = 0 and running down the
// bed as a front (Schaffer et al.'s runs: its figures 7 and 8 show the water reaching the agents at 10-15 s). Obstacles are blocks standing on the ground: walls for the water and
// for the agents. Every frame (`frameTime`, the coupling's frame) the liquid is advanced, then each
// crowd walks, pushed by the particles colliding with its agents. An agent carried past the end of
// the river (x < 0) is lost. The liquid does not depend on the agents (the coupling is one way),
// so any number of crowds can cross the same river in one simulation: each is a separate run of
// Schaffer et al.'s table. Schaffer et al.'s experiments are scenario files (scenes/floods, read by
// lacrima/scenes/flood_scenario.hpp).
#include <string>
#include <utility>
#include <vector>

#include "lacrima/crowd/biocrowds.hpp"
#include "lacrima/crowd/fluid_coupling.hpp"
#include "lacrima/sph/dfsph.hpp"

namespace lacrima::crowd {

struct RiverParams {
  double zMin = 11.5, width = 27.0, depth = 1.0, length = 100.0;  // metres; it flows towards -x
  double speed = 1.5;             // v_F, m/s, of the inflow and of the water at the start
  double particleRadius = 0.25;   // metres: 21,600 particles fill Schaffer et al.'s river at 0.25
  double bankHeight = 2.0;        // metres: the channel's side walls
  std::vector<GroundRect> obstacles;  // blocks in the river or on the ground
  double obstacleHeight = 1.0;
  bool startsFull = true;  // false: the channel starts dry and fills from the emitter
};

struct FloodCrowd {
  std::string name;
  std::vector<Agent> agents;
  // The endurance tau over time: (seconds, tau) keys, held from each key to the next (Schaffer et al.
  // change tau at a frame); before the first key, the first key's value.
  std::vector<std::pair<double, double>> endurance{{0.0, 0.0}};
  double agentMass = 65.0;  // kg, Schaffer et al.'s
};

struct FloodParams {
  GroundRect field{Vec2d(0, 0), Vec2d(100, 50)};
  RiverParams river;
  std::vector<FloodCrowd> crowds;
  CrowdParams crowd;
  CouplingParams coupling;
  double frameTime = 0.1;  // seconds: the coupling's frame (eq. 5 sums the mass colliding in one)
  // The density of the water as eq. 5 counts it: each colliding particle weighs this times its
  // volume (2r)^3; <= 0: the liquid's own rest density (1000 kg/m^3, 125 kg a particle at r = 0.25 m).
  // Schaffer et al.'s sums are per frame of a sparse stream whose particles it does not specify;
  // docs/crowd.md derives the mass its timings imply (about 80 kg/m^3 at 10 frames a second).
  // A density, not a mass, so that the push does not change with the particle size.
  double coupledDensity = 0.0;
};

// What became of one agent.
struct AgentOutcome {
  double arrivalTime = -1.0;  // seconds; < 0: did not arrive
  double lostTime = -1.0;     // seconds; < 0: not lost
};

class FloodSimulation {
 public:
  explicit FloodSimulation(FloodParams params);

  // Advances the liquid and every crowd by one frame.
  void advanceFrame();
  // Whether every agent of every crowd has arrived or been lost.
  bool settled() const;

  double time() const { return time_; }
  const FloodParams& params() const { return params_; }
  const sph::DfsphSolver& liquid() const { return liquid_; }
  const BioCrowds& crowd(size_t c) const { return crowds_[c]; }
  const std::vector<AgentOutcome>& outcomes(size_t c) const { return outcomes_[c]; }
  // Per agent of crowd c, whether it was drawn as a ragdoll in the last frame (tau >= 0.8 in water
  // faster than 2 m/s), and its hip height then (the colliding particles' mean height; 0 if dry).
  const std::vector<bool>& ragdolls(size_t c) const { return ragdolls_[c]; }
  const std::vector<double>& hipHeights(size_t c) const { return hipHeights_[c]; }
  // Per agent of crowd c, the colliding particles' mean ground speed in the last frame (0 if dry).
  const std::vector<double>& waterSpeeds(size_t c) const { return waterSpeeds_[c]; }
  double endurance(size_t c, double time) const;
  size_t particlesEmitted() const { return emitted_; }

 private:
  void feedAndDrainRiver();
  void advanceCrowd(size_t c);

  FloodParams params_;
  sph::DfsphSolver liquid_;
  std::vector<BioCrowds> crowds_;
  std::vector<std::vector<AgentOutcome>> outcomes_;
  std::vector<std::vector<bool>> ragdolls_;
  std::vector<std::vector<double>> hipHeights_;
  std::vector<std::vector<double>> waterSpeeds_;
  double time_ = 0.0;
  size_t emitted_ = 0;
};

}  // namespace lacrima::crowd
