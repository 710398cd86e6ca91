#pragma once
// A glTF 2.0 asset flattened for rendering: one entry per mesh primitive, in asset space
// (node transforms already applied), with its sparse morph targets (blendshapes).
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lacrima/io/gltf_animation.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

// The glTF material of a primitive, as far as lacrima maps it (pbrMetallicRoughness + extensions).
struct GltfMaterialInfo {
  std::string name;                       // glTF material name ("" if none)
  Color baseColor = Color(0.8f, 0.8f, 0.8f);  // baseColorFactor rgb (linear)
  float roughness = 1.0f;                 // roughnessFactor
  float metallic = 0.0f;                  // metallicFactor
  float transmission = 0.0f;              // KHR_materials_transmission.transmissionFactor
  float ior = 1.5f;                       // KHR_materials_ior.ior
  bool hasVolume = false;                 // KHR_materials_volume present
  bool doubleSided = false;               // glTF doubleSided (thin sheets: tear meniscus, lashes)
  // False when the material has no pbrMetallicRoughness block. glTF would then default to a
  // white metal; lacrima keeps the grey dielectric above instead (the ICT face has no factors).
  bool hasPbrFactors = false;
};

// One morph target of one primitive: only the vertices it moves.
struct SparseDelta {
  std::vector<uint32_t> vertices;  // indices into the primitive's positions, ascending
  std::vector<Vec3> deltas;        // position offsets, same length as vertices (asset space)
};

struct GltfPrimitive {
  std::string name;        // "<mesh name>/<extras.part or material name or index>"
  std::string part;        // extras.part if present (e.g. "M_Face"), else the material name
  TriangleMesh mesh;       // neutral shape, asset space, smooth welded normals computed
  GltfMaterialInfo material;
  std::vector<SparseDelta> targets;  // one per morph target (asset target order); may be empty deltas
  // Already applied to mesh; kept to transform deltas. Identity for skinned primitives, whose
  // node transform glTF ignores (their rest pose comes from the skin, see below).
  Affine3 nodeTransform = Affine3::Identity();
  int node = -1;  // index into GltfAsset::nodes of the node that instanced this primitive
  // Linear blend skinning (spec 3.7.3), when the node has a skin: index into GltfAsset::skins,
  // else -1. Per vertex, JOINTS_0 (indices into that skin's joints) and WEIGHTS_0 (normalized to
  // sum 1). mesh and targets are already in the skin's rest pose: mesh vertex = S_rest(v) v with
  // S_rest(v) = sum_k w_k GltfSkin::restJointMatrices[joint_k], and each delta transformed by
  // the linear part of its vertex's S_rest. JOINTS_1 / WEIGHTS_1 are not read.
  int skin = -1;
  std::vector<std::array<uint16_t, 4>> skinJoints;
  std::vector<Vec4> skinWeights;
  // findCoincidentVertices of the neutral mesh: keeps UV seams welded when morphs recompute normals.
  std::vector<uint32_t> weldMap;
  // Set by a linear refinement (refinePrimitive), empty otherwise: the mesh is shaded as the mesh
  // before that refinement was (computePrimitiveNormals): normalTriangles are its triangles (over
  // the original vertices, which keep their indices), and normalSources gives per vertex the
  // original vertices whose normals an added vertex's normal blends (an empty row: an original
  // vertex, normal from normalTriangles).
  std::vector<uint32_t> normalTriangles;
  VertexStencils normalSources;
};

// A facial landmark: a vertex of one primitive (nodes[0].extras.landmarks68 in the ICT face).
struct Landmark {
  int index = 0;        // position in the landmark list (multi-PIE 68: 0..67)
  int primitive = 0;    // index into GltfAsset::primitives
  uint32_t vertex = 0;  // vertex of that primitive
};

struct GltfCamera {
  std::string name;
  Affine3 cameraToAsset = Affine3::Identity();  // glTF camera looks down -Z, +Y up
  float yfovRadians = 0.7f;
  float aspectRatio = 0.0f;  // 0 when unspecified
};

// One node of the file, as animation playback needs it (sampleGltfAnimation).
struct GltfNode {
  std::string name;  // "" if unnamed
  // The node that lists this one among its children; -1 for roots and for nodes outside the
  // default scene's tree. glTF allows one parent per node; should a file share a subtree
  // anyway, the first parent met while walking the scene is kept (and a warning says so).
  int parent = -1;
  int mesh = -1;  // glTF mesh index, -1 for none
  // The rest pose (the file's own transform). A node given by a matrix keeps it in `matrix` and
  // identity TRS; for TRS nodes matrix == trs.matrix().
  bool hasMatrix = false;
  NodeTrs trs;
  Affine3 matrix = Affine3::Identity();
  // For a node with a mesh in the default scene: the asset-wide index (into
  // GltfAsset::targetNames) of each morph target of its mesh, in the mesh's target order.
  std::vector<int> targetSlots;
};

