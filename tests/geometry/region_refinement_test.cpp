// Local subdivision with closure: conforming (no T-junctions, seams included), orientation and
// shape kept, Loop's masks where the whole neighbourhood is refined, attributes carried along.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "geometry/mesh_support.hpp"
#include "lacrima/rig/region_refinement.hpp"

namespace lacrima {
namespace region_refinement_test {

// The regular icosahedron on the unit sphere, counter-clockwise from outside.
TriangleMesh icosahedron() {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  TriangleMesh m;
  for (const Vec3& p : {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0), Vec3(0, -1, t), Vec3(0, 1, t),
                        Vec3(0, -1, -t), Vec3(0, 1, -t), Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)})
    m.positions.push_back(p.normalized());
  m.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
               3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
  return m;
}

// An icosahedron split `levels` times everywhere, projected onto the unit sphere.
TriangleMesh icosphere(int levels) {
  TriangleMesh m = icosahedron();
  m = refineMesh(m, std::vector<bool>(m.triangleCount(), true), RefinementScheme::Linear, levels);
  for (Vec3& p : m.positions) p.normalize();
  return m;
}

// The unit cube with 4 vertices per face (24), as a UV-mapped glTF cube has: every edge is a seam.
TriangleMesh seamedCube() {
  TriangleMesh m;
  const Vec3 normals[6] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY(), Vec3::UnitZ(), -Vec3::UnitZ()};
  for (const Vec3& n : normals) {
    const Vec3 u = std::abs(n.x()) > 0.5f ? Vec3(Vec3::UnitY()) : Vec3(Vec3::UnitX());
    const Vec3 v = n.cross(u);
    const uint32_t base = uint32_t(m.positions.size());
    for (const Vec2& c : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
      m.positions.push_back(0.5f * (n + c.x() * u + c.y() * v));
      m.uvs.push_back(0.5f * (c + Vec2::Ones()));
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

// A planar n x n grid of quads on z = 0 over [0, 1]^2, counter-clockwise from +z.
TriangleMesh grid(int n) {
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.positions.emplace_back(float(i) / float(n), float(j) / float(n), 0.0f);
      m.uvs.emplace_back(float(i) / float(n), float(j) / float(n));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n) + 2, d = a + uint32_t(n) + 1;
      m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
    }
  return m;
}

// The triangles with a corner within `radius` of `p`.
std::vector<bool> trianglesNear(const TriangleMesh& m, const Vec3& p, float radius) {
  std::vector<bool> out(m.triangleCount(), false);
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int k = 0; k < 3; ++k) out[t] = out[t] || (m.positions[m.indices[3 * t + k]] - p).norm() <= radius;
  return out;
}

// Closed and consistently oriented once coincident vertices are merged (seams welded): a crack or
// a T-junction leaves an edge with one triangle.
std::string weldedClosedDefect(const TriangleMesh& m) {
  TriangleMesh welded = m;
  const std::vector<uint32_t> weld = findCoincidentVertices(m);
  for (uint32_t& i : welded.indices) i = weld[i];
  return findClosedMeshDefect(welded);
}

class RegionRefinementLevels : public ::testing::TestWithParam<std::tuple<int, RefinementScheme>> {};

TEST_P(RegionRefinementLevels, RefinedPatchOfAClosedMeshStaysClosedAndOriented) {
  const auto [levels, scheme] = GetParam();
  const TriangleMesh sphere = icosphere(2);
  const std::vector<bool> patch = trianglesNear(sphere, sphere.positions[0], 0.45f);
  const TriangleMesh refined = refineMesh(sphere, patch, scheme, levels);
  EXPECT_GT(refined.triangleCount(), sphere.triangleCount());
  EXPECT_EQ(findMeshDefect(refined), "");
  EXPECT_EQ(findClosedMeshDefect(refined), "") << "every edge on exactly two triangles, no T-junction";
  const double before = signedVolume(sphere), after = signedVolume(refined);
  if (scheme == RefinementScheme::Linear) {
    EXPECT_NEAR(after, before, 1e-6 * before) << "midpoints keep the polyhedron";
  } else {
    EXPECT_GT(after, 0.97 * before) << "Loop shrinks a convex patch a little";
    EXPECT_LT(after, before);
  }
}

