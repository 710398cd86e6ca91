// Simulated flesh in shots: the "flesh" key builds a tetrahedral volume under skin
// regions and moves the rendered skin with it. The flesh lags a sudden nod of the head
// and settles on the rig's pose; a still face is left bitwise as the rig made it; the skin
// outside the regions never moves; a frame built alone is the frame built in sequence; and the
// key's mistakes get one clear message each.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>

#include "lacrima/flesh/flesh_state_cache.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/flesh_bench.hpp"
#include "support/test_directory.hpp"

#include "shot_support.hpp"

namespace lacrima {
namespace flesh_shot_test {

using test::ScopedCacheHome;

using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;

// The right cheek of the ICT face as loaded (no head pose: the asset's own coordinates), very soft
// (100 Pa) so that this small region, held by the rig all round and beneath, lags a rigid nod by
// over half a millimetre; at 1 kPa it lags 0.02 mm.
const std::string kFlesh =
    R"("flesh": [{"asset": "face", "part": "M_Face", "regions": [{"center": [-0.05, 0.0, 0.09], "radius": 0.015}],
       "depth": 0.008, "tetSize": 0.004, "youngsModulus": 100}])";
// The head nods 8 degrees down over two frames (1-3) and holds: the cheek's flesh lags and catches up.
const std::string kNod = R"("rig": {"preset": "ict"}, "joints": {"head.rx": {"keys": [[1, 0], [3, 8], [24, 8]]}})";
constexpr int kFrames = 24;

const TriangleMesh& faceSkin(const Frame& frame) {
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == "face/ICTFace/M_Face") return m.mesh;
  ADD_FAILURE() << "no face mesh";
  return frame.meshes.front().mesh;
}

// The largest distance between the same vertex in two poses of the skin, and how many moved.
struct SkinDifference {
  float largest = 0.0f;
  size_t moved = 0;
};

SkinDifference difference(const TriangleMesh& a, const TriangleMesh& b) {
  SkinDifference d;
  for (size_t v = 0; v < a.positions.size(); ++v) {
    const float distance = (a.positions[v] - b.positions[v]).norm();
    d.largest = std::max(d.largest, distance);
    d.moved += distance > 0.0f ? 1 : 0;
  }
  return d;
}

Shot nodShot(bool withFlesh, const std::string& name) {
  return loadShot(writeShot(name, ictFaceShot(withFlesh ? kFlesh : "", "", kNod, kFrames)));
}

TEST(FleshShot, TheCheekLagsANodAndSettlesOnTheRigsPose) {
  const Shot flesh = nodShot(true, "flesh_nod.json"), rig = nodShot(false, "flesh_nod_rig.json");
  ASSERT_EQ(flesh.flesh.size(), 1u);
  FrameBuilder withFlesh(flesh), rigOnly(rig);
  std::vector<float> offsets;
  for (int f = 1; f <= kFrames; ++f)
    offsets.push_back(difference(faceSkin(withFlesh.build(f)), faceSkin(rigOnly.build(f))).largest);
  const float peak = *std::max_element(offsets.begin(), offsets.begin() + 6);
  EXPECT_EQ(offsets[0], 0.0f);  // the first frame: at rest on the rig's pose
  EXPECT_GT(peak, 1e-4f) << "the flesh should lag the nod by a tenth of a millimetre or more";
  EXPECT_LT(peak, 3e-3f);
  EXPECT_LT(offsets.back(), 0.05f * peak) << "the flesh should have settled three quarters of a second later";
  std::printf("cheek offset from the rig's pose, mm, frames 1-%d:", kFrames);
  for (float o : offsets) std::printf(" %.3f", 1e3 * o);
  std::printf("\n");
}

TEST(FleshShot, OnlyTheSkinOverTheVolumeMoves) {
  const Shot flesh = nodShot(true, "flesh_nod_region.json"), rig = nodShot(false, "flesh_nod_region_rig.json");
  const TriangleMesh a = faceSkin(buildFrame(flesh, 3)), b = faceSkin(buildFrame(rig, 3));
  const TriangleMesh first = faceSkin(buildFrame(rig, 1));  // the regions are found on this pose
  const Vec3 center(-0.05f, 0.0f, 0.09f);
  size_t moved = 0;
  for (size_t v = 0; v < a.positions.size(); ++v) {
    if (a.positions[v] == b.positions[v]) continue;
    EXPECT_LT((first.positions[v] - center).norm(), 0.015f) << v;
    ++moved;
  }
  EXPECT_GT(moved, 10u);
}

