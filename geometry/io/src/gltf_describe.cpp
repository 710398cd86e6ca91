// The human-readable summary printed by `lacrima info`.
#include <algorithm>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

namespace {

// Names joined with ", " and wrapped to `width` columns, each line indented by `indent`.
std::string wrapNames(const std::vector<std::string>& names, size_t indent, size_t width) {
  std::string out, line(indent, ' ');
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string item = names[i] + (i + 1 < names.size() ? "," : "");
    if (line.size() > indent && line.size() + 1 + item.size() > width) {
      out += line + "\n";
      line.assign(indent, ' ');
    }
    if (line.size() > indent) line += ' ';
    line += item;
  }
  if (line.size() > indent) out += line + "\n";
  return out;
}

size_t movingTargetCount(const GltfPrimitive& p) {
  return size_t(std::count_if(p.targets.begin(), p.targets.end(), [](const SparseDelta& d) { return !d.vertices.empty(); }));
}

// The open primitives with their boundary edges: what decides whether a primitive given a
// dielectric material bounds a volume or renders as a thin sheet.
std::string describeOpenSurfaces(const GltfAsset& asset) {
  std::vector<std::string> open;
  for (size_t i = 0; i < asset.primitives.size(); ++i)
    if (const size_t edges = countBoundaryEdges(asset.primitives[i].mesh); edges > 0)
      open.push_back(fmt::format("#{} {} ({})", i, asset.primitives[i].part, edges));
  std::string out = fmt::format(
      "  open surfaces: {} of {} (boundary edges, vertices welded by position); given water or another\n"
      "  dielectric in a shot, an open primitive renders as a thin sheet, a closed one bounds a volume\n",
      open.size(), asset.primitives.size());
  return open.empty() ? out : out + wrapNames(open, 4, 100);
}

std::string describePrimitives(const GltfAsset& asset) {
  size_t nameWidth = 4, partWidth = 4;
  for (const GltfPrimitive& p : asset.primitives) {
    nameWidth = std::max(nameWidth, p.name.size());
    partWidth = std::max(partWidth, p.part.size());
  }
  std::string out = fmt::format("primitives: {}\n", asset.primitives.size());
  out += fmt::format("  {:>3}  {:<{}}  {:<{}}  {:>8}  {:>9}  {:>7}  {}\n", "#", "name", nameWidth, "part", partWidth,
                     "vertices", "triangles", "targets", "material");
  size_t vertices = 0, triangles = 0;
  for (size_t i = 0; i < asset.primitives.size(); ++i) {
    const GltfPrimitive& p = asset.primitives[i];
    const GltfMaterialInfo& m = p.material;
    std::string material = m.name.empty() ? "(none)" : m.name;
    if (m.doubleSided) material += ", double-sided";
    if (m.transmission > 0.0f) material += fmt::format(", transmission {:.2f}", m.transmission);
    if (m.ior != 1.5f) material += fmt::format(", ior {:.3f}", m.ior);
    if (m.hasVolume) material += ", volume";
    out += fmt::format("  {:>3}  {:<{}}  {:<{}}  {:>8}  {:>9}  {:>7}  {}\n", i, p.name, nameWidth, p.part, partWidth,
                       p.mesh.vertexCount(), p.mesh.triangleCount(), movingTargetCount(p), material);
    vertices += p.mesh.vertexCount();
    triangles += p.mesh.triangleCount();
  }
  out += fmt::format("  total: {} vertices, {} triangles ('targets' counts the targets that move a primitive)\n", vertices,
                     triangles);
  return out + describeOpenSurfaces(asset);
}

std::string describeBounds(const GltfAsset& asset) {
  Eigen::AlignedBox3f box;
  for (const GltfPrimitive& p : asset.primitives) box.extend(computeBounds(p.mesh));
  if (box.isEmpty()) return "bounds: empty\n";
  const Vec3 size = box.sizes();
  return fmt::format("bounds (m): x {:.3f}..{:.3f}  y {:.3f}..{:.3f}  z {:.3f}..{:.3f}  (size {:.3f} x {:.3f} x {:.3f})\n",
                     box.min().x(), box.max().x(), box.min().y(), box.max().y(), box.min().z(), box.max().z(),
                     size.x(), size.y(), size.z());
}

