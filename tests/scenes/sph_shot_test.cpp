// The shot format's SPH liquids (docs/shot-format.md "sph", scenes/src/frame/sph_liquid.hpp): the
// surfaced liquid in the frame (closed, in its material, blurred by the particles' velocities, at
// rest on its collider), any frame built alone equal to the same frame built in a sequence or
// after a later one, and bad input reported at its JSON path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"
#include "lacrima/sph/surface_tension.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace sph_shot_test {

using test::expectSingleError;
using test::replaced;
using test::writeShot;

// A 1.5 mm drop of 0.25 mm particles (about 110) released 2.6 mm above a table at 0.3 m/s, at
// 240 fps from frame 1; the shot renders frames 2-4 (or from `firstFrame`).
std::string dropShot(const std::string& sphExtra = "", int firstFrame = 2) {
  return R"({
  "version": 1,
  "frames": {"start": )" + std::to_string(firstFrame) + R"(, "end": 4, "fps": 240},
  "output": "out.####.exr",
  "render": {"width": 8, "height": 8, "spp": 1},
  "camera": {"position": [0, 0.01, 0.03], "lookAt": [0, 0, 0], "fov": 30, "shutter": {"open": -0.25, "close": 0.25}},
  "materials": {"table": {"type": "diffuse"}, "water": {"type": "water"}},
  "shapes": [{"type": "rectangle", "center": [0, 0, 0], "size": [0.02, 0.02], "normal": [0, 1, 0], "material": "table"}],
  "sph": [{"material": "water", "start": 1, "particleRadius": 0.00025,
           "drops": [{"center": [0, 0.0041, 0], "radius": 0.0015, "velocity": [0, -0.3, 0]}],
           "colliders": [{"shape": 0}], "surfaceTension": 20)" + sphExtra + R"(}]
})";
}

const MeshInstance* liquidMesh(const Frame& frame) {
  const auto it = std::find_if(frame.meshes.begin(), frame.meshes.end(),
                               [](const MeshInstance& m) { return m.mesh.name == "sph 0"; });
  return it == frame.meshes.end() ? nullptr : &*it;
}
// A pointer into a temporary Frame would dangle (an ASan find of 2026-12-04): keep the frame.
const MeshInstance* liquidMesh(Frame&&) = delete;

TEST(SphShot, TheSurfacedDropIsAClosedWaterMeshBlurredByItsMotionAboveTheTable) {
  const Shot shot = loadShot(writeShot("sph_drop.json", dropShot()));
  ASSERT_EQ(shot.sph.size(), 1u);
  FrameBuilder builder(shot);
  const Frame frame = builder.build(2);
  const MeshInstance* liquid = liquidMesh(frame);
  ASSERT_NE(liquid, nullptr);
  EXPECT_EQ(frame.materials[liquid->materialId].name, "water");
  EXPECT_GT(liquid->mesh.triangleCount(), 100u);
  EXPECT_EQ(countBoundaryEdges(liquid->mesh), 0u) << "a water surface must bound its volume";
  ASSERT_EQ(liquid->positionsAtClose.size(), liquid->mesh.positions.size());
  // Falling at 0.33 m/s at shutter open, over half a frame (1/480 s): the surface moves down ~0.7 mm.
  float meanDrop = 0.0f, lowest = 1.0f;
  for (size_t i = 0; i < liquid->mesh.positions.size(); ++i) {
    meanDrop += liquid->mesh.positions[i].y() - liquid->positionsAtClose[i].y();
    lowest = std::min(lowest, liquid->mesh.positions[i].y());
  }
  meanDrop /= float(liquid->mesh.positions.size());
  EXPECT_GT(meanDrop, 0.5e-3f);
  EXPECT_LT(meanDrop, 0.9e-3f);
  // Later the drop lies on the table: nothing of it below the table's boundary layer.
  const Frame later = builder.build(4);
  const MeshInstance* landed = liquidMesh(later);
  ASSERT_NE(landed, nullptr);
  for (const Vec3& p : landed->mesh.positions) ASSERT_GT(p.y(), -0.5e-3f);
}