TEST(FleshShot, AStillFaceIsLeftBitwiseAsTheRigMadeIt) {
  const std::string still = R"("rig": {"preset": "ict"}, "joints": {"head.rx": 8})";
  const Shot flesh = loadShot(writeShot("flesh_still.json", ictFaceShot(kFlesh, "", still, 6)));
  const Shot rig = loadShot(writeShot("flesh_still_rig.json", ictFaceShot("", "", still, 6)));
  FrameBuilder withFlesh(flesh);
  for (int f : {1, 6}) EXPECT_EQ(difference(faceSkin(withFlesh.build(f)), faceSkin(buildFrame(rig, f))).moved, 0u) << f;
}

TEST(FleshShot, AFrameBuiltAloneIsTheFrameBuiltInSequenceWithAnyThreadCount) {
  // States filed by the sequence are not where the frame built alone looks: it simulates from the start.
  const std::filesystem::path home = test::testDirectory("flesh_cache", true);
  const ScopedCacheHome cache(home / "sequence");
  const Shot shot = nodShot(true, "flesh_sequence.json");
  FrameBuilder sequence(shot);
  TriangleMesh inSequence;
  for (int f = 1; f <= 5; ++f) inSequence = faceSkin(sequence.build(f));
  const ScopedCacheHome aloneCache(home / "alone");
  TriangleMesh single;
  tbb::task_arena oneThread(1);
  oneThread.execute([&] { single = faceSkin(buildFrame(shot, 5)); });
  EXPECT_EQ(difference(inSequence, single).moved, 0u);
  // Asked again for an earlier frame, the simulation starts over and gives it bitwise again.
  const TriangleMesh again = faceSkin(sequence.build(3));
  EXPECT_EQ(difference(again, faceSkin(buildFrame(shot, 3))).moved, 0u);
}

// The state filed at a whole frame (frame 1 + index: the nod shot has no shutter) of the shot's
// one flesh in the cache folder, with its key from the file's name.
std::pair<std::filesystem::path, uint64_t> filedState(const std::filesystem::path& cacheHome, long index) {
  const std::string prefix = fmt::format("frame{:05d}-", index);
  for (const auto& entry : std::filesystem::directory_iterator(cacheHome / "lacrima/flesh/states")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) return {entry.path(), std::stoull(name.substr(prefix.size(), 16), nullptr, 16)};
  }
  ADD_FAILURE() << "no state filed for frame index " << index;
  return {};
}

TEST(FleshShot, AFrameBuiltAloneContinuesFromTheStateFiledAtTheFrameBefore) {
  const std::filesystem::path home = test::testDirectory("flesh_cache", true);
  const ScopedCacheHome cache(home);
  const Shot sequence = nodShot(true, "flesh_filed_sequence.json");
  FrameBuilder builder(sequence);
  TriangleMesh inSequence;
  for (int f = 1; f <= 5; ++f) inSequence = faceSkin(builder.build(f));
  // Frame 5 alone continues from the state of frame 5 itself (index 4): moved by a millimetre
  // there, the frame built alone moves with it, so it was read; put back, the frame is bitwise the
  // sequence's.
  const auto [file, key] = filedState(home, 4);
  std::optional<flesh::FleshState> state = flesh::readFleshState(file, key, sequence.flesh[0].tetVolume->mesh.nodes.size());
  ASSERT_TRUE(state);
  flesh::FleshState moved = *state;
  for (size_t n = 0; n < moved.positions.size(); ++n)
    if (!sequence.flesh[0].tetVolume->kinematic[n]) moved.positions[n].x() += 1e-3;
  flesh::writeFleshState(file, moved, key);
  EXPECT_GT(difference(inSequence, faceSkin(buildFrame(sequence, 5))).largest, 5e-4f);
  flesh::writeFleshState(file, *state, key);
  EXPECT_EQ(difference(inSequence, faceSkin(buildFrame(sequence, 5))).moved, 0u);
  // A corrupt state is passed over (the one before it serves).
  std::ofstream(file, std::ios::binary | std::ios::trunc) << "garbage";
  EXPECT_EQ(difference(inSequence, faceSkin(buildFrame(sequence, 5))).moved, 0u);
}

