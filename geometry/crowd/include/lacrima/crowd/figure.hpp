#pragma once
// How an agent of the flood is drawn: a figure 1.8 m tall, posed each frame from what the
// simulation did to it.
// * Walking (or wading): upright on the ground, turned to the way it moved, its legs and arms
//   swinging in a walk cycle whose phase is the distance walked over the stride (two steps,
//   1.4 m: about the 1.3 m/s walk of Schaffer et al.'s agents at 1.9 steps a second).
// * Carried (the ragdoll rule of Schaffer et al. 2020, section 4.1): the hip at the colliding
//   particles' mean height, the body turned about all three axes at a rate that is the water's
//   speed plus a number drawn per agent in [0.1, 0.5] (radians a second), limbs spread.
// The figure itself is either built here (ellipsoids on a skeleton of pelvis, torso, head, thighs,
// shins, upper arms and forearms) or a glTF mesh placed by the pose's root transform (its feet at
// y = 0, facing +z, in metres; a mesh does not swing its limbs).
#include <cstdint>
#include <vector>

#include "lacrima/crowd/biocrowds.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima::crowd {

struct FigurePose {
  Vec3d hip = Vec3d::Zero();               // the pelvis' centre, world metres
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  // figure frame (y up, facing +z) to world
  double walkPhase = 0.0;                  // cycles of the walk (fraction used)
  bool carried = false;                    // a ragdoll: limbs spread, no walk cycle
  // Where the feet stand when walking: the hip is this far above the ground.
  static constexpr double kHipHeight = 0.92;
};

// Follows every agent of one crowd from frame to frame (headings, walk phases, ragdoll turns).
class FigureAnimator {
 public:
  // `seed` draws each agent's extra turning rate.
  FigureAnimator(const std::vector<Agent>& agents, uint64_t seed);

  // One frame of `seconds`: the agents' new ground positions, whether each is carried, its hip
  // height when carried (metres), the water's ground speed at it (m/s), and the height of the
  // ground under it.
  struct AgentFrame {
    Vec2d position = Vec2d::Zero();
    bool carried = false;
    double hipHeight = 0.0;
    double waterSpeed = 0.0;
    double groundHeight = 0.0;
  };
  void advance(const std::vector<AgentFrame>& frame, double seconds);

  const std::vector<FigurePose>& poses() const { return poses_; }
  // The extra turning rate of agent a (radians a second, in [0.1, 0.5]).
  double extraTurnRate(size_t a) const { return extraTurnRates_[a]; }

  static constexpr double kStrideLength = 1.4;  // metres walked per walk cycle (two steps)

 private:
  std::vector<FigurePose> poses_;
  std::vector<Vec2d> lastPositions_;
  std::vector<double> headings_;        // radians about +y, 0 facing +z
  std::vector<Vec3d> ragdollAngles_;    // accumulated turns about x, y, z while carried
  std::vector<double> extraTurnRates_;
};

// The built-in figure in `pose`: eleven ellipsoids (`rings` x 2 `rings` facets each), closed and
// outward-facing, feet on the ground when upright.
TriangleMesh articulatedFigure(const FigurePose& pose, int rings = 8);

// The pose's root transform (figure frame to world): what places a glTF figure (feet at y = 0,
// facing +z) so that its hip sits where the built-in figure's does.
Eigen::Affine3d figureRootTransform(const FigurePose& pose);

}  // namespace lacrima::crowd