TEST(SphShot, AFrameBuiltAloneEqualsTheSameFrameInASequenceOrAfterALaterOne) {
  // Each in a cache of its own: the frame built alone must not find the sequence's checkpoints.
  const std::filesystem::path home = test::testDirectory("sph_alone_cache", true);
  std::optional<test::ScopedCacheHome> cache(std::in_place, home / "sequence");
  const Shot shot = loadShot(writeShot("sph_sequence.json", dropShot()));
  FrameBuilder sequence(shot);
  sequence.build(2);
  const Frame inSequence = sequence.build(3);
  cache.reset();
  cache.emplace(home / "alone");
  FrameBuilder alone(shot);
  const Frame builtAlone = alone.build(3);
  ASSERT_NE(liquidMesh(inSequence), nullptr);
  ASSERT_NE(liquidMesh(builtAlone), nullptr);
  EXPECT_EQ(liquidMesh(inSequence)->mesh.positions, liquidMesh(builtAlone)->mesh.positions);
  // Backwards: frame 2 after frame 4 starts the simulation again.
  alone.build(4);
  const Frame again = alone.build(2);
  const Frame first = sequence.build(2);
  EXPECT_EQ(liquidMesh(again)->mesh.positions, liquidMesh(first)->mesh.positions);
}

size_t filesIn(const std::filesystem::path& dir) {
  std::error_code ec;
  size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) count += entry.is_regular_file() ? 1 : 0;
  return count;
}

TEST(SphShot, CheckpointsAreFiledAndAFrameBuiltLaterResumesFromThemEvenPastACorruptOne) {
  const std::filesystem::path home = test::testDirectory("sph_cache", true);
  const test::ScopedCacheHome cache(home);
  const std::filesystem::path states = home / "lacrima" / "sph" / "states";
  const Shot first = loadShot(writeShot("sph_filing.json", dropShot()));
  const Frame simulated = buildFrame(first, 4);
  EXPECT_EQ(filesIn(states), 2u) << "frame 4 opens at 3.75: checkpoints at frames 2 and 3 (frame 1 holds only the release)";
  // Another load (a farm task) finds them; one of them corrupt is simulated again, to the same bits.
  for (const auto& entry : std::filesystem::directory_iterator(states))
    if (entry.path().filename().string().rfind("frame00002", 0) == 0) std::ofstream(entry.path()) << "garbage";
  const Shot second = loadShot(writeShot("sph_filing.json", dropShot()));
  const Frame resumed = buildFrame(second, 4);
  EXPECT_EQ(liquidMesh(resumed)->mesh.positions, liquidMesh(simulated)->mesh.positions);
  const Shot third = loadShot(writeShot("sph_filing.json", dropShot()));
  const Frame fromFiled = buildFrame(third, 3), fromFirst = buildFrame(first, 3);
  EXPECT_EQ(liquidMesh(fromFiled)->mesh.positions, liquidMesh(fromFirst)->mesh.positions);
  // A change of the fluid files its checkpoints under other keys.
  const Shot changed = loadShot(writeShot("sph_filing_changed.json", dropShot(R"(, "adhesion": 3)")));
  buildFrame(changed, 3);
  EXPECT_EQ(filesIn(states), 3u) << "frame 3 opens at 2.75: the changed fluid files its checkpoint at frame 2";
}

// The lowest and highest vertex heights of the liquid's surface.
std::pair<float, float> heightRange(const MeshInstance& liquid) {
  float lo = 1.0f, hi = -1.0f;
  for (const Vec3& p : liquid.mesh.positions) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
  return {lo, hi};
}

