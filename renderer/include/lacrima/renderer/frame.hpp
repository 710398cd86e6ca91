#pragma once
// The renderer's input: everything needed to render one frame, already in world space.
// The renderer never reads shot files; scenes/ builds a Frame, tests build tiny ones in code.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/renderer/sampler.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/renderer/light_paths.hpp"
#include "lacrima/renderer/pixel_filter.hpp"

namespace lacrima {

class EnvironmentMap;  // environment.hpp

// Motion blur: geometry and camera are given at shutter open (the plain fields) and, when they
// move, at shutter close; in between they move linearly in the shutter time t in [0, 1].

struct MeshInstance {
  MeshInstance() = default;
  MeshInstance(TriangleMesh mesh_, uint32_t materialId_) : mesh(std::move(mesh_)), materialId(materialId_) {}

  TriangleMesh mesh;  // world space at shutter open; normals optional (geometric normal when absent)
  uint32_t materialId = 0;
  // Deformation blur: vertex positions at shutter close (same vertices and triangles), empty
  // when the mesh does not move; normals at close are optional (the open normals otherwise).
  std::vector<Vec3> positionsAtClose;
  std::vector<Vec3> normalsAtClose;
  // Water film on skin (a tear's wet trail): thickness in metres per vertex, interpolated
  // barycentrically at a hit; empty = dry. Read only for skin materials, which then shade as
  // wet skin (materials/wet_skin.hpp); the same at shutter open and close.
  std::vector<float> wetness;
  // An open dielectric surface that bounds no volume (a tear-line card on a lid, a water
  // rectangle): rendered as a thin sheet, crossed straight through without entering a medium
  // (materials/thin_dielectric.hpp). Ignored for opaque materials. The shot loader sets it for
  // dielectric glTF primitives with boundary edges and for dielectric rectangles; false keeps the
  // closed-volume model (a mesh, or several meshes together, bounding the medium).
  bool thinSheet = false;
  bool moves() const { return !positionsAtClose.empty(); }
};

// Exact sphere (drops, furnace tests), rendered with Embree's analytic sphere primitive.
struct Sphere {
  Sphere() = default;
  Sphere(const Vec3& center_, float radius_, uint32_t materialId_)
      : center(center_), radius(radius_), materialId(materialId_) {}

