// Agents' figures and their poses; see figure.hpp.
#include "lacrima/crowd/figure.hpp"

#include <cmath>
#include <numbers>

#include "lacrima/base/hash.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima::crowd {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Eigen::Matrix3d rotationAbout(const Vec3d& axis, double radians) {
  return Eigen::AngleAxisd(radians, axis).toRotationMatrix();
}

// A limb (or trunk) segment from joint p to joint q, `radius` thick: an ellipsoid overlapping the
// next segment at the joints.
struct Segment {
  Vec3d from, to;
  double radius;
};

// A direction in the figure's sagittal plane: `forward` radians from straight down towards +z,
// tilted `outward` radians towards `side` (+1 left, -1 right; left is +x).
Vec3d limbDirection(double forward, double outward, double side) {
  return Vec3d(side * std::sin(outward), -std::cos(forward) * std::cos(outward), std::sin(forward) * std::cos(outward));
}

// The skeleton's segments in the figure frame (y up, facing +z, feet at y = 0 when upright).
std::vector<Segment> skeleton(const FigurePose& pose) {
  const double cycle = 2.0 * std::numbers::pi * pose.walkPhase;
  std::vector<Segment> segments;
  const Vec3d pelvis(0.0, FigurePose::kHipHeight + 0.03, 0.0);
  segments.push_back({pelvis + Vec3d(0, 0.08, 0), Vec3d(0, 1.44, 0), 0.15});  // torso
  for (const double side : {1.0, -1.0}) {
    // Legs: the thigh swings 20 degrees either way, opposite legs half a cycle apart; the knee
    // bends up to 40 degrees while its leg swings forward. Carried: legs apart, a little bent.
    const double legPhase = side > 0 ? cycle : cycle + std::numbers::pi;
    const double thighAngle = pose.carried ? 10.0 * kDegree : 20.0 * kDegree * std::sin(legPhase);
    const double kneeBend = pose.carried ? 25.0 * kDegree : 40.0 * kDegree * std::max(0.0, std::cos(legPhase));
    const double legSpread = pose.carried ? 15.0 * kDegree : 2.0 * kDegree;
    const Vec3d hip(side * 0.09, FigurePose::kHipHeight, 0.0);
    const Vec3d knee = hip + 0.45 * limbDirection(thighAngle, legSpread, side);
    const Vec3d ankle = knee + 0.43 * limbDirection(thighAngle - kneeBend, legSpread, side);
    segments.push_back({hip, knee, 0.075});
    segments.push_back({knee, ankle, 0.055});
    segments.push_back({ankle + Vec3d(0, -0.02, -0.03), ankle + Vec3d(0, -0.03, 0.15), 0.045});  // foot
    // Arms swing against the leg of their side; carried, they are thrown out.
    const double armAngle = pose.carried ? 0.0 : -18.0 * kDegree * std::sin(legPhase);
    const double armSpread = pose.carried ? 70.0 * kDegree : 8.0 * kDegree;
    const Vec3d shoulder(side * 0.2, 1.42, 0.0);
    const Vec3d elbow = shoulder + 0.3 * limbDirection(armAngle, armSpread, side);
    const Vec3d wrist = elbow + 0.27 * limbDirection(armAngle + 20.0 * kDegree, armSpread, side);
    segments.push_back({shoulder, elbow, 0.05});
    segments.push_back({elbow, wrist, 0.04});
  }
  return segments;
}

void append(TriangleMesh& into, const TriangleMesh& part) {
  const uint32_t base = uint32_t(into.positions.size());
  into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
  into.normals.insert(into.normals.end(), part.normals.begin(), part.normals.end());
  for (uint32_t i : part.indices) into.indices.push_back(base + i);
}

