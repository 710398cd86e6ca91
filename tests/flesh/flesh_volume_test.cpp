// The flesh volume under a patch of skin: its border cleaned, meshed by TetGen with the skin's
// vertices as its first nodes, the right volume, nodes anchored so any pose of the skin places
// them, and clear errors for a volume that cannot be built.
#include "lacrima/flesh/flesh_volume.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <map>
#include <random>

namespace lacrima::flesh {
namespace flesh_volume_test {

struct SkinMesh {
  std::vector<Vec3d> positions, normals;
  std::vector<std::array<uint32_t, 3>> triangles;
  SkinPatch patch() const { return extractSkinPatch(positions, normals, triangles, std::vector<bool>(triangles.size(), true)); }
};

// An n x n grid of squares over [0, size]^2 in the plane z = 0, facing +z.
SkinMesh flatSkin(double size, int n) {
  SkinMesh skin;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      skin.positions.emplace_back(size * i / n, size * j / n, 0.0);
      skin.normals.emplace_back(0, 0, 1);
    }
  const auto v = [n](int i, int j) { return uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      skin.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      skin.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  return skin;
}

// The cap of a sphere of radius r within `angle` of its +z pole, by latitude-longitude rings.
SkinMesh sphereCap(double r, double angle, int rings, int segments) {
  SkinMesh skin;
  skin.positions.emplace_back(0, 0, r);
  for (int ring = 1; ring <= rings; ++ring)
    for (int s = 0; s < segments; ++s) {
      const double theta = angle * ring / rings, phi = 2 * std::numbers::pi * s / segments;
      skin.positions.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  for (const Vec3d& p : skin.positions) skin.normals.push_back(p.normalized());
  const auto v = [segments](int ring, int s) { return uint32_t(1 + (ring - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) skin.triangles.push_back({0, v(1, s), v(1, s + 1)});
  for (int ring = 1; ring < rings; ++ring)
    for (int s = 0; s < segments; ++s) {
      skin.triangles.push_back({v(ring, s), v(ring + 1, s), v(ring + 1, s + 1)});
      skin.triangles.push_back({v(ring, s), v(ring + 1, s + 1), v(ring, s + 1)});
    }
  return skin;
}

TEST(FleshVolume, FlatSkinGivesTheSlabUnderIt) {
  const SkinPatch patch = flatSkin(0.04, 10).patch();
  FleshVolumeSettings settings;
  settings.depth = 0.01;
  settings.maxTetVolume = 2e-8;
  const FleshVolume volume = buildFleshVolume(patch, settings);
  EXPECT_EQ(findTetMeshDefect(volume.mesh), "");
  EXPECT_NEAR(totalVolume(volume.mesh), 0.04 * 0.04 * 0.01, 1e-12);
  ASSERT_GE(volume.mesh.nodes.size(), 2 * patch.positions.size());
  EXPECT_EQ(volume.skinNodes, int(patch.positions.size()));
  for (size_t v = 0; v < patch.positions.size(); ++v) EXPECT_EQ(volume.mesh.nodes[v], patch.positions[v]);
  // The volume bound holds inside; tetrahedra on the skin's unsplit triangles may exceed it.
  size_t withinBound = 0;
  for (const Tet& t : volume.mesh.tets) withinBound += signedVolume(volume.mesh.nodes, t) <= settings.maxTetVolume * 1.000001;
  EXPECT_GT(double(withinBound), 0.8 * double(volume.mesh.tets.size()));
  // Kinematic: the inner surface (z = -depth) and the walls (with the skin's border); free: the
  // skin inside the border and the points inside.
  for (size_t i = 0; i < volume.mesh.nodes.size(); ++i) {
    const Vec3d& p = volume.mesh.nodes[i];
    const bool onWall = p.x() < 1e-9 || p.x() > 0.04 - 1e-9 || p.y() < 1e-9 || p.y() > 0.04 - 1e-9;
    const bool inner = std::abs(p.z() + 0.01) < 1e-12;
    EXPECT_EQ(bool(volume.kinematic[i]), onWall || inner) << i << ": " << p.transpose();
  }
  std::printf("flat skin 4 x 4 cm, 1 cm deep: %zu nodes, %zu tetrahedra\n", volume.mesh.nodes.size(), volume.mesh.tets.size());
}

TEST(FleshVolume, SphereCapGivesTheSphericalShellSegment) {
  // The patch: the triangles within 0.6 rad of the pole of a 0.9 rad cap.
  const double r = 0.06, angle = 0.6, depth = 0.012;
  const SkinMesh cap = sphereCap(r, 0.9, 24, 48);
  std::vector<bool> selected;
  for (const auto& t : cap.triangles) {
    bool inside = true;
    for (uint32_t v : t) inside = inside && cap.positions[v].z() >= r * std::cos(angle) - 1e-12;
    selected.push_back(inside);
  }
  const SkinPatch patch = extractSkinPatch(cap.positions, cap.normals, cap.triangles, selected);
  FleshVolumeSettings settings;
  settings.depth = depth;
  settings.maxTetVolume = 5e-9;
  const FleshVolume volume = buildFleshVolume(patch, settings);
  EXPECT_EQ(findTetMeshDefect(volume.mesh), "");
  const double exact = 2.0 * std::numbers::pi / 3.0 * (1.0 - std::cos(angle)) * (std::pow(r, 3) - std::pow(r - depth, 3));
  // Chords cut a little off the sphere (about 1 - cos(dphi / 2) of it, under 1 % here).
  EXPECT_NEAR(totalVolume(volume.mesh) / exact, 1.0, 0.01);
  std::printf("cap: %zu tetrahedra, volume %.4g m^3 against %.4g m^3\n", volume.mesh.tets.size(),
              totalVolume(volume.mesh), exact);
}

TEST(FleshVolume, AnchorsCarryTheNodesWithAnyRigidPoseOfTheSkin) {
  const SkinPatch patch = sphereCap(0.06, 0.5, 8, 24).patch();
  FleshVolumeSettings settings;
  settings.maxTetVolume = 2e-8;
  const FleshVolume volume = buildFleshVolume(patch, settings);
  // At rest the anchors give the nodes back.
  const std::vector<Vec3d> rest = anchoredNodePositions(volume, patch, patch.positions);
  for (size_t i = 0; i < rest.size(); ++i) EXPECT_LT((rest[i] - volume.mesh.nodes[i]).norm(), 1e-12) << i;
  // A turned and moved skin turns and moves the whole volume with it.
  const Eigen::Isometry3d pose = Eigen::Translation3d(0.1, -0.2, 0.05) * Eigen::AngleAxisd(0.8, Vec3d(1, 1, 0).normalized());
  std::vector<Vec3d> posedSkin;
  for (const Vec3d& p : patch.positions) posedSkin.push_back(pose * p);
  const std::vector<Vec3d> posed = anchoredNodePositions(volume, patch, posedSkin);
  for (size_t i = 0; i < posed.size(); ++i) EXPECT_LT((posed[i] - pose * volume.mesh.nodes[i]).norm(), 1e-12) << i;
}

TEST(FleshVolume, TooDeepForTheSkinsCurvatureIsAnError) {
  const SkinPatch patch = sphereCap(0.01, 1.2, 8, 24).patch();
  FleshVolumeSettings settings;
  settings.depth = 0.02;  // deeper than the sphere's radius: the inner surface turns inside out
  try {
    buildFleshVolume(patch, settings);
    FAIL() << "no error";
  } catch (const FleshVolumeError& e) {
    EXPECT_NE(std::string(e.what()).find("too deep for the skin's curvature"), std::string::npos) << e.what();
  }
  EXPECT_THROW(buildFleshVolume(SkinPatch{}, FleshVolumeSettings{}), FleshVolumeError);
  settings.depth = -0.01;
  EXPECT_THROW(buildFleshVolume(patch, settings), FleshVolumeError);
}

TEST(FleshVolume, SkinThatCrossesItselfIsAnErrorNotACrash) {
  // Two sheets of skin through each other: TetGen fails (or dies, in its own process) on the
  // intersecting boundary; either way the caller gets an error.
  SkinMesh a = flatSkin(0.04, 4), b = flatSkin(0.04, 4);
  for (Vec3d& p : b.positions) p = Vec3d(p.x(), 0.02, p.y() - 0.02);
  for (Vec3d& n : b.normals) n = Vec3d(0, -1, 0);
  SkinMesh both = a;
  const uint32_t offset = uint32_t(a.positions.size());
  both.positions.insert(both.positions.end(), b.positions.begin(), b.positions.end());
  both.normals.insert(both.normals.end(), b.normals.begin(), b.normals.end());
  for (auto t : b.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  FleshVolumeSettings settings;
  settings.depth = 0.005;
  EXPECT_THROW(buildFleshVolume(both.patch(), settings), FleshVolumeError);
}

TEST(FleshVolume, PatchBorderIsCleanedOfPinches) {
  SkinMesh skin = flatSkin(0.03, 3);
  std::vector<bool> selected(skin.triangles.size(), false);
  // Two squares side by side, and a third touching the second at a single corner (a pinch).
  for (size_t t : {size_t(0), size_t(1), size_t(2), size_t(3), size_t(10), size_t(11)}) selected[t] = true;
  const SkinPatch patch = extractSkinPatch(skin.positions, skin.normals, skin.triangles, selected);
  EXPECT_LT(patch.triangles.size(), 6u);
  EXPECT_GT(patch.triangles.size(), 0u);
  // What is left has a border of simple loops: every border vertex has two border edges.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : patch.triangles)
    for (int c = 0; c < 3; ++c) ++uses[std::minmax(t[c], t[(c + 1) % 3])];
  std::map<int, int> borderAt;
  for (const auto& [edge, count] : uses)
    if (count == 1) ++borderAt[edge.first], ++borderAt[edge.second];
  for (const auto& [vertex, count] : borderAt) EXPECT_EQ(count, 2) << vertex;
  ASSERT_EQ(patch.skinTriangle.size(), patch.triangles.size());
  for (size_t t = 0; t < patch.triangles.size(); ++t)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(patch.skinVertex[size_t(patch.triangles[t][c])], skin.triangles[patch.skinTriangle[t]][c]);
}

TEST(FleshVolume, PointsEmbedWithWeightsThatRebuildThem) {
  const SkinPatch patch = flatSkin(0.04, 8).patch();
  FleshVolumeSettings settings;
  settings.maxTetVolume = 2e-8;
  const FleshVolume volume = buildFleshVolume(patch, settings);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3d> points = patch.positions;  // on the boundary
  for (int i = 0; i < 200; ++i) points.emplace_back(0.04 * u(random), 0.04 * u(random), -0.012 * u(random));
  const std::vector<TetEmbedding> embedded = embedPoints(volume.mesh, points);
  for (size_t i = 0; i < points.size(); ++i) {
    ASSERT_GE(embedded[i].tet, 0);
    EXPECT_GT(embedded[i].weights.minCoeff(), -1e-9) << i;
    EXPECT_NEAR(embedded[i].weights.sum(), 1.0, 1e-12);
    EXPECT_LT((embeddedPosition(volume.mesh, volume.mesh.nodes, embedded[i]) - points[i]).norm(), 1e-12);
  }
}

TEST(FleshVolume, PointsOutsideTheVolumeEmbedOnlyWithinTheSlack) {
  const SkinPatch patch = flatSkin(0.04, 8).patch();
  FleshVolumeSettings settings;
  settings.maxTetVolume = 2e-8;
  const FleshVolume volume = buildFleshVolume(patch, settings);
  // The skin is the plane z = 0 and the flesh lies under it: a hair above is a hair outside.
  const std::vector<Vec3d> points{{0.02, 0.02, 1e-6}, {0.02, 0.02, 0.004}, {0.02, 0.02, -0.1}};
  const std::vector<TetEmbedding> embedded = embedPoints(volume.mesh, points, 0.02);
  ASSERT_GE(embedded[0].tet, 0);
  EXPECT_LT(embedded[0].weights.minCoeff(), 0.0);
  EXPECT_GE(embedded[0].weights.minCoeff(), -0.02);
  EXPECT_EQ(embedded[1].tet, -1) << "4 mm above the skin";
  EXPECT_EQ(embedded[2].tet, -1) << "far below the inner surface";
  EXPECT_EQ(embedPoints(volume.mesh, points)[0].tet, -1) << "no slack: not inside";
}

}  // namespace flesh_volume_test
}  // namespace lacrima::flesh