TEST_P(RegionRefinementLevels, SeamsSplitOnBothSidesSoTheWeldedCubeStaysClosed) {
  const auto [levels, scheme] = GetParam();
  const TriangleMesh cube = seamedCube();
  std::vector<bool> topFace(cube.triangleCount(), false);
  topFace[4] = topFace[5] = true;  // +y face
  const TriangleMesh refined = refineMesh(cube, topFace, scheme, levels);
  EXPECT_EQ(findMeshDefect(refined), "");
  EXPECT_EQ(weldedClosedDefect(refined), "");
  EXPECT_NEAR(signedVolume(refined), 1.0, 1e-6) << "seams and the face border stay linear: the cube keeps its shape";
  for (size_t v = 0; v < refined.vertexCount(); ++v) {
    const Vec3& p = refined.positions[v];
    EXPECT_NEAR(p.cwiseAbs().maxCoeff(), 0.5f, 1e-6f) << "vertex " << v << " left the cube's surface";
  }
}

INSTANTIATE_TEST_SUITE_P(OneToThreeLevels, RegionRefinementLevels,
                         ::testing::Combine(::testing::Values(1, 2, 3),
                                            ::testing::Values(RefinementScheme::Linear, RefinementScheme::Loop)));

TEST(RegionRefinement, TriangleCountsFollowFourPerLevelInsideAndAFanOnTheBorder) {
  const TriangleMesh ico = icosahedron();
  std::vector<bool> fan(ico.triangleCount(), false);
  for (size_t t = 0; t < 5; ++t) fan[t] = true;  // the five triangles around vertex 0
  for (int levels : {1, 2, 3}) {
    const TriangleMesh refined = refineMesh(ico, fan, RefinementScheme::Loop, levels);
    // 10 untouched, 5 * 4^L refined, and each of the 5 border neighbours fanned into 2^L.
    const size_t expected = 10 + 5 * (size_t(1) << (2 * levels)) + 5 * (size_t(1) << levels);
    EXPECT_EQ(refined.triangleCount(), expected) << levels << " levels";
  }
  const RegionRefinement once = refineRegionOnce(ico, fan, RefinementScheme::Linear);
  EXPECT_EQ(once.refinedParents, 5u) << "a fan needs no closure growth";
  EXPECT_EQ(std::count(once.refined.begin(), once.refined.end(), true), 20);
  EXPECT_EQ(once.stencils.size(), 12u + 10u) << "5 spokes and 5 rim edges get a midpoint";
}

TEST(RegionRefinement, ClosureGrowsOverTrianglesWithTwoSplitEdges) {
  const TriangleMesh ico = icosahedron();
  std::vector<bool> two(ico.triangleCount(), false);
  two[0] = two[2] = true;  // around vertex 0, with triangle 1 between them sharing an edge with each
  const RegionRefinement r = refineRegionOnce(ico, two, RefinementScheme::Linear);
  EXPECT_EQ(r.refinedParents, 3u);
  TriangleMesh refined;
  refined.positions = applyStencils(r.stencils, ico.positions);
  refined.indices = r.indices;
  EXPECT_EQ(findClosedMeshDefect(refined), "");
}

TEST(RegionRefinement, LinearKeepsAPlanarPatchOnItsPlaneWithItsAreaAndItsVertices) {
  const TriangleMesh plane = grid(8);
  const std::vector<bool> patch = trianglesNear(plane, Vec3(0.4f, 0.55f, 0.0f), 0.3f);
  for (int levels : {1, 3}) {
    const TriangleMesh refined = refineMesh(plane, patch, RefinementScheme::Linear, levels);
    for (const Vec3& p : refined.positions) ASSERT_EQ(p.z(), 0.0f);
    EXPECT_NEAR(test::meshArea(refined), 1.0, 1e-6);
    for (size_t v = 0; v < plane.vertexCount(); ++v) ASSERT_EQ(refined.positions[v], plane.positions[v]) << v;
    // The uvs of this grid are its xy: linear refinement keeps that.
    for (size_t v = 0; v < refined.vertexCount(); ++v)
      ASSERT_LT((refined.uvs[v] - refined.positions[v].head<2>()).norm(), 1e-6f) << v;
  }
}

