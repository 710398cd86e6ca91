#pragma once
// `lacrima export`: a Frame's geometry as named meshes with named materials, ready for the OBJ
// and glTF writers. The meshes are the ones the renderer gets (world space, metres, shutter open);
// the frame's analytic spheres become tessellated ellipsoids.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima {
struct Frame;
}

namespace lacrima::cli {

// What other tools can take from a lacrima material: a colour, a roughness, and for the
// dielectrics (tears, water) their index of refraction.
struct ExportMaterial {
  std::string name;
  Color baseColor = Color(0.8f, 0.8f, 0.8f);  // diffuse / skin albedo, dielectric tint (linear)
  float roughness = 1.0f;
  std::optional<float> ior;  // only for transmissive (dielectric) materials
};

struct ExportMesh {
  TriangleMesh mesh;  // mesh.name is unique within the ExportScene
  size_t material = 0;  // index into ExportScene::materials
};

struct ExportScene {
  std::vector<ExportMaterial> materials;  // only the ones some mesh uses, in order of first use
  std::vector<ExportMesh> meshes;         // frame.meshes in order, then frame.spheres

  size_t triangleCount() const;
};

// Tessellation of exported spheres (makeEllipsoid's defaults, about 9000 triangles each).
inline constexpr int kSphereRings = 48;
inline constexpr int kSphereSegments = 96;

// Every mesh and sphere of the frame that has triangles. Names come from the frame builder
// ("face/<mesh>/M_Face", "tear", "ellipsoid", "sphere"); a repeated name gets " 2", " 3", ...
ExportScene collectExportScene(const Frame& frame);

// The two file formats; each writes one file per frame (OBJ also its .mtl beside it).
void writeObj(const std::filesystem::path& path, const ExportScene& scene);
void writeGlb(const std::filesystem::path& path, const ExportScene& scene);

// The .mtl file that writeObj writes next to `objPath` (same name, extension .mtl).
std::filesystem::path mtlPathFor(const std::filesystem::path& objPath);

}  // namespace lacrima::cli