std::string describeCameras(const GltfAsset& asset) {
  std::string out = fmt::format("cameras: {}\n", asset.cameras.size());
  for (const GltfCamera& c : asset.cameras) {
    const Vec3 position = c.cameraToAsset.translation();
    const Vec3 forward = -c.cameraToAsset.linear().col(2).normalized();  // glTF cameras look down -Z
    out += fmt::format("  {}: yfov {:.1f} deg, aspect {}, at ({:.3f}, {:.3f}, {:.3f}) looking ({:.2f}, {:.2f}, {:.2f})\n",
                       c.name.empty() ? "(unnamed)" : c.name, c.yfovRadians * 180.0f / kPi,
                       c.aspectRatio > 0.0f ? fmt::format("{:.3f}", c.aspectRatio) : "unspecified", position.x(),
                       position.y(), position.z(), forward.x(), forward.y(), forward.z());
  }
  return out;
}

// One line per animation, then one per channel: what each channel drives and over which keys.
std::string describeAnimations(const GltfAsset& asset) {
  std::string out = fmt::format("animations: {}\n", asset.animations.size());
  for (size_t a = 0; a < asset.animations.size(); ++a) {
    const GltfAnimation& animation = asset.animations[a];
    out += fmt::format("  {}: {}, {} channels, duration {:.3f} s\n", a, animation.name.empty() ? "(unnamed)" : animation.name,
                       animation.channels.size(), animation.duration());
    for (const GltfAnimationChannel& c : animation.channels) {
      const std::string node = c.nodeName.empty() ? fmt::format("node {}", c.node) : c.nodeName;
      const std::string weights = c.path == GltfAnimationPath::Weights ? fmt::format(" ({} targets)", c.valueSize) : "";
      out += fmt::format("    {} {}{}: {} keys {}, {:.3f}..{:.3f} s\n", node, gltfAnimationPathName(c.path), weights,
                         c.times.size(), gltfInterpolationName(c.interpolation), c.times.front(), c.times.back());
    }
  }
  return out;
}

// One line per skin: its joints by node name, and how many primitives it deforms.
std::string describeSkins(const GltfAsset& asset) {
  std::string out = fmt::format("skins: {}\n", asset.skins.size());
  for (size_t s = 0; s < asset.skins.size(); ++s) {
    const GltfSkin& skin = asset.skins[s];
    std::vector<std::string> joints;
    for (const int j : skin.joints) {
      const std::string& name = asset.nodes[size_t(j)].name;
      joints.push_back(name.empty() ? fmt::format("node {}", j) : name);
    }
    const auto deformed = std::count_if(asset.primitives.begin(), asset.primitives.end(),
                                        [&](const GltfPrimitive& p) { return p.skin == int(s); });
    out += fmt::format("  {}: {}, {} joints ({}), {} primitives\n", s, skin.name.empty() ? "(unnamed)" : skin.name,
                       skin.joints.size(), fmt::join(joints, ", "), deformed);
  }
  return out;
}

}  // namespace

std::string describeGltfAsset(const GltfAsset& asset) {
  std::string out = fmt::format("file: {}\n", asset.path.string());
  out += describePrimitives(asset);
  out += fmt::format("morph targets: {}\n", asset.targetNames.size());
  out += wrapNames(asset.targetNames, 2, 100);
  out += describeCameras(asset);
  out += describeBounds(asset);
  out += fmt::format("landmarks: {}\n", asset.landmarks.size());
  out += describeAnimations(asset);
  out += describeSkins(asset);
  if (!asset.warnings.empty()) {
    out += fmt::format("warnings: {}\n", asset.warnings.size());
    for (const std::string& w : asset.warnings) out += "  " + w + "\n";
  }
  return out;
}

}  // namespace lacrima