TEST(RegionRefinement, LoopOnTheWholeIcosahedronMatchesItsClosedFormMasks) {
  const TriangleMesh ico = icosahedron();
  const RegionRefinement r = refineRegionOnce(ico, std::vector<bool>(20, true), RefinementScheme::Loop);
  const std::vector<Vec3> p = applyStencils(r.stencils, ico.positions);
  ASSERT_EQ(p.size(), 42u);
  // Even: (1 - 5 beta) v + beta sum of 5 neighbours, beta = 3/40; the neighbours sum to sqrt(5) v.
  const double beta = 3.0 / 40.0, s5 = std::sqrt(5.0);
  const double even = 1.0 - 5.0 * beta + s5 * beta;
  // Odd: 3/8 (a + b) + 1/8 (c + d); |a + b|^2 = 2 + 2/sqrt(5), |c + d|^2 = 2 - 2/sqrt(5), same direction.
  const double odd = 0.375 * std::sqrt(2.0 + 2.0 / s5) + 0.125 * std::sqrt(2.0 - 2.0 / s5);
  for (size_t v = 0; v < 12; ++v) EXPECT_NEAR(p[v].norm(), even, 1e-6) << v;
  for (size_t v = 12; v < 42; ++v) EXPECT_NEAR(p[v].norm(), odd, 1e-6) << v;
  for (size_t v = 0; v < 12; ++v) {
    const uint32_t begin = r.stencils.offsets[v];
    ASSERT_EQ(r.stencils.offsets[v + 1] - begin, 6u);
    EXPECT_FLOAT_EQ(r.stencils.weights[begin], 0.625f);
  }
}

// Largest angle between the normals of two triangles on one edge, over edges whose two
// triangles are both children of refined triangles and whose ends touch no other triangle.
float largestInteriorCrease(const std::vector<Vec3>& p, const RegionRefinement& r) {
  std::vector<bool> nearBorder(p.size(), false);
  for (size_t t = 0; t < r.refined.size(); ++t)
    if (!r.refined[t])
      for (int k = 0; k < 3; ++k) nearBorder[r.indices[3 * t + k]] = true;
  std::map<std::pair<uint32_t, uint32_t>, std::vector<Vec3>> faces;
  for (size_t t = 0; t < r.refined.size(); ++t) {
    if (!r.refined[t]) continue;
    const uint32_t* v = &r.indices[3 * t];
    const Vec3 n = (p[v[1]] - p[v[0]]).cross(p[v[2]] - p[v[0]]).normalized();
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = std::min(v[k], v[(k + 1) % 3]), b = std::max(v[k], v[(k + 1) % 3]);
      if (!nearBorder[a] && !nearBorder[b]) faces[{a, b}].push_back(n);
    }
  }
  float largest = 0.0f;
  for (const auto& [edge, normals] : faces)
    if (normals.size() == 2) largest = std::max(largest, std::acos(std::clamp(normals[0].dot(normals[1]), -1.0f, 1.0f)));
  return largest;
}

TEST(RegionRefinement, LoopSmoothsTheInsideOfAPatchAndLeavesTheRestBitwise) {
  const TriangleMesh sphere = icosphere(1);
  const std::vector<bool> patch = trianglesNear(sphere, sphere.positions[0], 0.8f);
  const RegionRefinement linear = refineRegionOnce(sphere, patch, RefinementScheme::Linear);
  const RegionRefinement loop = refineRegionOnce(sphere, patch, RefinementScheme::Loop);
  ASSERT_EQ(linear.indices, loop.indices) << "same topology, other weights";
  const std::vector<Vec3> linearP = applyStencils(linear.stencils, sphere.positions);
  const std::vector<Vec3> loopP = applyStencils(loop.stencils, sphere.positions);
  const float linearCrease = largestInteriorCrease(linearP, linear);
  const float loopCrease = largestInteriorCrease(loopP, loop);
  EXPECT_GT(linearCrease, 0.3f) << "the icosphere's own creases stay under linear refinement";
  EXPECT_LT(loopCrease, 0.6f * linearCrease) << "Loop smooths them";

  TriangleMesh loopMesh;
  loopMesh.positions = loopP;
  loopMesh.indices = loop.indices;
  TriangleMesh linearMesh = loopMesh;
  linearMesh.positions = linearP;
  EXPECT_NEAR(test::meshArea(loopMesh), test::meshArea(linearMesh), 0.03 * test::meshArea(linearMesh));

  // Vertices on no refined triangle are bitwise where they were.
  std::vector<bool> inRegion(sphere.vertexCount(), false);
  for (size_t t = 0; t < loop.refined.size(); ++t)
    if (loop.refined[t])
      for (int k = 0; k < 3; ++k)
        if (loop.indices[3 * t + k] < sphere.vertexCount()) inRegion[loop.indices[3 * t + k]] = true;
  size_t moved = 0;
  for (size_t v = 0; v < sphere.vertexCount(); ++v) {
    if (!inRegion[v]) {
      ASSERT_EQ(loopP[v], sphere.positions[v]) << v;
    } else if (loopP[v] != sphere.positions[v]) {
      ++moved;
    }
  }
  EXPECT_GT(moved, 3u) << "interior old vertices follow the even mask";
  for (size_t row = 0; row < loop.stencils.size(); ++row) {
    float sum = 0.0f;
    for (uint32_t k = loop.stencils.offsets[row]; k < loop.stencils.offsets[row + 1]; ++k) sum += loop.stencils.weights[k];
    ASSERT_NEAR(sum, 1.0f, 1e-6f) << "row " << row;
  }
}