TEST(FleshShot, TheFleshBenchSimulatesEveryStepAndFilesNoState) {
  const std::filesystem::path home = test::testDirectory("flesh_cache", true);
  const ScopedCacheHome cache(home);
  const Shot shot = nodShot(true, "flesh_bench.json");
  const FleshBenchResult result = measureFleshFrames(shot, 0.005, 4);
  ASSERT_EQ(result.frames.size(), 3u);  // frames 2-4, each from the one before
  EXPECT_EQ(result.frames.front().frame, 2);
  EXPECT_EQ(result.steps, 3 * shot.flesh[0].substeps);
  EXPECT_GE(result.newtonIterations, result.steps);
  EXPECT_GT(result.conjugateGradientIterations, result.newtonIterations);
  EXPECT_GT(result.tetrahedra, 100u);
  EXPECT_GT(result.freeNodes, 0u);
  EXPECT_LT(result.freeNodes, result.nodes);
  EXPECT_FALSE(std::filesystem::exists(home / "lacrima/flesh/states"));
  EXPECT_THROW(measureFleshFrames(loadShot(writeShot("flesh_bench_none.json", ictFaceShot("", "", kNod, kFrames))), 0.005, 4),
               InputError);
}

TEST(FleshShot, MistakesInTheFleshKeyGetOneClearMessage) {
  const auto shotWith = [](const std::string& from, const std::string& to) {
    return ictFaceShot(test::replaced(kFlesh, from, to), "", kNod, kFrames);
  };
  expectSingleError("flesh_bad_radius.json", shotWith(R"("radius": 0.015)", R"("radius": -0.01)"),
                    "/flesh/0/regions/0/radius: expected a number > 0, found -0.01");
  expectSingleError("flesh_bad_poisson.json", shotWith(R"("depth": 0.008)", R"("depth": 0.008, "poisson": 0.5)"),
                    "/flesh/0/poisson: expected a number in (-1, 0.5), found 0.5");
  expectSingleError("flesh_bad_material.json", shotWith(R"("depth": 0.008)", R"("depth": 0.008, "material": "corotated")"),
                    "/flesh/0/material: unknown flesh material 'corotated' (expected one of 'fixedCorotated', "
                    "'stVenantKirchhoff')");
  expectSingleError("flesh_no_regions.json",
                    shotWith(R"("regions": [{"center": [-0.05, 0.0, 0.09], "radius": 0.015}],)", ""),
                    "/flesh/0: missing required key 'regions' (an array of regions {\"center\", \"radius\"} of the "
                    "skin to simulate the flesh under)");
  expectSingleError("flesh_tiny_region.json", shotWith(R"("radius": 0.015)", R"("radius": 0.0001)"),
                    "/flesh/0/regions: no triangle of the skin lies wholly within the regions: give larger radii");
  expectSingleError("flesh_unknown_key.json", shotWith(R"("depth": 0.008)", R"("depth": 0.008, "stiffness": 3)"),
                    "/flesh/0/stiffness: unknown key 'stiffness' (allowed here: asset, part, regions, depth, tetSize, "
                    "youngsModulus, poisson, density, damping, substeps, material, integrator)");
  expectSingleError("flesh_too_deep.json", shotWith(R"("depth": 0.008)", R"("depth": 0.2)"),
                    "/flesh/0: the flesh volume cannot be built: the flesh depth 0.2 m is too deep for the skin's "
                    "curvature near (-0.0452, -0.0005, 0.0936) m (it lies 0.0329 m from the centre of the sphere the "
                    "region's skin fits); give a smaller depth");
}

}  // namespace flesh_shot_test
}  // namespace lacrima