TEST(SphShot, ARisingTableLiftsTheLiquidOnIt) {
  // A 2 mm block of 0.25 mm particles resting 0.5 mm above a table that rises 4 mm from frame 1 to
  // frame 4 (0.32 m/s at 240 fps): a static boundary would pass through the liquid.
  // No surface tension: a cube's corners under today's uncalibrated cohesion fly off (docs/sph.md).
  const std::string text = replaced(replaced(
      replaced(dropShot(), R"("drops": [{"center": [0, 0.0041, 0], "radius": 0.0015, "velocity": [0, -0.3, 0]}],)",
               R"("blocks": [{"min": [-0.001, 0.0005, -0.001], "max": [0.001, 0.0025, 0.001]}],)"),
      R"("center": [0, 0, 0], "size": [0.02, 0.02])",
      R"("center": {"keys": [[1, [0, 0, 0]], [4, [0, 0.004, 0]]], "interpolation": "linear"}, "size": [0.02, 0.02])"),
      R"("surfaceTension": 20)", R"("surfaceTension": 0, "surface": {"smoothing": 3})");
  const test::ScopedCacheHome cache(test::testDirectory("sph_rising_cache", true));  // simulated here
  const Shot shot = loadShot(writeShot("sph_rising_table.json", text));
  const Frame frame = buildFrame(shot, 4);  // kept: liquid points into it
  const MeshInstance* liquid = liquidMesh(frame);
  ASSERT_NE(liquid, nullptr);
  // At shutter open (frame 3.75) the table is at 3.67 mm: the liquid (spreading into a layer a few
  // particles thick, lightly smoothed so that it stays) lies on it, none of it left below.
  const auto [lo, hi] = heightRange(*liquid);
  EXPECT_GT(lo, 0.0036f);
  EXPECT_GT(hi, 0.0040f);
  EXPECT_LT(hi, 0.0070f);
}

TEST(SphShot, ALaterReleaseAddsItsDropAtItsFrame) {
  const std::string text = replaced(dropShot(), R"("velocity": [0, -0.3, 0]}])",
                                    R"("velocity": [0, -0.3, 0]}, {"center": [0.006, 0.004, 0], "radius": 0.0012, "frame": 3}])");
  const Shot shot = loadShot(writeShot("sph_two_drops.json", text));
  const auto xExtent = [](const MeshInstance& m) {
    float hi = -1.0f;
    for (const Vec3& p : m.mesh.positions) hi = std::max(hi, p.x());
    return hi;
  };
  FrameBuilder builder(shot);
  const Frame before = builder.build(2), after = builder.build(4);
  EXPECT_LT(xExtent(*liquidMesh(before)), 0.004f);  // only the first drop
  EXPECT_GT(xExtent(*liquidMesh(after)), 0.006f);   // the second one is there
}

// A 1.5 mm drop of 0.25 mm particles thrown at 0.3 m/s at the ICT face's left cheek (its centre
// 2.6 mm in front of the skin point (-0.0507, -0.0027, 0.0895), along the skin's normal there,
// (-0.645, -0.048, 0.762)), at 240 fps; `collider` is the liquid's colliders entry (or empty).
std::string dropOnTheCheek(const std::string& collider) {
  return replaced(test::ictFaceShot(R"("sph": [{"material": "water", "particleRadius": 0.00025, "surfaceTension": 20,
    "drops": [{"center": [-0.0524, -0.0028, 0.0915], "radius": 0.0015, "velocity": [0.194, 0.014, -0.229]}])" +
                                        (collider.empty() ? "" : R"(, "colliders": [)" + collider + "]") + "}]",
                                    "", "", 6),
                  R"("fps": 24)", R"("fps": 240)");
}

// The face's posed M_Face in a frame.
const MeshInstance& faceSkin(const Frame& frame) {
  const auto it = std::find_if(frame.meshes.begin(), frame.meshes.end(), [](const MeshInstance& m) {
    return m.mesh.name.size() >= 6 && m.mesh.name.compare(m.mesh.name.size() - 6, 6, "M_Face") == 0;
  });
  EXPECT_NE(it, frame.meshes.end());
  return *it;
}

// How far the liquid's surface reaches past the skin's tangent plane at `point` (a point on the
// skin; m, > 0: behind the skin), with the normal of the skin vertex nearest it.
float depthBehindTheSkin(const Frame& frame, const Vec3& point) {
  const TriangleMesh& skin = faceSkin(frame).mesh;
  size_t nearest = 0;
  for (size_t v = 1; v < skin.positions.size(); ++v)
    if ((skin.positions[v] - point).squaredNorm() < (skin.positions[nearest] - point).squaredNorm()) nearest = v;
  const Vec3 normal = skin.normals.at(nearest).normalized();
  float deepest = -1.0f;
  for (const Vec3& p : liquidMesh(frame)->mesh.positions) deepest = std::max(deepest, -(p - point).dot(normal));
  return deepest;
}