GltfPrimitive gridPrimitive() {
  GltfPrimitive p;
  p.mesh = grid(6);
  // A target that is a linear function of the position: zero only at the origin.
  SparseDelta target;
  for (uint32_t v = 0; v < p.mesh.vertexCount(); ++v) {
    const Vec3& x = p.mesh.positions[v];
    const Vec3 d(0.1f * x.x() + 0.05f * x.y(), 0.0f, 0.3f * x.y());
    if (d == Vec3::Zero()) continue;
    target.vertices.push_back(v);
    target.deltas.push_back(d);
  }
  p.targets = {target, SparseDelta{}};
  // Even vertices on joints 0-3, odd ones on 2-5: midpoints combine six joints and keep four.
  for (uint32_t v = 0; v < p.mesh.vertexCount(); ++v) {
    p.skinJoints.push_back(v % 2 == 0 ? std::array<uint16_t, 4>{0, 1, 2, 3} : std::array<uint16_t, 4>{2, 3, 4, 5});
    p.skinWeights.emplace_back(0.4f, 0.3f, 0.2f, 0.1f);
  }
  p.skin = 0;
  p.weldMap = findCoincidentVertices(p.mesh);
  computeSmoothNormals(p.mesh, p.weldMap);
  return p;
}

TEST(RegionRefinementPrimitive, LinearInterpolatesMorphTargetsAndKeepsOriginalVertices) {
  const GltfPrimitive p = gridPrimitive();
  const std::vector<bool> patch = trianglesNear(p.mesh, Vec3(0.0f, 0.0f, 0.0f), 0.4f);  // touches the origin
  const GltfPrimitive r = refinePrimitive(p, patch, RefinementScheme::Linear, 2);
  ASSERT_GT(r.mesh.vertexCount(), p.mesh.vertexCount());
  for (size_t v = 0; v < p.mesh.vertexCount(); ++v) ASSERT_EQ(r.mesh.positions[v], p.mesh.positions[v]) << v;
  const SparseDelta& t = r.targets[0];
  ASSERT_EQ(t.vertices.size(), r.mesh.vertexCount() - 1) << "every vertex but the origin moves";
  for (size_t i = 0; i < t.vertices.size(); ++i) {
    const Vec3& x = r.mesh.positions[t.vertices[i]];
    ASSERT_NE(x, Vec3::Zero());
    EXPECT_LT((t.deltas[i] - Vec3(0.1f * x.x() + 0.05f * x.y(), 0.0f, 0.3f * x.y())).norm(), 1e-6f) << i;
    if (i > 0) {
      ASSERT_LT(t.vertices[i - 1], t.vertices[i]);
    }
  }
  EXPECT_TRUE(r.targets[1].vertices.empty());
  EXPECT_EQ(r.weldMap, findCoincidentVertices(r.mesh));
  ASSERT_EQ(r.mesh.normals.size(), r.mesh.vertexCount());
  for (const Vec3& n : r.mesh.normals) EXPECT_EQ(n, Vec3(Vec3::UnitZ()));
}

// A primitive made of a coarse icosphere (level 1, on the unit sphere), its smooth normals as the
// loader computes them.
GltfPrimitive spherePrimitive() {
  GltfPrimitive p;
  p.name = "sphere/skin";
  p.mesh = icosphere(1);
  p.weldMap = findCoincidentVertices(p.mesh);
  computeSmoothNormals(p.mesh, p.weldMap);
  return p;
}

