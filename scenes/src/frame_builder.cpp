// buildFrame: a checked Shot at one frame number -> the renderer's Frame, through the geometry
// stage (static blendshape weights, asset transforms, simple shapes). Nothing is read from disk
// here: loadShot loaded the assets and the environment map once.
#include <fmt/format.h>

#include <algorithm>

#include "lacrima/geometry/shapes.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima {

namespace {

void addAssetMeshes(const Shot& shot, const ShotAsset& asset, Frame& frame) {
  if (!asset.gltf)
    throw InputError(fmt::format("{}: asset '{}' ({}) is not loaded; shots must come from loadShot", shot.path.string(),
                                 asset.name, asset.file.string()));
  const GltfAsset& gltf = *asset.gltf;
  if (asset.primitiveMaterials.size() != gltf.primitives.size())
    throw InputError(fmt::format("{}: asset '{}': {} primitive materials for {} primitives", shot.path.string(),
                                 asset.name, asset.primitiveMaterials.size(), gltf.primitives.size()));
  const bool morphed = std::any_of(asset.weights.begin(), asset.weights.end(), [](float w) { return w != 0.0f; });
  const Affine3 toWorld = asset.transform.matrix();
  for (size_t i = 0; i < gltf.primitives.size(); ++i) {
    const int materialId = asset.primitiveMaterials[i];
    if (materialId < 0) continue;  // hidden
    const GltfPrimitive& primitive = gltf.primitives[i];
    MeshInstance instance;
    instance.mesh = morphed ? applyMorphTargets(primitive, asset.weights) : primitive.mesh;
    transformMesh(instance.mesh, toWorld);
    instance.mesh.name = asset.name + "/" + primitive.name;
    if (const std::string defect = findMeshDefect(instance.mesh); !defect.empty())
      throw InputError(fmt::format("{}: asset '{}' ({}), primitive '{}': {}", shot.path.string(), asset.name,
                                   asset.file.string(), primitive.name, defect));
    instance.materialId = uint32_t(materialId);
    frame.meshes.push_back(std::move(instance));
  }
}

void addShape(const ShotShape& shape, Frame& frame) {
  switch (shape.type) {
    case ShotShape::Type::Sphere:
      frame.spheres.push_back(Sphere{shape.center, shape.radius, shape.materialId});
      break;
    case ShotShape::Type::Ellipsoid: {
      const Mat3 axes = shape.rotation * shape.radii.asDiagonal();
      frame.meshes.push_back(MeshInstance{makeEllipsoid(shape.center, axes), shape.materialId});
      break;
    }
    case ShotShape::Type::Rectangle:
      frame.meshes.push_back(MeshInstance{makeRectangle(shape.center, shape.edgeU, shape.edgeV), shape.materialId});
      break;
  }
}

}  // namespace

Frame buildFrame(const Shot& shot, int frameNumber) {
  if (frameNumber < shot.frameStart || frameNumber > shot.frameEnd)
    throw InputError(fmt::format("{}: frame {} is outside the shot's frame range {}-{}", shot.path.string(),
                                 frameNumber, shot.frameStart, shot.frameEnd));
  Frame frame;
  frame.materials = shot.frameMaterials();
  for (const ShotAsset& asset : shot.assets) addAssetMeshes(shot, asset, frame);
  for (const ShotShape& shape : shot.shapes) addShape(shape, frame);
  frame.lights = shot.lights;
  if (shot.environment) frame.environment = shot.environment->map;
  frame.uniformBackground = shot.background;
  frame.camera = shot.camera.camera;
  frame.settings = shot.render;
  frame.settings.frameNumber = frameNumber;
  return frame;
}

}  // namespace lacrima