TEST(SphShot, AStretchOfTheFaceIsAColliderTheDropLandsOn) {
  const std::string region = R"({"asset": "face", "part": "M_Face", "regions": [{"center": [-0.0507, -0.0027, 0.0895], "radius": 0.008}]})";
  const Shot shot = loadShot(writeShot("sph_on_the_cheek.json", dropOnTheCheek(region)));
  const Vec3 cheek = shot.sph[0].colliderParts[0].regions[0].centerPoint.reference;
  // Frame 3, 8 ms after the release: landed (the drop, repelled by a skin it does not wet, lifts
  // off again from frame 4: 0.51, 0.93, 1.88 mm in front of the plane at frames 4-6).
  const Frame landed = buildFrame(shot, 3);
  ASSERT_NE(liquidMesh(landed), nullptr);
  const float depth = depthBehindTheSkin(landed, cheek);
  // Without the collider the drop runs on through the skin (its surface 1.1 mm behind the plane).
  const Shot through = loadShot(writeShot("sph_through_the_cheek.json", dropOnTheCheek("")));
  const Frame passed = buildFrame(through, 3);
  const float depthWithout = depthBehindTheSkin(passed, cheek);
  std::printf("[ face collider ] liquid surface behind the cheek's tangent plane: %.2f mm (%.2f mm without the collider)\n",
              1e3 * depth, 1e3 * depthWithout);
  EXPECT_LT(depth, 0.0f);  // held by the face's boundary particles (0.35 mm in front)
  EXPECT_GT(depth, -0.001f) << "the drop must have reached the skin";
  EXPECT_GT(depthWithout, 0.0008f);
}

// A 1.2 mm drop of 0.2 mm particles floating (no gravity) 1.2 mm under the ICT face's chin while the
// jaw opens over 50 ms (jawOpen keyed 0 -> 1, frames 1-13 at 240 fps); `collider` is the liquid's
// colliders entry (or empty).
std::string dropUnderAnOpeningJaw(const std::string& collider) {
  return replaced(test::ictFaceShot(R"("sph": [{"material": "water", "particleRadius": 0.0002, "surfaceTension": 20,
    "gravity": [0, 0, 0], "drops": [{"center": [0, -0.0847, 0.0817], "radius": 0.0012}])" +
                                        (collider.empty() ? "" : R"(, "colliders": [)" + collider + "]") + "}]",
                                    "", R"("blendshapes": {"jawOpen": {"keys": [[1, 0], [13, 1]], "interpolation": "linear"}})", 13),
                  R"("fps": 24)", R"("fps": 240)");
}

// The highest point of the liquid's surface.
float liquidTop(const Frame& frame) {
  float top = -1.0f;
  for (const Vec3& p : liquidMesh(frame)->mesh.positions) top = std::max(top, p.y());
  return top;
}

TEST(SphShot, TheChinOfAnOpeningJawPushesTheDropUnderIt) {
  const std::string chin = R"({"asset": "face", "part": "M_Face", "regions": [{"center": [0, -0.0823, 0.0817], "radius": 0.008}]})";
  const Shot shot = loadShot(writeShot("sph_under_the_jaw.json", dropUnderAnOpeningJaw(chin)));
  const Shot alone = loadShot(writeShot("sph_under_no_jaw.json", dropUnderAnOpeningJaw("")));
  FrameBuilder builder(shot);
  const Frame start = builder.build(1), pushed = builder.build(13), left = buildFrame(alone, 13);
  // The chin's underside: the lowest skin point within 3 mm of the midline, in front of the neck.
  const auto chinBottom = [](const Frame& frame) {
    float lowest = 1.0f;
    for (const Vec3& p : faceSkin(frame).mesh.positions)
      if (std::abs(p.x()) < 0.003f && p.z() > 0.07f && p.y() > -0.13f) lowest = std::min(lowest, p.y());
    return lowest;
  };
  std::printf("[ moving face collider ] chin %.2f -> %.2f mm; drop top %.2f -> %.2f mm (%.2f mm without the collider)\n",
              1e3 * chinBottom(start), 1e3 * chinBottom(pushed), 1e3 * liquidTop(start), 1e3 * liquidTop(pushed),
              1e3 * liquidTop(left));
  EXPECT_LT(chinBottom(pushed), chinBottom(start) - 0.015f) << "the jaw must open";
  // Measured: the chin 83.6 -> 105.7 mm down, the drop's top 83.6 -> 109.9 mm (pushed ahead of it,
  // and moving on in zero gravity); left alone it stays (83.7).
  EXPECT_LT(liquidTop(pushed), liquidTop(start) - 0.015f);
  EXPECT_LT(liquidTop(pushed), chinBottom(pushed)) << "the drop stays under the chin";
  EXPECT_NEAR(liquidTop(left), liquidTop(start), 0.0005f);
}

