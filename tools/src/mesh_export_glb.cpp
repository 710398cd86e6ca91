// Binary glTF 2.0 (.glb) export with tinygltf's writer: one buffer, one node + mesh + primitive
// per exported mesh, POSITION (with the min/max the spec requires), NORMAL and TEXCOORD_0 when
// the mesh has them, uint32 indices, and one pbrMetallicRoughness material per material name.
// Vertices are written as they are (never split or welded), so a closed mesh stays closed.
#include <tiny_gltf.h>  // Debian's shared libtinygltf: never define TINYGLTF_IMPLEMENTATION here.

#include <algorithm>
#include <cstring>

#include "atomic_write.hpp"
#include "lacrima/base/error.hpp"
#include "mesh_export.hpp"

#ifndef LACRIMA_VERSION
#define LACRIMA_VERSION "unknown"
#endif

namespace lacrima::cli {

namespace {

constexpr int kArrayBuffer = 34962;         // bufferView target of vertex attributes
constexpr int kElementArrayBuffer = 34963;  // bufferView target of indices

// Eigen's fixed-size float vectors are tightly packed, so a std::vector of them is a float array.
static_assert(sizeof(Vec3) == 3 * sizeof(float) && sizeof(Vec2) == 2 * sizeof(float));

// Appends raw values to the model's single buffer as a new bufferView; returns its index.
template <typename T>
int addBufferView(tinygltf::Model& model, const std::vector<T>& values, int target) {
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();  // every component is 4 bytes, so offsets stay 4-aligned
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  bytes.resize(bytes.size() + view.byteLength);
  if (view.byteLength > 0) std::memcpy(bytes.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, int bufferView, int componentType, size_t count, int type) {
  tinygltf::Accessor accessor;
  accessor.bufferView = bufferView;
  accessor.componentType = componentType;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

int addPositions(tinygltf::Model& model, const TriangleMesh& mesh) {
  const int view = addBufferView(model, mesh.positions, kArrayBuffer);
  const int index = addAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, mesh.positions.size(), TINYGLTF_TYPE_VEC3);
  const Eigen::AlignedBox3f bounds = computeBounds(mesh);
  tinygltf::Accessor& accessor = model.accessors[size_t(index)];
  for (int k = 0; k < 3; ++k) {
    accessor.minValues.push_back(bounds.min()[k]);
    accessor.maxValues.push_back(bounds.max()[k]);
  }
  return index;
}

tinygltf::Primitive makePrimitive(tinygltf::Model& model, const ExportMesh& exported) {
  const TriangleMesh& mesh = exported.mesh;
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = int(exported.material);
  primitive.attributes["POSITION"] = addPositions(model, mesh);
  if (!mesh.normals.empty())
    primitive.attributes["NORMAL"] =
        addAccessor(model, addBufferView(model, mesh.normals, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT,
                    mesh.normals.size(), TINYGLTF_TYPE_VEC3);
  if (!mesh.uvs.empty())
    primitive.attributes["TEXCOORD_0"] =
        addAccessor(model, addBufferView(model, mesh.uvs, kArrayBuffer), TINYGLTF_COMPONENT_TYPE_FLOAT,
                    mesh.uvs.size(), TINYGLTF_TYPE_VEC2);
  primitive.indices = addAccessor(model, addBufferView(model, mesh.indices, kElementArrayBuffer),
                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, mesh.indices.size(), TINYGLTF_TYPE_SCALAR);
  return primitive;
}

void useExtension(tinygltf::Model& model, const std::string& name) {
  if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), name) == model.extensionsUsed.end())
    model.extensionsUsed.push_back(name);
}

// Dielectrics (tears, water) as transmissive glTF materials with their index of refraction.
tinygltf::Material makeMaterial(tinygltf::Model& model, const ExportMaterial& material) {
  tinygltf::Material out;
  out.name = material.name;
  const Color& c = material.baseColor;
  out.pbrMetallicRoughness.baseColorFactor = {c.x(), c.y(), c.z(), 1.0};
  out.pbrMetallicRoughness.metallicFactor = 0.0;
  out.pbrMetallicRoughness.roughnessFactor = material.roughness;
  if (material.ior) {
    out.extensions["KHR_materials_transmission"] =
        tinygltf::Value(tinygltf::Value::Object{{"transmissionFactor", tinygltf::Value(1.0)}});
    out.extensions["KHR_materials_ior"] =
        tinygltf::Value(tinygltf::Value::Object{{"ior", tinygltf::Value(double(*material.ior))}});
    useExtension(model, "KHR_materials_transmission");
    useExtension(model, "KHR_materials_ior");
  }
  return out;
}

tinygltf::Model makeModel(const ExportScene& scene) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = std::string("lacrima ") + LACRIMA_VERSION + " export";
  model.buffers.resize(1);
  for (const ExportMaterial& material : scene.materials) model.materials.push_back(makeMaterial(model, material));
  tinygltf::Scene root;
  for (const ExportMesh& exported : scene.meshes) {
    tinygltf::Mesh mesh;
    mesh.name = exported.mesh.name;
    mesh.primitives.push_back(makePrimitive(model, exported));
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = exported.mesh.name;
    node.mesh = int(model.meshes.size()) - 1;
    model.nodes.push_back(node);
    root.nodes.push_back(int(model.nodes.size()) - 1);
  }
  if (model.buffers[0].data.empty()) model.buffers.clear();  // glTF buffers must not be empty
  model.scenes.push_back(root);
  model.defaultScene = 0;
  return model;
}

}  // namespace

void writeGlb(const std::filesystem::path& path, const ExportScene& scene) {
  const tinygltf::Model model = makeModel(scene);
  writeFileAtomically(path, "glTF file", [&](std::ostream& out) {
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false, /*writeBinary=*/true))
      throw InputError("cannot write glTF file '" + path.string() + "': the glTF writer failed");
  });
}

}  // namespace lacrima::cli
