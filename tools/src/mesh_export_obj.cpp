// Wavefront OBJ export: one .obj per frame with an `o`/`g` and `usemtl` per mesh, and a small
// .mtl beside it. Indices are 1-based and continue across objects; floats are written with nine
// significant digits, which reads back to the same float.
#include <fmt/format.h>

#include <iterator>
#include <string>

#include "atomic_write.hpp"
#include "mesh_export.hpp"

namespace lacrima::cli {

namespace {

// OBJ statements end at the line end; `g` also splits its names at whitespace.
std::string objName(const std::string& name, bool splitsAtSpaces) {
  std::string out = name;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || (splitsAtSpaces && c == ' ')) c = '_';
  return out;
}

struct ObjOffsets {
  size_t positions = 1, uvs = 1, normals = 1;  // the next index of each kind (OBJ counts from 1)
};

// One vertex reference of a face: v, v/vt, v//vn or v/vt/vn.
void appendCorner(fmt::memory_buffer& out, const TriangleMesh& m, uint32_t vertex, const ObjOffsets& at) {
  fmt::format_to(std::back_inserter(out), " {}", at.positions + vertex);
  if (m.uvs.empty() && m.normals.empty()) return;
  out.push_back('/');
  if (!m.uvs.empty()) fmt::format_to(std::back_inserter(out), "{}", at.uvs + vertex);
  if (!m.normals.empty()) fmt::format_to(std::back_inserter(out), "/{}", at.normals + vertex);
}

void appendMesh(fmt::memory_buffer& out, const ExportMesh& exported, const ExportScene& scene, ObjOffsets& at) {
  const TriangleMesh& m = exported.mesh;
  auto to = std::back_inserter(out);
  fmt::format_to(to, "o {}\ng {}\nusemtl {}\n", objName(m.name, false), objName(m.name, true),
                 objName(scene.materials[exported.material].name, false));
  for (const Vec3& p : m.positions) fmt::format_to(to, "v {:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
  // lacrima's uvs follow glTF (origin top left); OBJ's origin is bottom left.
  for (const Vec2& uv : m.uvs) fmt::format_to(to, "vt {:.9g} {:.9g}\n", uv.x(), 1.0f - uv.y());
  for (const Vec3& n : m.normals) fmt::format_to(to, "vn {:.9g} {:.9g} {:.9g}\n", n.x(), n.y(), n.z());
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    out.push_back('f');
    for (int k = 0; k < 3; ++k) appendCorner(out, m, m.indices[3 * t + size_t(k)], at);
    out.push_back('\n');
  }
  at.positions += m.positions.size();
  at.uvs += m.uvs.size();
  at.normals += m.normals.size();
}

std::string mtlText(const ExportScene& scene) {
  fmt::memory_buffer out;
  auto to = std::back_inserter(out);
  fmt::format_to(to, "# lacrima export: {} materials\n", scene.materials.size());
  for (const ExportMaterial& material : scene.materials) {
    const Color& c = material.baseColor;
    fmt::format_to(to, "\nnewmtl {}\nKd {:.9g} {:.9g} {:.9g}\n", objName(material.name, false), c.x(), c.y(), c.z());
    if (material.ior) fmt::format_to(to, "Ni {:.9g}\n", *material.ior);
  }
  return fmt::to_string(out);
}

}  // namespace

void writeObj(const std::filesystem::path& path, const ExportScene& scene) {
  const std::filesystem::path mtlPath = mtlPathFor(path);
  writeFileAtomically(mtlPath, "material library", [&](std::ostream& out) { out << mtlText(scene); });
  fmt::memory_buffer text;
  fmt::format_to(std::back_inserter(text), "# lacrima export: {} meshes, {} triangles; world space, metres\nmtllib {}\n",
                 scene.meshes.size(), scene.triangleCount(), objName(mtlPath.filename().string(), false));
  ObjOffsets at;
  for (const ExportMesh& mesh : scene.meshes) appendMesh(text, mesh, scene, at);
  writeFileAtomically(path, "OBJ file", [&](std::ostream& out) { out.write(text.data(), std::streamsize(text.size())); });
}

}  // namespace lacrima::cli