TriangleMesh segmentEllipsoid(const Segment& s, const Eigen::Affine3d& root, int rings) {
  const Vec3d along = s.to - s.from;
  const Vec3d u = along.normalized();
  const Vec3d helper = std::abs(u.x()) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
  const Vec3d v = u.cross(helper).normalized(), w = u.cross(v);
  Eigen::Matrix3d axes;
  axes.col(0) = v * s.radius;
  axes.col(1) = u * (0.5 * along.norm() + 0.6 * s.radius);
  axes.col(2) = w * s.radius;
  const Eigen::Matrix3d world = root.linear() * axes;
  const Vec3d center = root * (0.5 * (s.from + s.to));
  return makeEllipsoid(center.cast<float>(), world.cast<float>(), rings, 2 * rings);
}

}  // namespace

FigureAnimator::FigureAnimator(const std::vector<Agent>& agents, uint64_t seed)
    : poses_(agents.size()), headings_(agents.size(), 0.0), ragdollAngles_(agents.size(), Vec3d::Zero()) {
  for (size_t a = 0; a < agents.size(); ++a) {
    lastPositions_.push_back(agents[a].position);
    const Vec2d toGoal = agents[a].goal - agents[a].position;
    if (toGoal.norm() > 1e-9) headings_[a] = std::atan2(toGoal.x(), toGoal.y());
    // Schaffer et al.'s random increase of the ragdoll's turning rate, in [0.1, 0.5].
    extraTurnRates_.push_back(0.1 + 0.4 * double(uint64ToUnitFloat(hashCombine(seed, uint64_t(a)))));
    poses_[a].hip = Vec3d(agents[a].position.x(), FigurePose::kHipHeight, agents[a].position.y());
    poses_[a].orientation = rotationAbout(Vec3d::UnitY(), headings_[a]);
  }
}

void FigureAnimator::advance(const std::vector<AgentFrame>& frame, double seconds) {
  for (size_t a = 0; a < poses_.size() && a < frame.size(); ++a) {
    const AgentFrame& f = frame[a];
    FigurePose& pose = poses_[a];
    const Vec2d moved = f.position - lastPositions_[a];
    lastPositions_[a] = f.position;
    // Facing the way it went (a step shorter than a millimetre keeps the heading).
    if (moved.norm() > 1e-3) headings_[a] = std::atan2(moved.x(), moved.y());
    const Eigen::Matrix3d heading = rotationAbout(Vec3d::UnitY(), headings_[a]);
    pose.carried = f.carried;
    if (f.carried) {
      ragdollAngles_[a] += Vec3d::Constant((f.waterSpeed + extraTurnRates_[a]) * seconds);
      const Vec3d& t = ragdollAngles_[a];
      pose.orientation = heading * rotationAbout(Vec3d::UnitZ(), t.z()) * rotationAbout(Vec3d::UnitY(), t.y()) *
                         rotationAbout(Vec3d::UnitX(), t.x());
      pose.hip = Vec3d(f.position.x(), f.hipHeight, f.position.y());
    } else {
      ragdollAngles_[a].setZero();  // back on its feet
      pose.orientation = heading;
      pose.walkPhase += moved.norm() / kStrideLength;
      pose.hip = Vec3d(f.position.x(), f.groundHeight + FigurePose::kHipHeight, f.position.y());
    }
  }
}

Eigen::Affine3d figureRootTransform(const FigurePose& pose) {
  Eigen::Affine3d root = Eigen::Affine3d::Identity();
  root.linear() = pose.orientation;
  root.translation() = pose.hip - pose.orientation * Vec3d(0.0, FigurePose::kHipHeight, 0.0);
  return root;
}

TriangleMesh articulatedFigure(const FigurePose& pose, int rings) {
  const Eigen::Affine3d root = figureRootTransform(pose);
  TriangleMesh figure;
  for (const Segment& s : skeleton(pose)) append(figure, segmentEllipsoid(s, root, rings));
  // The head: an ellipsoid above the torso.
  Eigen::Matrix3d head = Vec3d(0.09, 0.115, 0.105).asDiagonal();
  head = root.linear() * head;
  append(figure, makeEllipsoid((root * Vec3d(0.0, 1.64, 0.01)).cast<float>(), head.cast<float>(), rings, 2 * rings));
  return figure;
}

}  // namespace lacrima::crowd
