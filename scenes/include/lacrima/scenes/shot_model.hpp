#pragma once
// The Shot: everything a shot file says, checked and in lacrima's units (metres, radians where
// the renderer wants them, linear RGB), plus the external files it names, loaded once.
// Plain data: loadShot() fills it, buildFrame() reads it. docs/shot-format.md describes the file.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lacrima/geometry/gltf_asset.hpp"
#include "lacrima/geometry/math.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/renderer/environment.hpp"
#include "lacrima/renderer/frame.hpp"
#include "lacrima/scenes/shot.hpp"  // Diagnostic (shot.hpp includes this file after defining it)

namespace lacrima {

// Scale, then rotation, then translation: x_world = translate + rotation * (scale .* x).
struct ShotTransform {
  Vec3 translate = Vec3::Zero();
  Mat3 rotation = Mat3::Identity();
  Vec3 scale = Vec3::Ones();

  Affine3 matrix() const;
};

// The camera as the shot file describes it, and the renderer camera derived from it at load.
struct ShotCamera {
  enum class Kind { LookAt, Gltf };
  Kind kind = Kind::LookAt;
  // Kind::LookAt
  Vec3 position = Vec3::Zero();
  Vec3 lookAt = Vec3(0, 0, -1);
  Vec3 up = Vec3(0, 1, 0);
  // Kind::Gltf: a camera of one of the shot's assets (the asset's transform applies)
  std::string gltfAsset;   // ShotAsset::name
  std::string gltfCamera;  // GltfCamera::name
  // Field of view: exactly one of these, or neither for a glTF camera (its yfov is used).
  std::optional<float> fovDegrees;     // vertical
  std::optional<float> focalLengthMm;  // with sensorHeightMm
  float sensorHeightMm = 24.0f;
  // Thin lens; pinhole when fStop is absent.
  std::optional<float> fStop;
  std::optional<float> focusDistance;  // metres; default: distance to lookAt

  Camera camera;  // derived: what buildFrame hands to the renderer
};

struct ShotEnvironment {
  std::filesystem::path file;  // resolved
  float intensity = 1.0f;
  float rotationDegrees = 0.0f;               // about world +Y
  std::shared_ptr<const EnvironmentMap> map;  // loaded once by loadShot
};

// One glTF asset placed in the shot.
struct ShotAsset {
  std::string name;            // unique within the shot (default: file stem)
  std::filesystem::path file;  // resolved
  ShotTransform transform;
  // Binding of the asset's material or part names to shot material names, in file order.
  std::vector<std::pair<std::string, std::string>> materialBindings;
  // Static blendshape weights as written, in file order ...
  std::vector<std::pair<std::string, float>> blendshapes;
  // ... and indexed like gltf->targetNames (what applyMorphTargets wants).
  std::vector<float> weights;
  std::vector<std::string> hide;          // part names not rendered
  std::shared_ptr<const GltfAsset> gltf;  // loaded once by loadShot
  // Per primitive of gltf: index into the frame's material list (Shot::frameMaterials()),
  // or -1 when the primitive is hidden.
  std::vector<int> primitiveMaterials;
};

// Simple analytic or tessellated shapes (drops, floors, furnace spheres).
struct ShotShape {
  enum class Type { Sphere, Ellipsoid, Rectangle };
  Type type = Type::Sphere;
  Vec3 center = Vec3::Zero();
  float radius = 0.0f;               // Sphere
  Vec3 radii = Vec3::Ones();         // Ellipsoid semi-axes before rotation
  Mat3 rotation = Mat3::Identity();  // Ellipsoid
  Vec3 edgeU = Vec3(1, 0, 0);        // Rectangle: spans center +- edgeU/2 +- edgeV/2,
  Vec3 edgeV = Vec3(0, 1, 0);        //   normal normalize(edgeU x edgeV)
  std::string material;              // shot material name
  uint32_t materialId = 0;           // index into Shot::materials
};

struct Shot {
  std::filesystem::path path;  // the shot file, as given to loadShot
  int version = 1;

  int frameStart = 1;
  int frameEnd = 1;
  double fps = 24.0;

  // Resolved relative to the shot file's directory; '#' runs (or %04d) stand for the frame.
  std::string outputPattern;
  // "colorConfig" resolved; empty when the shot does not name one (the tool uses its default).
  std::filesystem::path ocioConfig;

  RenderSettings render;  // frameNumber is set by buildFrame
  ShotCamera camera;

  std::optional<ShotEnvironment> environment;
  Color background = Color(0, 0, 0);  // uniform radiance when there is no environment

  std::vector<Material> materials;       // from the shot file, in file order
  std::vector<Material> assetMaterials;  // glTF materials mapped automatically (unbound ones)
  std::vector<AreaLight> lights;         // radiance already derived from power where given
  std::vector<ShotAsset> assets;
  std::vector<ShotShape> shapes;

  // Things that load but deserve a look (glTF loader caveats, environment texels that were
  // NaN/Inf/negative and set to 0). Each message starts with "warning: ". The tool prints them.
  std::vector<Diagnostic> warnings;

  // Index of a shot material by name, or -1.
  int findMaterial(const std::string& name) const;
  // materials followed by assetMaterials: the list material ids index into.
  std::vector<Material> frameMaterials() const;
};

}  // namespace lacrima