// A glTF skin (spec 3.7.3): its joints and their inverse bind matrices.
struct GltfSkin {
  std::string name;  // "" if unnamed
  std::vector<int> joints;  // node indices (into GltfAsset::nodes)
  std::vector<Affine3> inverseBindMatrices;  // one per joint; identity when the file has none
  // Per joint: restWorld(joint) * inverseBindMatrix, the joint matrices of the rest pose (the
  // default scene's node transforms) that the loader baked into the skinned primitives.
  std::vector<Affine3> restJointMatrices;
};

struct GltfAsset {
  std::filesystem::path path;
  std::vector<GltfPrimitive> primitives;
  std::vector<std::string> targetNames;  // morph target names (meshes[i].extras.targetNames)
  std::vector<GltfCamera> cameras;
  std::vector<std::string> nodeNames;
  std::vector<GltfNode> nodes;         // every node of the file, in file order (nodeNames[i] == nodes[i].name)
  std::vector<Landmark> landmarks;     // nodes[0].extras.landmarks68 when present
  std::vector<GltfAnimation> animations;  // every animation of the file, in file order
  std::vector<GltfSkin> skins;            // every skin of the file, in file order
  std::vector<std::string> warnings;   // things loaded with a caveat or skipped, and why

  // Index of a morph target by exact name, or -1.
  int findTarget(const std::string& name) const;
};

// Loads a .glb or .gltf file. Throws InputError naming the file for missing, truncated or
// corrupt files, unsupported primitive modes, or accessors that point outside their buffers, and
// naming the skin or primitive for skins that break spec 3.7.3 (joint indices, inverse bind
// matrix counts and values, JOINTS_0 / WEIGHTS_0 formats, all-zero or negative weights), and
// naming the animation and channel for animations that break spec 3.11 (accessor types and
// counts, key times, node / sampler indices, target paths, interpolations).
GltfAsset loadGltfAsset(const std::filesystem::path& path);

// Neutral mesh plus weighted sparse deltas: x = n + B b (Bao et al. 2019, eq. 1 without skinning).
// weights is indexed like asset.targetNames (missing trailing weights count as zero).
// Normals are recomputed (welded by primitive.weldMap) when a non-zero weight moves a vertex of
// this primitive; otherwise the result is bitwise the neutral mesh. A non-finite weight throws
// InputError.
TriangleMesh applyMorphTargets(const GltfPrimitive& primitive, const std::vector<float>& weights);

// An animation evaluated at one time, for a whole asset.
struct GltfAnimationSample {
  // Indexed like GltfAsset::targetNames. Only weights channels contribute: a target no channel
  // drives stays 0 (mesh.weights / node.weights defaults are not applied). When several nodes'
  // weights channels drive the same asset-wide target (the same name in several meshes), the
  // channel listed last in the animation wins. ICT-style assets have one mesh.
  std::vector<float> weights;
  // Per primitive: animatedWorld * restWorld^-1 of its node (the rest world transform is what the
  // loader already applied to the primitive), so that applying it to the flattened primitive
  // gives the animated pose. Exactly the identity when no node on the primitive's path to the
  // root is animated by a translation, rotation or scale channel.
  std::vector<Affine3> primitiveMotion;
  // True when some primitive's motion is not the identity.
  bool anyPrimitiveMoves = false;
  // Per skin (indexed like GltfAsset::skins): the joint matrices J_k = animatedWorld(joint_k) *
  // inverseBindMatrix_k, or empty when no joint of the skin (nor any of their ancestors) is
  // animated by a TRS channel. Skinned primitives get no primitiveMotion (identity): glTF
  // ignores their node's transform; they move only through these (applyGltfSkin).
  std::vector<std::vector<Affine3>> skinJointMatrices;
  // True when some skin's skinJointMatrices is not empty.
  bool anySkinMoves = false;
};

// `animation` (one of asset.animations) at `seconds` (held at the first / last key outside the
// keys). A node given by a matrix that an animation targets anyway (glTF forbids it) starts from
// identity TRS for the properties without a channel. Throws InputError for a non-finite time.
GltfAnimationSample sampleGltfAnimation(const GltfAsset& asset, const GltfAnimation& animation, double seconds);

// Poses a skinned primitive: `mesh` holds its (possibly morphed) rest-pose positions in asset
// space, n + delta; each vertex becomes S(v) S_rest(v)^-1 (n + delta) with S(v) = sum_k w_k
// jointMatrices[joint_k] (morph first, then skin, as glTF orders them), and normals are
// recomputed (welded by primitive.weldMap). jointMatrices is one GltfAnimationSample::
// skinJointMatrices entry for primitive.skin. Throws std::invalid_argument when the primitive is
// not skinned or the sizes disagree.
void applyGltfSkin(const GltfAsset& asset, const GltfPrimitive& primitive, const std::vector<Affine3>& jointMatrices,
                   TriangleMesh& mesh);

// Human-readable summary for `lacrima info`: primitives with vertex/triangle counts,
// materials, morph target names, cameras, bounding box, animations.
std::string describeGltfAsset(const GltfAsset& asset);

}  // namespace lacrima