// Largest angle (radians) between a vertex normal of `m` and the sphere's true normal there, over
// the vertices from `first` on.
float worstSphereNormalError(const TriangleMesh& m, size_t first) {
  float worst = 0.0f;
  for (size_t v = first; v < m.vertexCount(); ++v)
    worst = std::max(worst, std::acos(std::clamp(m.normals[v].dot(m.positions[v].normalized()), -1.0f, 1.0f)));
  return worst;
}

TEST(RegionRefinementPrimitive, ALinearSplitShadesAsTheSurfaceItSplitNotAsFacets) {
  const GltfPrimitive coarse = spherePrimitive();
  const std::vector<bool> patch = trianglesNear(coarse.mesh, coarse.mesh.positions[0], 0.7f);
  const GltfPrimitive once = refinePrimitive(coarse, patch, RefinementScheme::Linear, 2);
  const size_t original = coarse.mesh.vertexCount();
  ASSERT_EQ(once.normalTriangles, coarse.mesh.indices);
  ASSERT_EQ(once.normalSources.size(), once.mesh.vertexCount());
  // Original vertices keep the unrefined mesh's normals, also on the patch's border where small
  // split triangles meet large ones; every added vertex blends original vertices' normals
  // (composed over the two levels) with its own interpolation weights.
  for (size_t v = 0; v < once.mesh.vertexCount(); ++v) {
    const uint32_t begin = once.normalSources.offsets[v], end = once.normalSources.offsets[v + 1];
    if (v < original) {
      EXPECT_EQ(begin, end) << v;
      EXPECT_LT((once.mesh.normals[v] - coarse.mesh.normals[v]).norm(), 1e-6f) << v;
      continue;
    }
    ASSERT_GT(end, begin) << v;
    float weights = 0.0f;
    Vec3 blend = Vec3::Zero(), position = Vec3::Zero();
    for (uint32_t k = begin; k < end; ++k) {
      ASSERT_LT(once.normalSources.sources[k], original);
      weights += once.normalSources.weights[k];
      blend += once.normalSources.weights[k] * coarse.mesh.normals[once.normalSources.sources[k]];
      position += once.normalSources.weights[k] * coarse.mesh.positions[once.normalSources.sources[k]];
    }
    EXPECT_NEAR(weights, 1.0f, 1e-6f);
    EXPECT_LT((position - once.mesh.positions[v]).norm(), 1e-6f) << "the row is the vertex's interpolation";
    EXPECT_LT((once.mesh.normals[v] - blend.normalized()).norm(), 1e-5f) << v;
  }
  // Against the true sphere: normals computed from the split triangles are facets, off by up to
  // half a coarse triangle's angle.
  TriangleMesh faceted = once.mesh;
  computeSmoothNormals(faceted, once.weldMap);
  EXPECT_LT(worstSphereNormalError(once.mesh, original), 0.5f * worstSphereNormalError(faceted, original));
  // A second linear refinement over the first composes: its rows still name original vertices.
  const GltfPrimitive twice = refinePrimitive(once, trianglesNear(once.mesh, once.mesh.positions[0], 0.3f),
                                              RefinementScheme::Linear, 1);
  ASSERT_EQ(twice.normalTriangles, coarse.mesh.indices);
  ASSERT_EQ(twice.normalSources.size(), twice.mesh.vertexCount());
  for (uint32_t source : twice.normalSources.sources) EXPECT_LT(source, original);
  EXPECT_LT(worstSphereNormalError(twice.mesh, original), 0.5f * worstSphereNormalError(faceted, original));
  // Loop refinement's surface is smooth: its normals are its own.
  const GltfPrimitive loopOnly = refinePrimitive(coarse, patch, RefinementScheme::Loop, 1);
  EXPECT_TRUE(loopOnly.normalTriangles.empty());
  EXPECT_EQ(loopOnly.normalSources.size(), 0u);
}