  Vec3 center = Vec3::Zero();  // at shutter open
  float radius = 1.0f;
  uint32_t materialId = 0;
  std::optional<Vec3> centerAtClose;  // transform blur (a falling drop); none = still
  Vec3 centerAt(float time) const { return centerAtClose ? Vec3((1.0f - time) * center + time * *centerAtClose) : center; }
};

// Pinhole or thin-lens camera. Camera space: +X right, +Y up, looks down -Z (glTF convention).
struct Camera {
  Affine3 cameraToWorld = Affine3::Identity();
  float verticalFovRadians = degreesToRadians(40.0f);
  float lensRadius = 0.0f;     // 0 = pinhole; focal length / (2 f-number) for a thin lens
  float focusDistance = 1.0f;  // metres along the view axis
  // Focus on the first surface the view axis meets at mid-shutter, as a focus puller follows the
  // subject; the renderer resolves it once per frame for a thin lens (focusDistance stays when the
  // axis meets nothing).
  bool focusOnSurface = false;
  std::optional<Affine3> cameraToWorldAtClose;  // camera motion blur; none = still
};

// Area light with uniform radiance. Rectangles emit from the side of normalize(edgeU x edgeV)
// unless twoSided; spheres emit outwards.
struct AreaLight {
  enum class Shape { Rectangle, Sphere };
  Shape shape = Shape::Rectangle;
  Vec3 center = Vec3::Zero();
  Vec3 edgeU = Vec3(1, 0, 0);
  Vec3 edgeV = Vec3(0, 1, 0);
  float radius = 0.0f;
  Color radiance = Color(1, 1, 1);
  bool twoSided = false;
  std::string group;  // its light group (light_groups.hpp); empty: a group of its own, "light<i>"
};

// How light reaches a diffuse or glossy point through smooth dielectrics (drops, tears, the
// cornea) on the way to a light; see docs/shot-format.md, "Caustics".
enum class Caustics {
  Off,       // plain path tracing: only BSDF-sampled paths find it (unbiased, very noisy)
  Straight,  // transparent shadows: shadow rays go straight through, Fresnel-weighted (no focusing)
  Mnee,      // manifold next-event estimation: the refracted connection, focused caustics
};
// Every mode, in the order shot files and the command line list them.
inline constexpr std::array<Caustics, 3> kCausticsModes = {Caustics::Mnee, Caustics::Straight, Caustics::Off};
// The mode as shot files spell it: "mnee", "straight", "off".
const char* causticsName(Caustics caustics);

// Per-type bounce limits, as Cycles has them (its light-path settings "diffuse", "glossy" and
// "transmission" bounces): a path may scatter `diffuse` times off diffuse lobes, `glossy` times
// off specular or glossy reflection lobes and `transmission` times through a surface. The
// scattering that goes over its kind's limit still sends its ray on to gather the light it meets
// (lights, emission, the environment), then the path ends: a limit of 0 keeps direct lighting by
// both MIS strategies. RenderSettings::maxDepth caps all kinds together. Default: no per-type limit.
struct BounceLimits {
  static constexpr int kUnlimited = 1024;  // the most a shot may ask for
  int diffuse = kUnlimited;
  int glossy = kUnlimited;
  int transmission = kUnlimited;
  bool operator==(const BounceLimits&) const = default;
};

// Adaptive sampling (renderer/src/adaptive_sampling.hpp): every pixel takes minSamples, then
// the pixels whose error estimate (Dammertz et al. 2010) is still above `threshold`, and their
// neighbours, take more, up to RenderSettings::samplesPerPixel. Off by default.
struct AdaptiveSampling {
  bool enabled = false;
  float threshold = 0.01f;  // relative to the square root of the pixel's value (Cycles' default)
  int minSamples = 16;
  bool operator==(const AdaptiveSampling&) const = default;
};

// Cryptomatte ID mattes (cryptomatte.hpp) of the first hits' objects and materials, each with
// `ranks` (ID, coverage) pairs a pixel (the specification's suggested 6).
struct CryptomatteSettings {
  bool objects = false;
  bool materials = false;
  int ranks = 6;
  bool any() const { return objects || materials; }
  bool operator==(const CryptomatteSettings&) const = default;
};

// A rectangle of a frame's pixels (x right, y down, row 0 at the top), in the pixels of the
// whole frame.
struct PixelRegion {
  int x = 0, y = 0, width = 0, height = 0;
  bool empty() const { return width <= 0 || height <= 0; }
  bool operator==(const PixelRegion&) const = default;
};

struct RenderSettings {
  int width = 640;   // the whole frame's, whatever `region` renders of it
  int height = 360;
  // The pixels rendered (a crop window, as film renderers call it): the camera and every pixel's
  // samples are those of the whole width x height frame, so a region's pixels are the frame's
  // bitwise (adaptive sampling and the denoiser see the region's pixels only, so near its edges
  // theirs differ). Empty: the whole frame.
  PixelRegion region;
  // The film's size: the region's, or the whole frame's.
  int filmWidth() const { return region.empty() ? width : region.width; }
  int filmHeight() const { return region.empty() ? height : region.height; }
  int samplesPerPixel = 16;  // the most a pixel takes (all of them without adaptive sampling)
  AdaptiveSampling adaptive;
  // Denoise the frame after path tracing (denoiser.hpp): the film gets a denoised layer beside
  // the raw beauty. Needs at least 2 samples per pixel (two half buffers).
  bool denoise = false;
  int maxDepth = 12;       // path vertices after the camera ray
  BounceLimits bounces;    // per kind of scattering, within maxDepth
  uint64_t seed = 0;
  SamplerKind sampler = SamplerKind::Sobol;  // how each pixel's samples are spread (sampler.hpp)
  int threads = 0;         // 0 = all cores
  int frameNumber = 1;     // part of the random key
  bool floatOutput = false;  // EXR beauty as float instead of half
  Caustics caustics = Caustics::Mnee;
  // Pixel reconstruction filter, importance-sampled per camera sample (pixel_filter.hpp).
  PixelFilter filter;
  CryptomatteSettings cryptomatte;
  // A beauty layer per light group (light_groups.hpp), the groups adding up to the beauty.
  bool lightGroups = false;
  // The light-path layers written (light_paths.hpp); all of them add up to the beauty.
  LightPathSet lightPaths;
};

// The further EXR layers a render can write, by the names shots and `--aov` give them:
// "CryptoObject", "CryptoMaterial", "lightGroups", "lightPaths" (every light path), and each
// light path's own name ("diffuse_direct", ..., light_paths.hpp).
const std::vector<std::string>& aovNames();
// Turns on the AOV `name` in `s`; false (and `s` unchanged) for a name not in aovNames().
bool enableAov(RenderSettings& s, const std::string& name);

struct Frame {
  std::vector<Material> materials;  // indexed by materialId
  std::vector<MeshInstance> meshes;
  std::vector<Sphere> spheres;
  std::vector<AreaLight> lights;
  std::shared_ptr<const EnvironmentMap> environment;  // may be null (black background)
  Color uniformBackground = Color(0, 0, 0);  // used when environment is null (furnace tests)
  Camera camera;
  RenderSettings settings;

  // True when anything moves during the shutter: camera rays then carry a sampled time. A still
  // frame draws no time sample, so it renders bitwise as it did without motion blur.
  bool hasMotion() const;
};

}  // namespace lacrima
