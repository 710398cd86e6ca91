#pragma once
// Linear blend skinning and the rigid joint transforms a face rig is posed with.
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {

// A rigid joint: rotation by Euler angles in degrees (about x, then y, then z, all in asset axes)
// about a pivot, then a translation. The identity when all six numbers are zero.
struct RigidJoint {
  Vec3 eulerDegrees = Vec3::Zero();
  Vec3 translation = Vec3::Zero();

  bool isIdentity() const { return eulerDegrees.isZero(0.0f) && translation.isZero(0.0f); }
};

// Rotation R = Rz Ry Rx (x applied first) from Euler degrees.
Mat3 eulerDegreesToRotation(const Vec3& eulerDegrees);

// The joint as an affine map: p -> R (p - pivot) + pivot + translation.
Affine3 jointTransform(const RigidJoint& joint, const Vec3& pivot);

// Bone weights of every vertex, dense: weights[v * boneCount + k] is the weight of bone k on
// vertex v. Rows should sum to 1 (a vertex's bone weights, as in Bao et al. 2019).
struct SkinWeights {
  size_t boneCount = 0;
  std::vector<float> weights;
};

// Bao et al. 2019, linear blend skinning: v' = sum_k w_k T_k v, in place.
// Throws std::invalid_argument when the weights do not have one row of boneCount per position
// or boneCount differs from bones.size().
void applyLinearBlendSkinning(std::vector<Vec3>& positions, const std::vector<Affine3>& bones,
                              const SkinWeights& weights);

}  // namespace lacrima