TEST(RegionRefinementPrimitive, ARefinedPrimitiveShadedAfterItMovesKeepsBlendingItsOriginalNormals) {
  GltfPrimitive refined = refinePrimitive(spherePrimitive(), std::vector<bool>(80, true), RefinementScheme::Linear, 1);
  // Squash the sphere as a pose would (a linear map keeps added vertices on the original triangles).
  TriangleMesh posed = refined.mesh;
  for (Vec3& p : posed.positions) p.z() *= 0.5f;
  computePrimitiveNormals(posed, refined);
  TriangleMesh coarsePosed = posed;
  coarsePosed.indices = refined.normalTriangles;
  computeSmoothNormals(coarsePosed, refined.weldMap);
  for (size_t v = 0; v < 42; ++v) EXPECT_LT((posed.normals[v] - coarsePosed.normals[v]).norm(), 1e-6f) << v;
  for (size_t v = 42; v < posed.vertexCount(); ++v) {
    Vec3 blend = Vec3::Zero();
    for (uint32_t k = refined.normalSources.offsets[v]; k < refined.normalSources.offsets[v + 1]; ++k)
      blend += refined.normalSources.weights[k] * coarsePosed.normals[refined.normalSources.sources[k]];
    EXPECT_LT((posed.normals[v] - blend.normalized()).norm(), 1e-5f) << v;
  }
  refined.normalSources = VertexStencils();  // rows missing for the vertices
  EXPECT_THROW(computePrimitiveNormals(posed, refined), std::invalid_argument);
}

TEST(RegionRefinementPrimitive, SkinInfluencesStayFourNormalisedAndLargestFirst) {
  const GltfPrimitive p = gridPrimitive();
  const std::vector<bool> patch = trianglesNear(p.mesh, Vec3(0.5f, 0.5f, 0.0f), 0.3f);
  const GltfPrimitive r = refinePrimitive(p, patch, RefinementScheme::Loop, 2);
  ASSERT_EQ(r.skinJoints.size(), r.mesh.vertexCount());
  ASSERT_EQ(r.skinWeights.size(), r.mesh.vertexCount());
  size_t pruned = 0;
  for (size_t v = 0; v < r.mesh.vertexCount(); ++v) {
    const Vec4& w = r.skinWeights[v];
    EXPECT_NEAR(w.sum(), 1.0f, 1e-6f) << v;
    EXPECT_GE(w.minCoeff(), 0.0f) << v;
    for (int c = 0; c < 3; ++c) EXPECT_GE(w[c], w[c + 1]) << v;
    if (v >= p.mesh.vertexCount() && w[0] != 0.4f) ++pruned;
  }
  EXPECT_GT(pruned, 0u) << "some new vertices mix both joint sets";
  // A midpoint of an even and an odd vertex: joint 2 (0.3), joints 0 and 3 (0.2), joint 1 (0.15).
  const RegionRefinement once = refineRegionOnce(p.mesh, patch, RefinementScheme::Linear);
  std::vector<std::array<uint16_t, 4>> joints = p.skinJoints;
  std::vector<Vec4> weights = p.skinWeights;
  applyStencils(once.stencils, joints, weights);
  bool checked = false;
  for (size_t v = p.mesh.vertexCount(); v < once.stencils.size() && !checked; ++v) {
    const uint32_t k = once.stencils.offsets[v];
    if (once.stencils.sources[k] % 2 == once.stencils.sources[k + 1] % 2) continue;
    // Joints 0 and 3 tie up to float rounding of the input weights: either order.
    EXPECT_EQ(joints[v][0], 2);
    EXPECT_EQ(std::min(joints[v][1], joints[v][2]), 0);
    EXPECT_EQ(std::max(joints[v][1], joints[v][2]), 3);
    EXPECT_EQ(joints[v][3], 1);
    EXPECT_LT((weights[v] - Vec4(0.3f, 0.2f, 0.2f, 0.15f) / 0.85f).norm(), 1e-6f);
    checked = true;
  }
  EXPECT_TRUE(checked);
}

TEST(RegionRefinement, ZeroLevelsOrAnEmptySelectionChangeNothingAndBadSelectionsThrow) {
  const TriangleMesh sphere = icosphere(1);
  const TriangleMesh same = refineMesh(sphere, trianglesNear(sphere, sphere.positions[0], 0.5f), RefinementScheme::Loop, 0);
  EXPECT_EQ(same.positions, sphere.positions);
  EXPECT_EQ(same.indices, sphere.indices);
  const TriangleMesh none = refineMesh(sphere, std::vector<bool>(sphere.triangleCount(), false), RefinementScheme::Loop, 2);
  EXPECT_EQ(none.indices, sphere.indices);
  EXPECT_THROW(refineRegionOnce(sphere, std::vector<bool>(3, true), RefinementScheme::Loop), std::invalid_argument);
  EXPECT_THROW(refineMesh(sphere, std::vector<bool>(sphere.triangleCount(), true), RefinementScheme::Loop, -1),
               std::invalid_argument);
}

}  // namespace region_refinement_test
}  // namespace lacrima
