// Shading frames.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {
namespace math_test {

std::vector<Vec3> testNormals() {
  std::vector<Vec3> normals = {Vec3(0, 0, 1),  Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0),
                               Vec3(0, -1, 0), Vec3(1e-4f, 0, -1).normalized(), Vec3(0, 1e-7f, -1).normalized(),
                               Vec3(1, 1, 1).normalized()};
  std::mt19937 rng(7);
  std::normal_distribution<float> gauss;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 v(gauss(rng), gauss(rng), gauss(rng));
    if (v.norm() > 1e-3f) normals.push_back(v.normalized());
  }
  return normals;
}

TEST(ShadingFrame, IsOrthonormalAndRightHandedForManyNormals) {
  for (const Vec3& n : testNormals()) {
    const ShadingFrame f = ShadingFrame::fromNormal(n);
    SCOPED_TRACE(::testing::Message() << "n = " << n.transpose());
    EXPECT_NEAR(f.s.norm(), 1.0f, 1e-5f);
    EXPECT_NEAR(f.t.norm(), 1.0f, 1e-5f);
    EXPECT_NEAR(f.s.dot(f.t), 0.0f, 1e-5f);
    EXPECT_NEAR(f.s.dot(n), 0.0f, 1e-5f);
    EXPECT_NEAR(f.t.dot(n), 0.0f, 1e-5f);
    EXPECT_LT((f.s.cross(f.t) - n).norm(), 1e-5f);  // right-handed: s x t = n
    EXPECT_EQ(f.n, n);
  }
}

TEST(ShadingFrame, LocalAndWorldAreInverse) {
  const Vec3 v(0.3f, -0.5f, 0.8f);
  for (const Vec3& n : {Vec3(0, 0, -1), Vec3(0.6f, 0.0f, 0.8f)}) {
    const ShadingFrame f = ShadingFrame::fromNormal(n);
    EXPECT_LT((f.toWorld(f.toLocal(v)) - v).norm(), 1e-6f);
    EXPECT_NEAR(f.toLocal(n).z(), 1.0f, 1e-6f);  // the normal is local +z
  }
}

}  // namespace math_test
}  // namespace lacrima
