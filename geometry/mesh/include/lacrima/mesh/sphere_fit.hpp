#pragma once
// Sphere through a point cloud by linear least squares (used to find an eyeball's centre).
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {

struct FittedSphere {
  Vec3 center = Vec3::Zero();
  float radius = 0.0f;
};

// Algebraic least-squares sphere: minimises sum (|p|^2 - 2 c.p - k)^2 over c and k = r^2 - |c|^2
// (Pratt 1987, "Direct least-squares fitting of algebraic surfaces", the sphere case), solved in
// double precision about the centroid. Throws InputError for fewer than 4 points or points that
// lie on a plane or line (no unique sphere).
FittedSphere fitSphere(const std::vector<Vec3>& points);

}  // namespace lacrima
