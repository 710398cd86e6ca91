// collectExportScene: the frame's meshes and spheres, named uniquely, with the materials they use.
#include <map>
#include <type_traits>
#include <variant>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/frame.hpp"
#include "mesh_export.hpp"

namespace lacrima::cli {

namespace {

ExportMaterial describeMaterial(const Material& material) {
  ExportMaterial out;
  out.name = material.name;
  std::visit(
      [&out](const auto& p) {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, DiffuseParams>) {
          out.baseColor = p.albedo;
        } else if constexpr (std::is_same_v<P, SkinParams>) {
          out.baseColor = p.albedo;
          out.roughness = p.roughness;
        } else if constexpr (std::is_same_v<P, SmoothDielectricParams>) {
          out.baseColor = p.tint;
          out.roughness = 0.0f;
          out.ior = p.ior;
        } else {
          static_assert(std::is_same_v<P, RoughDielectricParams>);
          out.baseColor = p.tint;
          out.roughness = p.roughness;
          out.ior = p.ior;
        }
      },
      material.params);
  return out;
}

// Gives each mesh its name, or the name with " 2", " 3", ... when it is taken already.
class UniqueNames {
 public:
  std::string claim(const std::string& wanted) {
    const std::string base = wanted.empty() ? "mesh" : wanted;
    std::string name = base;
    for (int n = 2; taken_.count(name) > 0; ++n) name = base + " " + std::to_string(n);
    taken_[name] = true;
    return name;
  }

 private:
  std::map<std::string, bool> taken_;
};

}  // namespace

size_t ExportScene::triangleCount() const {
  size_t count = 0;
  for (const ExportMesh& m : meshes) count += m.mesh.triangleCount();
  return count;
}

ExportScene collectExportScene(const Frame& frame) {
  ExportScene scene;
  std::map<uint32_t, size_t> exportedMaterial;  // frame material id -> index in scene.materials
  UniqueNames names;
  const auto add = [&](TriangleMesh mesh, uint32_t materialId) {
    if (mesh.triangleCount() == 0) return;
    auto [it, isNew] = exportedMaterial.try_emplace(materialId, scene.materials.size());
    if (isNew) {
      scene.materials.push_back(materialId < frame.materials.size() ? describeMaterial(frame.materials[materialId])
                                                                    : ExportMaterial{});
      if (scene.materials.back().name.empty()) scene.materials.back().name = "material " + std::to_string(materialId);
    }
    mesh.name = names.claim(mesh.name);
    scene.meshes.push_back({std::move(mesh), it->second});
  };
  for (const MeshInstance& instance : frame.meshes) add(instance.mesh, instance.materialId);
  for (const Sphere& sphere : frame.spheres) {
    TriangleMesh mesh =
        makeEllipsoid(sphere.center, Mat3(sphere.radius * Mat3::Identity()), kSphereRings, kSphereSegments);
    mesh.name = "sphere";
    add(std::move(mesh), sphere.materialId);
  }
  return scene;
}

std::filesystem::path mtlPathFor(const std::filesystem::path& objPath) {
  std::filesystem::path mtl = objPath;
  return mtl.replace_extension(".mtl");
}

}  // namespace lacrima::cli
