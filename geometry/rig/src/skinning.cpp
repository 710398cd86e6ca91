// Linear blend skinning and rigid joint transforms.
#include "lacrima/rig/skinning.hpp"


#include <stdexcept>

#include <fmt/format.h>

#include "lacrima/base/vertex_ranges.hpp"

namespace lacrima {

Mat3 eulerDegreesToRotation(const Vec3& eulerDegrees) {
  const Eigen::AngleAxisf rx(degreesToRadians(eulerDegrees.x()), Vec3::UnitX());
  const Eigen::AngleAxisf ry(degreesToRadians(eulerDegrees.y()), Vec3::UnitY());
  const Eigen::AngleAxisf rz(degreesToRadians(eulerDegrees.z()), Vec3::UnitZ());
  return (rz * ry * rx).toRotationMatrix();
}

Affine3 jointTransform(const RigidJoint& joint, const Vec3& pivot) {
  // Rotation about a pivot: translate the pivot to the origin, rotate, translate back.
  Affine3 t = Affine3::Identity();
  t.translate(pivot + joint.translation);
  t.rotate(eulerDegreesToRotation(joint.eulerDegrees));
  t.translate(-pivot);
  return t;
}

void applyLinearBlendSkinning(std::vector<Vec3>& positions, const std::vector<Affine3>& bones,
                              const SkinWeights& weights) {
  if (weights.boneCount != bones.size())
    throw std::invalid_argument(
        fmt::format("skinning: weights are for {} bones but {} bones given", weights.boneCount, bones.size()));
  if (weights.weights.size() != positions.size() * bones.size())
    throw std::invalid_argument(fmt::format("skinning: {} weights for {} vertices and {} bones",
                                            weights.weights.size(), positions.size(), bones.size()));
  const size_t n = bones.size();
  forVertexRanges(positions.size(), [&](uint32_t begin, uint32_t end) {
    for (size_t v = begin; v < end; ++v) {
      // LBS (Bao et al. 2019): v' = sum_k w_k T_k v. Blending the matrices first (T = sum_k w_k T_k) is
      // the same linear map and costs one matrix-vector product per vertex instead of one per bone.
      Eigen::Matrix<float, 3, 4> blended = Eigen::Matrix<float, 3, 4>::Zero();
      for (size_t k = 0; k < n; ++k) {
        const float w = weights.weights[v * n + k];
        if (w != 0.0f) blended += w * bones[k].matrix().topRows<3>();
      }
      positions[v] = blended.leftCols<3>() * positions[v] + blended.col(3);
    }
  });
}

}  // namespace lacrima