// A 6 mm plate held 1.4 mm under the ICT face's chin, facing down, `attach`ed to the face or not,
// over a 1.2 mm drop floating (no gravity) 1.5 mm under it while the jaw opens as above; the plate
// is the liquid's only collider.
std::string plateUnderAnOpeningJaw(bool attached) {
  const std::string attach = attached ? R"(, "attach": {"asset": "face", "part": "M_Face"})" : "";
  return replaced(
      test::ictFaceShot(R"("shapes": [{"type": "rectangle", "center": [0, -0.085, 0.0817], "size": [0.006, 0.006],
                    "normal": [0, -1, 0], "material": "skin")" + attach + R"(}],
  "sph": [{"material": "water", "particleRadius": 0.0002, "surfaceTension": 20, "gravity": [0, 0, 0],
           "drops": [{"center": [0, -0.0877, 0.0817], "radius": 0.0012}], "colliders": [{"shape": 0}]}])",
                        "", R"("blendshapes": {"jawOpen": {"keys": [[1, 0], [13, 1]], "interpolation": "linear"}})", 13),
      R"("fps": 24)", R"("fps": 240)");
}

TEST(SphShot, AShapeAttachedToTheFaceCollidesWhereTheFaceCarriesIt) {
  const Shot attached = loadShot(writeShot("sph_attached_plate.json", plateUnderAnOpeningJaw(true)));
  const Shot still = loadShot(writeShot("sph_still_plate.json", plateUnderAnOpeningJaw(false)));
  FrameBuilder builder(attached);
  const Frame start = builder.build(1), pushed = builder.build(13), left = buildFrame(still, 13);
  std::printf("[ attached collider ] drop top %.2f -> %.2f mm under an attached plate, %.2f mm under a still one\n",
              1e3 * liquidTop(start), 1e3 * liquidTop(pushed), 1e3 * liquidTop(left));
  // The rendered plate (the frame builder's) and the collider move together: the plate goes down
  // with the chin, and the drop under it is pushed ahead of it.
  const auto plateHeight = [](const Frame& frame) {
    for (const MeshInstance& m : frame.meshes)
      if (m.mesh.name == "rectangle") return m.mesh.positions[0].y();
    return 1.0f;
  };
  EXPECT_LT(plateHeight(pushed), plateHeight(start) - 0.015f) << "the attached plate must follow the opening jaw";
  EXPECT_LT(liquidTop(pushed), liquidTop(start) - 0.015f);
  EXPECT_LT(liquidTop(pushed), plateHeight(pushed)) << "the drop stays under the plate";
  EXPECT_NEAR(liquidTop(left), liquidTop(start), 0.0005f) << "a plate not attached stays, and so does the drop";
}

TEST(SphShot, AColliderRegionHoldingNoTriangleIsAnErrorNamingIt) {
  const std::filesystem::path path = writeShot(
      "sph_empty_region.json",
      dropOnTheCheek(R"({"asset": "face", "part": "M_Face", "regions": [{"center": [-0.0525, -0.0029, 0.0915], "radius": 0.00001}]})"));
  const Shot shot = loadShot(path);
  try {
    buildFrame(shot, 2);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": /sph/0/colliders/0/regions: no triangle of the part lies wholly "
                                                     "within the regions: give larger radii");
  }
}

TEST(SphShot, BadInputIsReportedAtItsPath) {
  expectSingleError("sph_no_material.json", replaced(dropShot(), R"("material": "water", )", ""),
                    "/sph/0: missing required key 'material' (the name of a material in 'materials' (e.g. one of type "
                    "'water'))");
  expectSingleError("sph_tiny_drop.json", replaced(dropShot(), R"("radius": 0.0015)", R"("radius": 0.0001)"),
                    "/sph/0/drops/0: holds no particle: make it larger than the particle spacing (0.0005 m = 2 x "
                    "particleRadius)");
  expectSingleError("sph_bad_shape.json", replaced(dropShot(), R"({"shape": 0})", R"({"shape": 3})"),
                    "/sph/0/colliders/0/shape: expected an integer in [0, 0], found 3");
  expectSingleError("sph_early_release.json", replaced(dropShot(), R"("velocity": [0, -0.3, 0]})",
                                                       R"("velocity": [0, -0.3, 0], "frame": 0})"),
                    "/sph/0/drops/0/frame: expected an integer in [1, 4], found 0");
  expectSingleError("sph_late_start.json", replaced(dropShot(), R"("start": 1)", R"("start": 3)"),
                    "/sph/0/start: expected an integer <= 2, found 3");
  expectSingleError("sph_negative_radius.json", replaced(dropShot(), R"("particleRadius": 0.00025)", R"("particleRadius": -1)"),
                    "/sph/0/particleRadius: expected a number > 0, found -1");
  expectSingleError("sph_unknown_key.json", dropShot(R"(, "viscocity": 0.1)"),
                    "/sph/0/viscocity: unknown key 'viscocity'; did you mean 'viscosity'?");
  expectSingleError("sph_no_fluid.json",
                    replaced(dropShot(), R"("drops": [{"center": [0, 0.0041, 0], "radius": 0.0015, "velocity": [0, -0.3, 0]}],)", ""),
                    "/sph/0/drops: an SPH liquid needs at least one of 'drops' or 'blocks' (the fluid it releases)");
  expectSingleError("sph_sigma_and_gamma.json", dropShot(R"(, "sigma": 0.072)"),
                    "/sph/0/sigma: give one of 'sigma' (N/m) and 'surfaceTension' (Akinci et al.'s gamma), not both");
  expectSingleError("sph_negative_sigma.json", replaced(dropShot(), R"("surfaceTension": 20)", R"("sigma": -0.07)"),
                    "/sph/0/sigma: expected a number >= 0, found -0.07");
}

TEST(SphShot, SigmaInNewtonsPerMetreSetsTheCohesionForTheParticleSize) {
  // 0.25 mm particles of water at 0.072 N/m: gamma = sigma / (c rho0^2 r^2) (surface_tension.hpp).
  const Shot shot = loadShot(writeShot("sph_sigma.json", replaced(dropShot(), R"("surfaceTension": 20)", R"("sigma": 0.072)")));
  ASSERT_EQ(shot.sph.size(), 1u);
  EXPECT_NEAR(shot.sph[0].fluid.surfaceTension, 0.072 / (sph::kSigmaPerGamma * 1e6 * 0.00025 * 0.00025), 1e-9);
  // The same sigma at twice the rest density (read after it) needs a quarter of the gamma.
  const Shot dense = loadShot(writeShot(
      "sph_sigma_dense.json", replaced(dropShot(), R"("surfaceTension": 20)", R"("sigma": 0.072, "restDensity": 2000)")));
  EXPECT_NEAR(dense.sph[0].fluid.surfaceTension, shot.sph[0].fluid.surfaceTension / 4.0, 1e-9);
}

TEST(SphShot, AParticleRadiusFarTooSmallForTheDropIsAnErrorNotAnExhaustedMemory) {
  // 1.5 mm drop at 1 um particles: 1500^3 = 3.4e9 lattice points in its bounding box.
  expectSingleError("sph_too_many_particles.json",
                    replaced(dropShot(), R"("particleRadius": 0.00025)", R"("particleRadius": 0.000001)"),
                    "/sph/0/drops/0: the liquid's releases up to this one fill 3.38e+09 particles at particleRadius "
                    "1e-06 m, more than the 4 million allowed: make particleRadius larger or the releases smaller");
}

TEST(SphShot, AColliderFarTooLargeForTheParticleSpacingIsAnErrorNamingIt) {
  // A 100 m table under 0.25 mm particles: some 10^11 boundary particles.
  const std::filesystem::path path =
      writeShot("sph_huge_table.json", replaced(dropShot(), R"("size": [0.02, 0.02])", R"("size": [100, 100])"));
  const Shot shot = loadShot(path);  // loading stays cheap: colliders are sampled on the first frame built
  try {
    buildFrame(shot, 2);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.string() + ": /sph/0/colliders/0: sampling this collider"), std::string::npos) << message;
    EXPECT_NE(message.find("more than the 8 million allowed"), std::string::npos) << message;
  }
}

}  // namespace sph_shot_test
}  // namespace lacrima
