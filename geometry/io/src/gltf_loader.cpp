// glTF 2.0 loading: tinygltf parses the file, then everything lacrima reads from it is checked
// against the buffers before it is touched, so a truncated or corrupt file gives an InputError
// that names the file and the problem instead of a crash.
//
// Flattening: the default scene's node tree is walked, each mesh primitive becomes one
// GltfPrimitive in asset space (world transform applied), its morph targets become sparse
// deltas (transformed by the linear part), and smooth normals are computed welded by position.
// Skinned primitives (spec 3.7.3) ignore their node: after the walk, bakeSkinnedRestPoses()
// places them vertex by vertex in the skin's rest pose.
// Animations are read as they are (node-local keys), validated against spec 3.11.
#include <tiny_gltf.h>  // Debian's shared libtinygltf: never define TINYGLTF_IMPLEMENTATION here.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {

namespace fs = std::filesystem;

namespace {

// Node transforms are composed in double so deep hierarchies do not accumulate float error.
using Affine3d = Eigen::Transform<double, 3, Eigen::Affine>;

// A corrupt count must not make us allocate gigabytes before noticing: no real asset has more
// elements than this in one accessor (a 256 M-vertex mesh would not fit in memory anyway).
constexpr uint64_t kMaxAccessorElements = uint64_t(1) << 28;
// Bounds the work on files whose node graph shares subtrees many times over.
constexpr size_t kMaxNodeVisits = 1'000'000;

// ------------------------------------------------------------------------------------------
// Reading the file and the GLB container
// ------------------------------------------------------------------------------------------

[[noreturn]] void failFile(const fs::path& path, const std::string& what) {
  throw InputError(fmt::format("{}: {}", path.string(), what));
}

std::vector<unsigned char> readWholeFile(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) failFile(path, "file not found");
  if (fs::is_directory(status)) failFile(path, "is a directory, not a glTF file");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) failFile(path, "cannot read the file size: " + ec.message());
  // tinygltf takes the size as a 32-bit unsigned (and GLB lengths are 32-bit).
  if (size >= std::numeric_limits<uint32_t>::max()) failFile(path, "file is 4 GB or larger; glTF binaries cannot be");
  std::ifstream in(path, std::ios::binary);
  if (!in) failFile(path, "cannot open the file (permissions?)");
  std::vector<unsigned char> bytes(static_cast<size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size));
  if (!in || in.gcount() != std::streamsize(size)) failFile(path, "read error");
  return bytes;
}

uint32_t readLittleEndianU32(const unsigned char* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

bool hasGlbMagic(const std::vector<unsigned char>& bytes) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

bool looksLikeJson(const std::vector<unsigned char>& bytes) {
  for (unsigned char c : bytes) {
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
    return c == '{';
  }
  return false;
}

// Checks the GLB header and walks its chunks, so that truncation is reported precisely (and
// so tinygltf never sees a BIN chunk that runs past the data: its own check misses the 8-byte
// chunk header). Returns the number of bytes that belong to the GLB.
uint32_t checkGlbContainer(const fs::path& path, const std::vector<unsigned char>& bytes) {
  if (bytes.size() < 12)
    failFile(path, fmt::format("truncated GLB: {} bytes, the header alone needs 12", bytes.size()));
  const uint32_t version = readLittleEndianU32(&bytes[4]);
  const uint32_t length = readLittleEndianU32(&bytes[8]);
  if (version != 2) failFile(path, fmt::format("GLB container version {}; only version 2 is supported", version));
  if (length > bytes.size())
    failFile(path, fmt::format("truncated GLB: the header declares {} bytes but the file has {}", length, bytes.size()));
  if (length < 20) failFile(path, fmt::format("corrupt GLB: declared length {} leaves no room for the JSON chunk", length));

  uint64_t offset = 12;
  for (int chunk = 0; offset < length; ++chunk) {
    if (offset + 8 > length)
      failFile(path, fmt::format("corrupt GLB: chunk {} header at byte {} runs past the end ({} bytes)", chunk, offset, length));
    const uint32_t chunkLength = readLittleEndianU32(&bytes[size_t(offset)]);
    const uint32_t chunkType = readLittleEndianU32(&bytes[size_t(offset) + 4]);
    if (chunk == 0 && chunkType != 0x4E4F534Au)
      failFile(path, "corrupt GLB: the first chunk is not the JSON chunk");
    if (offset + 8 + uint64_t(chunkLength) > length)
      failFile(path, fmt::format("truncated or corrupt GLB: chunk {} ({} bytes at byte {}) runs past the end of the "
                                 "{}-byte file", chunk, chunkLength, offset + 8, length));
    offset += 8 + uint64_t(chunkLength);
  }
  return length;
}

// lacrima takes no textures from glTF files: skipping decoding saves time and keeps stb_image
// away from untrusted bytes.
bool skipImageData(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

tinygltf::Model parseModel(const fs::path& path, std::vector<std::string>& warnings) {
  const std::vector<unsigned char> bytes = readWholeFile(path);
  tinygltf::TinyGLTF parser;
  parser.SetImageLoader(&skipImageData, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    if (hasGlbMagic(bytes)) {
      const uint32_t length = checkGlbContainer(path, bytes);
      if (length < bytes.size()) warnings.push_back(fmt::format("{} bytes after the end of the GLB ignored", bytes.size() - length));
      ok = parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), length, path.parent_path().string());
    } else if (looksLikeJson(bytes)) {
      ok = parser.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                      unsigned(bytes.size()), path.parent_path().string());
    } else {
      failFile(path, "not a glTF file: neither a GLB binary (magic \"glTF\") nor JSON");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {  // tinygltf's JSON parser or an allocation on bogus sizes
    failFile(path, fmt::format("not a valid glTF file: {}", e.what()));
  }
  if (!ok) failFile(path, fmt::format("not a valid glTF file: {}", trimmed(err.empty() ? "unknown tinygltf error" : err)));
  if (!warn.empty()) warnings.push_back("tinygltf: " + trimmed(warn));
  return model;
}

// ------------------------------------------------------------------------------------------
// Accessors
// ------------------------------------------------------------------------------------------

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
    default: return "unknown";
  }
}

int componentSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;  // DOUBLE and INT are not glTF 2.0 accessor types
  }
}

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT4: return 16;  // skin inverse bind matrices (FLOAT: no column padding)
    default: return 0;  // MAT2 / MAT3: nothing lacrima reads
  }
}

// One component as double: exact for every glTF integer type; normalized integers map to
// [0,1] or [-1,1] as the spec says (signed: max(v / (2^(n-1) - 1), -1)).
double decodeComponent(const unsigned char* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const auto v = static_cast<int8_t>(p[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: return 0.0;  // rejected earlier by componentSize()
  }
}

// The sparse part of an accessor: element indices and their tightly packed values.
struct SparseBlock {
  std::vector<uint32_t> indices;
  std::vector<double> values;  // indices.size() * components
};

// Reads, with every byte range checked, the accessors and buffer views of one model.
class AccessorReader {
 public:
  AccessorReader(const fs::path& path, const tinygltf::Model& model) : path_(path), model_(model) {}

  [[noreturn]] void fail(const std::string& what) const { failFile(path_, what); }

  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
      fail(fmt::format("{}: accessor {} does not exist ({} accessors)", what, index, model_.accessors.size()));
    return model_.accessors[size_t(index)];
  }

  // Checks type and component type, returns the element count.
  size_t checkLayout(const tinygltf::Accessor& a, int index, int expectedComponents, bool integerOnly,
                     const std::string& what) const {
    if (componentCount(a.type) != expectedComponents)
      fail(fmt::format("{}: accessor {} has {} components per element, expected {}", what, index,
                       componentCount(a.type), expectedComponents));
    if (componentSize(a.componentType) == 0)
      fail(fmt::format("{}: accessor {} has unsupported componentType {}", what, index, a.componentType));
    if (integerOnly && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || a.normalized ||
                        a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT))
      fail(fmt::format("{}: accessor {} must hold unsigned integers (componentType {})", what, index, a.componentType));
    if (uint64_t(a.count) > kMaxAccessorElements)
      fail(fmt::format("{}: accessor {} claims {} elements, more than lacrima accepts", what, index, a.count));
    return a.count;
  }

  // Start of `count` elements of `elementSize` bytes spaced `stride` apart, from byteOffset in
  // a buffer view; fails unless the whole range lies inside the view and the view in its buffer.
  const unsigned char* checkedRange(int viewIndex, uint64_t byteOffset, uint64_t elementSize, uint64_t stride,
                                    uint64_t count, const std::string& what) const {
    const tinygltf::BufferView& view = bufferView(viewIndex, what);
    if (count == 0) return nullptr;
    if (byteOffset > view.byteLength)
      fail(fmt::format("{}: byteOffset {} lies beyond the {} bytes of bufferView {}", what, byteOffset, view.byteLength, viewIndex));
    // No overflow: byteOffset < 2^64 is now bounded by the buffer, count <= 2^28, stride <= 2^8.
    const uint64_t end = byteOffset + (count - 1) * stride + elementSize;
    if (end > view.byteLength)
      fail(fmt::format("{}: reads bytes {}..{} of bufferView {}, which has only {} bytes (truncated or corrupt file)",
                       what, byteOffset, end, viewIndex, view.byteLength));
    return model_.buffers[size_t(view.buffer)].data.data() + view.byteOffset + byteOffset;
  }

  // Dense values (count * components, as double) with the sparse substitution applied.
  // An accessor without bufferView is all zeros before substitution (glTF 2.0, 3.6.2.3).
  std::vector<double> readDense(int index, int components, bool integerOnly, const std::string& what) const {
    const tinygltf::Accessor& a = accessor(index, what);
    const size_t count = checkLayout(a, index, components, integerOnly, what);
    std::vector<double> values(count * size_t(components), 0.0);
    if (a.bufferView >= 0) readElements(a, index, components, values.data(), what);
    if (a.sparse.isSparse) {
      const SparseBlock sparse = readSparse(a, index, components, what);
      for (size_t i = 0; i < sparse.indices.size(); ++i)
        std::copy_n(&sparse.values[i * size_t(components)], components, &values[sparse.indices[i] * size_t(components)]);
    }
    return values;
  }

  SparseBlock readSparse(const tinygltf::Accessor& a, int index, int components, const std::string& what) const {
    const auto& s = a.sparse;
    const std::string where = fmt::format("{}: sparse block of accessor {}", what, index);
    if (s.count < 0 || size_t(s.count) > a.count)
      fail(fmt::format("{}: count {} is outside 0..{}", where, s.count, a.count));
    if (s.indices.byteOffset < 0 || s.values.byteOffset < 0) fail(where + ": negative byteOffset");
    const int indexSize = componentSize(s.indices.componentType);
    if (indexSize == 0 || s.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        s.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE || s.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT)
      fail(fmt::format("{}: indices componentType {} is not an unsigned integer type", where, s.indices.componentType));

    SparseBlock block;
    const uint64_t n = uint64_t(s.count);
    const unsigned char* indexBytes =
        checkedRange(s.indices.bufferView, uint64_t(s.indices.byteOffset), uint64_t(indexSize), uint64_t(indexSize), n, where + " indices");
    block.indices.resize(size_t(n));
    for (size_t i = 0; i < n; ++i) {
      const double v = decodeComponent(indexBytes + i * size_t(indexSize), s.indices.componentType, false);
      if (v >= double(a.count)) fail(fmt::format("{}: index {} is {}, but the accessor has {} elements", where, i, v, a.count));
      block.indices[i] = uint32_t(v);
    }
    const size_t elementSize = size_t(componentSize(a.componentType)) * size_t(components);
    const unsigned char* valueBytes =
        checkedRange(s.values.bufferView, uint64_t(s.values.byteOffset), elementSize, elementSize, n, where + " values");
    block.values.resize(size_t(n) * size_t(components));
    for (size_t i = 0; i < block.values.size(); ++i)
      block.values[i] = decodeComponent(valueBytes + i * size_t(componentSize(a.componentType)), a.componentType, a.normalized);
    return block;
  }

 private:
  const tinygltf::BufferView& bufferView(int viewIndex, const std::string& what) const {
    if (viewIndex < 0 || size_t(viewIndex) >= model_.bufferViews.size())
      fail(fmt::format("{}: bufferView {} does not exist ({} buffer views)", what, viewIndex, model_.bufferViews.size()));
    const tinygltf::BufferView& view = model_.bufferViews[size_t(viewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
      fail(fmt::format("{}: bufferView {} refers to buffer {}, which does not exist", what, viewIndex, view.buffer));
    const size_t bufferSize = model_.buffers[size_t(view.buffer)].data.size();
    if (view.byteOffset > bufferSize || view.byteLength > bufferSize - view.byteOffset)
      fail(fmt::format("{}: bufferView {} spans bytes {}..{} of buffer {}, which has only {} bytes (truncated or corrupt file)",
                       what, viewIndex, view.byteOffset, uint64_t(view.byteOffset) + view.byteLength, view.buffer, bufferSize));
    return view;
  }

  void readElements(const tinygltf::Accessor& a, int index, int components, double* out, const std::string& what) const {
    const int size = componentSize(a.componentType);
    const uint64_t elementSize = uint64_t(size) * uint64_t(components);
    const tinygltf::BufferView& view = bufferView(a.bufferView, what);
    const uint64_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize || stride % uint64_t(size) != 0)
      fail(fmt::format("{}: accessor {} has byteStride {} for {}-byte elements", what, index, stride, elementSize));
    const unsigned char* base = checkedRange(a.bufferView, a.byteOffset, elementSize, stride, a.count,
                                             fmt::format("{} (accessor {})", what, index));
    for (size_t e = 0; e < a.count; ++e)
      for (int c = 0; c < components; ++c)
        out[e * size_t(components) + size_t(c)] = decodeComponent(base + e * stride + size_t(c * size), a.componentType, a.normalized);
  }

  const fs::path& path_;
  const tinygltf::Model& model_;
};

// ------------------------------------------------------------------------------------------
// Values from extras / extensions
// ------------------------------------------------------------------------------------------

std::string stringExtra(const tinygltf::Value& extras, const std::string& key) {
  if (!extras.IsObject() || !extras.Has(key)) return {};
  const tinygltf::Value& v = extras.Get(key);
  return v.IsString() ? v.Get<std::string>() : std::string();
}

float numberOr(const tinygltf::Value& object, const std::string& key, float fallback) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? float(v.GetNumberAsDouble()) : fallback;
}

Affine3d toAffine(const Eigen::Matrix4d& m) {
  Affine3d a = Affine3d::Identity();
  a.matrix().topRows<3>() = m.topRows<3>();
  return a;
}

const char* accessorTypeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "unknown";
  }
}

// ------------------------------------------------------------------------------------------
// Flattening the scene
// ------------------------------------------------------------------------------------------

class SceneFlattener {
 public:
  SceneFlattener(const fs::path& path, const tinygltf::Model& model, GltfAsset& asset)
      : path_(path), model_(model), asset_(asset), reader_(path, model) {}

  void run() {
    rejectUnsupportedExtensions();
    for (const tinygltf::Node& node : model_.nodes) {
      asset_.nodeNames.push_back(node.name);
      GltfNode out;
      out.name = node.name;
      out.mesh = node.mesh;
      asset_.nodes.push_back(std::move(out));
    }
    visited_.assign(model_.nodes.size(), false);
    warnedParents_.assign(model_.nodes.size(), false);
    restWorld_.assign(model_.nodes.size(), Affine3d::Identity());
    readSkins();
    std::vector<bool> onPath(model_.nodes.size(), false);
    for (int root : sceneRoots()) visitNode(root, -1, Affine3d::Identity(), onPath, "scene root");
    for (GltfPrimitive& p : asset_.primitives) p.targets.resize(asset_.targetNames.size());
    bakeSkinnedRestPoses();
    readLandmarks();
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { failFile(path_, what); }

  // Compressed geometry cannot be read at all; quantized attributes are decoded by
  // decodeComponent; material extensions only change looks, which the shot file decides anyway.
  void rejectUnsupportedExtensions() const {
    for (const std::string& ext : model_.extensionsRequired) {
      if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression")
        fail(fmt::format("requires the extension {}, which lacrima does not support (export without compression)", ext));
      if (ext != "KHR_mesh_quantization" && !ext.starts_with("KHR_materials_"))
        asset_.warnings.push_back(fmt::format("required extension {} is ignored", ext));
    }
  }

  // The default scene's roots; scene 0 when none is marked default; else every parentless node.
  std::vector<int> sceneRoots() {
    if (!model_.scenes.empty()) {
      int scene = model_.defaultScene;
      if (scene < 0 || size_t(scene) >= model_.scenes.size()) {
        if (scene >= 0) fail(fmt::format("default scene {} does not exist ({} scenes)", scene, model_.scenes.size()));
        scene = 0;
      }
      return model_.scenes[size_t(scene)].nodes;
    }
    std::vector<bool> isChild(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes)
      for (int c : node.children)
        if (c >= 0 && size_t(c) < isChild.size()) isChild[size_t(c)] = true;
    std::vector<int> roots;
    for (size_t i = 0; i < model_.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(int(i));
    return roots;
  }

  Affine3d localTransform(const tinygltf::Node& node, int index) const {
    const auto allFinite = [](const std::vector<double>& v) {
      return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    };
    if (!allFinite(node.matrix) || !allFinite(node.translation) || !allFinite(node.rotation) || !allFinite(node.scale))
      fail(fmt::format("node {} ('{}') has a non-finite transform", index, node.name));
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(fmt::format("node {} ('{}'): matrix has {} numbers, expected 16", index, node.name, node.matrix.size()));
      return toAffine(Eigen::Map<const Eigen::Matrix4d>(node.matrix.data()));  // glTF matrices are column-major, like Eigen
    }
    Affine3d t = Affine3d::Identity();
    if (!node.translation.empty()) {
      if (node.translation.size() != 3) fail(fmt::format("node {} ('{}'): translation needs 3 numbers", index, node.name));
      t.translate(Vec3d(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (!node.rotation.empty()) {
      if (node.rotation.size() != 4) fail(fmt::format("node {} ('{}'): rotation needs 4 numbers", index, node.name));
      Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);  // glTF: x y z w
      if (q.norm() == 0.0) fail(fmt::format("node {} ('{}'): rotation quaternion is zero", index, node.name));
      t.rotate(q.normalized());
    }
    if (!node.scale.empty()) {
      if (node.scale.size() != 3) fail(fmt::format("node {} ('{}'): scale needs 3 numbers", index, node.name));
      t.scale(Vec3d(node.scale[0], node.scale[1], node.scale[2]));
    }
    return t;  // T * R * S, as glTF specifies
  }

  // The rest pose of a node for animation playback (localTransform has checked its numbers).
  void recordRestPose(const tinygltf::Node& node, GltfNode& out, const Affine3d& local) const {
    out.matrix = local.cast<float>();
    out.hasMatrix = !node.matrix.empty();
    if (out.hasMatrix) return;
    if (!node.translation.empty())
      out.trs.translation = Vec3(float(node.translation[0]), float(node.translation[1]), float(node.translation[2]));
    if (!node.rotation.empty())
      out.trs.rotation = Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])
                             .normalized()
                             .cast<float>();
    if (!node.scale.empty()) out.trs.scale = Vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2]));
  }

  void visitNode(int index, int parentIndex, const Affine3d& parent, std::vector<bool>& onPath,
                 const std::string& referrer) {
    if (index < 0 || size_t(index) >= model_.nodes.size())
      fail(fmt::format("{} refers to node {}, which does not exist ({} nodes)", referrer, index, model_.nodes.size()));
    if (onPath[size_t(index)]) fail(fmt::format("node {} is its own ancestor (cycle in the node hierarchy)", index));
    if (++visits_ > kMaxNodeVisits) fail("node hierarchy is too large (shared subtrees expand to over a million nodes)");
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    const Affine3d local = localTransform(node, index);
    const Affine3d world = parent * local;
    GltfNode& record = asset_.nodes[size_t(index)];
    if (!visited_[size_t(index)]) {
      visited_[size_t(index)] = true;
      record.parent = parentIndex;
      recordRestPose(node, record, local);
      restWorld_[size_t(index)] = world;
    } else if (record.parent != parentIndex && !warnedParents_[size_t(index)]) {
      warnedParents_[size_t(index)] = true;
      asset_.warnings.push_back(fmt::format("node {} ('{}') has more than one parent (not valid glTF); animations "
                                            "move all its instances as the one under node {}",
                                            index, node.name, record.parent));
    }
    if (node.mesh >= 0) addMeshInstance(node, index, world);
    if (node.camera >= 0) addCamera(node, index, world);
    onPath[size_t(index)] = true;
    for (int child : node.children)
      visitNode(child, index, world, onPath, fmt::format("node {} ('{}')", index, node.name));
    onPath[size_t(index)] = false;
  }

  void addCamera(const tinygltf::Node& node, int index, const Affine3d& world) {
    if (size_t(node.camera) >= model_.cameras.size())
      fail(fmt::format("node {} ('{}') refers to camera {}, which does not exist", index, node.name, node.camera));
    const tinygltf::Camera& camera = model_.cameras[size_t(node.camera)];
    const std::string name = !camera.name.empty() ? camera.name : node.name;
    if (camera.type != "perspective") {
      asset_.warnings.push_back(fmt::format("camera '{}' is {}; only perspective cameras are loaded", name, camera.type));
      return;
    }
    const double yfov = camera.perspective.yfov;
    if (!(yfov > 0.0 && yfov < std::numbers::pi))
      fail(fmt::format("camera '{}': yfov {} is not in (0, pi) radians", name, yfov));
    GltfCamera out;
    out.name = name;
    out.cameraToAsset = world.cast<float>();
    out.yfovRadians = float(yfov);
    const double aspect = camera.perspective.aspectRatio;
    out.aspectRatio = (aspect > 0.0 && std::isfinite(aspect)) ? float(aspect) : 0.0f;
    asset_.cameras.push_back(out);
  }

  GltfMaterialInfo readMaterial(int index, const std::string& what) const {
    GltfMaterialInfo info;
    if (index < 0) return info;
    if (size_t(index) >= model_.materials.size()) fail(fmt::format("{}: material {} does not exist", what, index));
    const tinygltf::Material& m = model_.materials[size_t(index)];
    info.name = m.name;
    info.doubleSided = m.doubleSided;
    // tinygltf fills pbrMetallicRoughness with spec defaults (white metal) even when the block is
    // absent; its legacy `values` map tells whether the file had any factor at all.
    info.hasPbrFactors = !m.values.empty();
    if (info.hasPbrFactors) {
      const auto& pbr = m.pbrMetallicRoughness;
      if (pbr.baseColorFactor.size() >= 3)
        info.baseColor = Color(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]), float(pbr.baseColorFactor[2]));
      info.roughness = float(pbr.roughnessFactor);
      info.metallic = float(pbr.metallicFactor);
    }
    if (auto it = m.extensions.find("KHR_materials_transmission"); it != m.extensions.end())
      info.transmission = numberOr(it->second, "transmissionFactor", 0.0f);
    if (auto it = m.extensions.find("KHR_materials_ior"); it != m.extensions.end())
      info.ior = numberOr(it->second, "ior", 1.5f);
    info.hasVolume = m.extensions.contains("KHR_materials_volume");
    if (!isFinite(info.baseColor) || !std::isfinite(info.roughness) || !std::isfinite(info.metallic) ||
        !std::isfinite(info.transmission) || !std::isfinite(info.ior))
      fail(fmt::format("material {} ('{}') has a non-finite factor", index, m.name));
    return info;
  }

  // Global morph target indices of one mesh's targets, registering new names. A target is
  // identified by name across meshes, so one weight vector drives every mesh of the asset.
  const std::vector<int>& targetSlots(int meshIndex) {
    if (auto it = targetSlotsByMesh_.find(meshIndex); it != targetSlotsByMesh_.end()) return it->second;
    const tinygltf::Mesh& mesh = model_.meshes[size_t(meshIndex)];
    const size_t count = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    std::vector<std::string> names = targetNamesOf(mesh, meshIndex, count);
    std::vector<int> slots;
    std::set<std::string> seen;
    for (const std::string& name : names) {
      if (!seen.insert(name).second) fail(fmt::format("mesh {} ('{}'): morph target name '{}' appears twice", meshIndex, mesh.name, name));
      auto [it, inserted] = targetIndex_.try_emplace(name, int(asset_.targetNames.size()));
      if (inserted) asset_.targetNames.push_back(name);
      slots.push_back(it->second);
    }
    return targetSlotsByMesh_[meshIndex] = std::move(slots);
  }

  std::vector<std::string> targetNamesOf(const tinygltf::Mesh& mesh, int meshIndex, size_t count) {
    const tinygltf::Value& extras = mesh.extras;
    if (extras.IsObject() && extras.Has("targetNames")) {
      const tinygltf::Value& list = extras.Get("targetNames");
      bool usable = list.IsArray() && list.ArrayLen() == count;
      std::vector<std::string> names;
      for (size_t i = 0; usable && i < count; ++i) {
        const tinygltf::Value& v = list.Get(int(i));
        usable = v.IsString();
        if (usable) names.push_back(v.Get<std::string>());
      }
      if (usable) return names;
      asset_.warnings.push_back(fmt::format("mesh {} ('{}'): extras.targetNames is not {} strings; targets named target<k>",
                                            meshIndex, mesh.name, count));
    }
    std::vector<std::string> names;
    for (size_t i = 0; i < count; ++i) names.push_back(fmt::format("target{}", i));
    return names;
  }

  void addMeshInstance(const tinygltf::Node& node, int nodeIndex, const Affine3d& world) {
    if (size_t(node.mesh) >= model_.meshes.size())
      fail(fmt::format("node {} ('{}') refers to mesh {}, which does not exist", nodeIndex, node.name, node.mesh));
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    if (node.skin >= 0 && size_t(node.skin) >= asset_.skins.size())
      fail(fmt::format("node {} ('{}') refers to skin {}, which does not exist ({} skins)", nodeIndex, node.name, node.skin,
                       asset_.skins.size()));
    if (node.skin < 0 && std::abs(world.linear().determinant()) < 1e-30) {
      asset_.warnings.push_back(fmt::format("node {} ('{}') has a singular transform; its mesh is skipped", nodeIndex, node.name));
      return;
    }
    for (const tinygltf::Primitive& p : mesh.primitives) {
      if (p.targets.size() != mesh.primitives[0].targets.size())
        fail(fmt::format("mesh {} ('{}'): primitives have different numbers of morph targets", node.mesh, mesh.name));
    }
    const std::vector<int>& slots = targetSlots(node.mesh);
    asset_.nodes[size_t(nodeIndex)].targetSlots = slots;
    firstPrimitiveOfNode_.try_emplace(nodeIndex, asset_.primitives.size());
    for (size_t k = 0; k < mesh.primitives.size(); ++k) {
      // Spec 3.7.3: a skinned mesh ignores its node's transform; bakeSkinnedRestPoses() places
      // it once every joint's rest world transform is known.
      asset_.primitives.push_back(flattenPrimitive(mesh, node.mesh, k, node.skin >= 0 ? Affine3d::Identity() : world,
                                                   slots, node.skin));
      asset_.primitives.back().node = nodeIndex;
    }
  }

  GltfPrimitive flattenPrimitive(const tinygltf::Mesh& mesh, int meshIndex, size_t k, const Affine3d& world,
                                 const std::vector<int>& slots, int skin) {
    const tinygltf::Primitive& p = mesh.primitives[k];
    GltfPrimitive out;
    const std::string what = fmt::format("primitive {} of mesh {} ('{}')", k, meshIndex, mesh.name);
    if (p.mode != -1 && p.mode != TINYGLTF_MODE_TRIANGLES)
      fail(fmt::format("{} has mode {} ({}); lacrima renders triangles only", what, modeName(p.mode), p.mode));
    out.material = readMaterial(p.material, what);
    out.part = stringExtra(p.extras, "part");
    if (out.part.empty()) out.part = out.material.name;
    const std::string meshName = mesh.name.empty() ? fmt::format("mesh{}", meshIndex) : mesh.name;
    out.name = meshName + "/" + (out.part.empty() ? std::to_string(k) : out.part);
    out.mesh.name = out.name;
    out.nodeTransform = world.cast<float>();

    readVertices(p, out.mesh, what + " '" + out.part + "'");
    if (skin >= 0) {
      // Still in mesh space: defects are checked here, welding and normals after baking.
      if (std::string defect = findMeshDefect(out.mesh); !defect.empty()) fail(fmt::format("{}: {}", what, defect));
      readSkinAttributes(p, skin, out, what + " '" + out.part + "'");
    } else {
      transformMesh(out.mesh, out.nodeTransform);  // also flips the winding of mirrored instances
      if (std::string defect = findMeshDefect(out.mesh); !defect.empty()) fail(fmt::format("{}: {}", what, defect));
      out.weldMap = findCoincidentVertices(out.mesh);
      computeSmoothNormals(out.mesh, out.weldMap);
    }

    const Mat3 linear = out.nodeTransform.linear();
    // Asset-wide slots can exceed this mesh's target count (a later mesh adds new names); run()
    // pads every primitive to the final targetNames.size() afterwards.
    out.targets.resize(slots.empty() ? 0 : size_t(*std::max_element(slots.begin(), slots.end())) + 1);
    for (size_t t = 0; t < p.targets.size(); ++t)
      out.targets[size_t(slots[t])] = readMorphTarget(p.targets[t], out.mesh.vertexCount(), linear,
                                                      fmt::format("{} '{}', morph target {}", what, out.part, t));
    return out;
  }

  // ----------------------------------------------------------------------------------------
  // Skins (spec 3.7.3)
  // ----------------------------------------------------------------------------------------

  // Every skin of the file: joints must be nodes, inverse bind matrices MAT4 FLOAT, one per
  // joint, finite and invertible-looking (affine bottom row); identity when absent.
  void readSkins() {
    for (size_t s = 0; s < model_.skins.size(); ++s) {
      const tinygltf::Skin& skin = model_.skins[s];
      const std::string what = fmt::format("skin {} ('{}')", s, skin.name);
      GltfSkin out;
      out.name = skin.name;
      if (skin.joints.empty()) fail(what + ": has no joints");
      for (size_t j = 0; j < skin.joints.size(); ++j) {
        const int node = skin.joints[j];
        if (node < 0 || size_t(node) >= model_.nodes.size())
          fail(fmt::format("{}: joint {} is node {}, which does not exist ({} nodes)", what, j, node, model_.nodes.size()));
        out.joints.push_back(node);
      }
      out.inverseBindMatrices.assign(out.joints.size(), Affine3::Identity());
      if (skin.inverseBindMatrices >= 0) {
        const std::string ibmWhat = what + " inverseBindMatrices";
        const tinygltf::Accessor& a = reader_.accessor(skin.inverseBindMatrices, ibmWhat);
        if (a.type != TINYGLTF_TYPE_MAT4 || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
          fail(fmt::format("{}: accessor {} is {} with componentType {}; expected MAT4 FLOAT (5126)", ibmWhat,
                           skin.inverseBindMatrices, accessorTypeName(a.type), a.componentType));
        if (a.count != out.joints.size())
          fail(fmt::format("{}: accessor {} has {} matrices for {} joints", ibmWhat, skin.inverseBindMatrices, a.count,
                           out.joints.size()));
        const std::vector<double> m = reader_.readDense(skin.inverseBindMatrices, 16, false, ibmWhat);
        for (size_t j = 0; j < out.joints.size(); ++j) {
          const Eigen::Map<const Eigen::Matrix4d> matrix(&m[16 * j]);  // column-major, like Eigen
          if (!matrix.allFinite()) fail(fmt::format("{}: matrix {} has a non-finite value", ibmWhat, j));
          out.inverseBindMatrices[j] = toAffine(matrix).cast<float>();
        }
      }
      asset_.skins.push_back(std::move(out));
    }
  }

  // JOINTS_0 (VEC4 unsigned byte / short, each < the skin's joint count) and WEIGHTS_0 (VEC4
  // FLOAT or normalized unsigned byte / short, non-negative, finite, not all zero; normalized to
  // sum 1) of a primitive whose node has `skin`.
  void readSkinAttributes(const tinygltf::Primitive& p, int skin, GltfPrimitive& out, const std::string& what) {
    const size_t vertexCount = out.mesh.vertexCount();
    const GltfSkin& s = asset_.skins[size_t(skin)];
    const std::string skinWhat = fmt::format("skin {} ('{}')", skin, s.name);
    auto joints = p.attributes.find("JOINTS_0");
    auto weights = p.attributes.find("WEIGHTS_0");
    if (joints == p.attributes.end() || weights == p.attributes.end())
      fail(fmt::format("{}: its node has {} but the primitive has no {}", what, skinWhat,
                       joints == p.attributes.end() ? "JOINTS_0" : "WEIGHTS_0"));
    if (p.attributes.contains("JOINTS_1") || p.attributes.contains("WEIGHTS_1"))
      asset_.warnings.push_back(fmt::format("{}: JOINTS_1 / WEIGHTS_1 ignored; only the first four joint influences "
                                            "(JOINTS_0 / WEIGHTS_0) are used", what));

    const std::string jointsWhat = what + " JOINTS_0";
    const tinygltf::Accessor& ja = reader_.accessor(joints->second, jointsWhat);
    if (ja.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && ja.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
      fail(fmt::format("{}: accessor {} has componentType {}; expected unsigned byte (5121) or unsigned short (5123)",
                       jointsWhat, joints->second, ja.componentType));
    const std::vector<double> j = reader_.readDense(joints->second, 4, true, jointsWhat);
    if (j.size() / 4 != vertexCount)
      fail(fmt::format("{}: {} elements for {} vertices", jointsWhat, j.size() / 4, vertexCount));

    const std::string weightsWhat = what + " WEIGHTS_0";
    const tinygltf::Accessor& wa = reader_.accessor(weights->second, weightsWhat);
    const bool normalizedInteger = (wa.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                    wa.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) && wa.normalized;
    if (wa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedInteger)
      fail(fmt::format("{}: accessor {} has componentType {}{}; expected FLOAT or normalized unsigned byte / short",
                       weightsWhat, weights->second, wa.componentType, wa.normalized ? "" : " without normalized"));
    const std::vector<double> w = reader_.readDense(weights->second, 4, false, weightsWhat);
    if (w.size() / 4 != vertexCount)
      fail(fmt::format("{}: {} elements for {} vertices", weightsWhat, w.size() / 4, vertexCount));

    out.skin = skin;
    out.skinJoints.resize(vertexCount);
    out.skinWeights.resize(vertexCount);
    for (size_t v = 0; v < vertexCount; ++v) {
      double sum = 0.0;
      for (size_t c = 0; c < 4; ++c) {
        const double joint = j[4 * v + c];
        if (joint >= double(s.joints.size()))
          fail(fmt::format("{}: vertex {} names joint {}, but {} has {} joints", jointsWhat, v, joint, skinWhat,
                           s.joints.size()));
        out.skinJoints[v][c] = uint16_t(joint);
        const double weight = w[4 * v + c];
        if (!std::isfinite(weight)) fail(fmt::format("{}: vertex {} has a non-finite weight", weightsWhat, v));
        if (weight < 0.0) fail(fmt::format("{}: vertex {} has a negative weight {}", weightsWhat, v, weight));
        sum += weight;
      }
      if (!(sum > 0.0)) fail(fmt::format("{}: vertex {} has all weights zero", weightsWhat, v));
      for (size_t c = 0; c < 4; ++c) out.skinWeights[v][int(c)] = float(w[4 * v + c] / sum);
    }
  }

  // After the scene walk, when every joint's rest world transform is known: each skinned
  // primitive goes from mesh space to its rest pose in asset space, vertex by vertex, and its
  // morph deltas follow the linear part of their vertex's skin matrix.
  void bakeSkinnedRestPoses() {
    std::vector<std::vector<Affine3d>> rest(asset_.skins.size());
    for (GltfPrimitive& p : asset_.primitives) {
      if (p.skin < 0) continue;
      GltfSkin& skin = asset_.skins[size_t(p.skin)];
      std::vector<Affine3d>& joints = rest[size_t(p.skin)];
      if (joints.empty()) {
        for (size_t j = 0; j < skin.joints.size(); ++j) {
          const int node = skin.joints[j];
          if (!visited_[size_t(node)])
            fail(fmt::format("skin {} ('{}'): joint {} is node {} ('{}'), which is not in the default scene", p.skin,
                             skin.name, j, node, model_.nodes[size_t(node)].name));
          joints.push_back(restWorld_[size_t(node)] * skin.inverseBindMatrices[j].cast<double>());
        }
        skin.restJointMatrices.clear();
        for (const Affine3d& m : joints) skin.restJointMatrices.push_back(m.cast<float>());
      }
      std::vector<Eigen::Matrix3d> linear(p.mesh.vertexCount());
      for (size_t v = 0; v < p.mesh.vertexCount(); ++v) {
        Eigen::Matrix<double, 3, 4> m = Eigen::Matrix<double, 3, 4>::Zero();
        for (int c = 0; c < 4; ++c)
          if (p.skinWeights[v][c] != 0.0f)
            m += double(p.skinWeights[v][c]) * joints[p.skinJoints[v][size_t(c)]].matrix().topRows<3>();
        linear[v] = m.leftCols<3>();
        if (!(std::abs(linear[v].determinant()) > 1e-30))
          fail(fmt::format("{}: vertex {} has a singular rest skin matrix (skin {} ('{}'))", p.name, v, p.skin, skin.name));
        p.mesh.positions[v] = (linear[v] * p.mesh.positions[v].cast<double>() + m.col(3)).cast<float>();
      }
      for (SparseDelta& target : p.targets)
        for (size_t i = 0; i < target.vertices.size(); ++i)
          target.deltas[i] = (linear[target.vertices[i]] * target.deltas[i].cast<double>()).cast<float>();
      // As transformMesh does for mirrored node transforms: a triangle whose corners are mostly
      // mirrored by the rest skin gets its winding flipped back.
      for (size_t t = 0; t + 2 < p.mesh.indices.size(); t += 3) {
        int mirrored = 0;
        for (size_t c = 0; c < 3; ++c) mirrored += linear[p.mesh.indices[t + c]].determinant() < 0.0 ? 1 : 0;
        if (mirrored >= 2) std::swap(p.mesh.indices[t + 1], p.mesh.indices[t + 2]);
      }
      p.weldMap = findCoincidentVertices(p.mesh);
      computeSmoothNormals(p.mesh, p.weldMap);
    }
  }

  // Positions, uvs and indices in the file's space. Normals are always recomputed (welded,
  // area-weighted) so that the neutral face and every morphed face are shaded the same way.
  void readVertices(const tinygltf::Primitive& p, TriangleMesh& mesh, const std::string& what) const {
    auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) fail(what + ": has no POSITION attribute");
    const std::vector<double> xyz = reader_.readDense(position->second, 3, false, what + " POSITION");
    mesh.positions.resize(xyz.size() / 3);
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      mesh.positions[v] = Vec3(float(xyz[3 * v]), float(xyz[3 * v + 1]), float(xyz[3 * v + 2]));

    if (auto uv = p.attributes.find("TEXCOORD_0"); uv != p.attributes.end()) {
      const std::vector<double> st = reader_.readDense(uv->second, 2, false, what + " TEXCOORD_0");
      if (st.size() / 2 != mesh.positions.size())
        fail(fmt::format("{}: TEXCOORD_0 has {} elements for {} vertices", what, st.size() / 2, mesh.positions.size()));
      mesh.uvs.resize(mesh.positions.size());
      for (size_t v = 0; v < mesh.uvs.size(); ++v) mesh.uvs[v] = Vec2(float(st[2 * v]), float(st[2 * v + 1]));
    }

    if (p.indices >= 0) {
      const std::vector<double> idx = reader_.readDense(p.indices, 1, true, what + " indices");
      mesh.indices.resize(idx.size());
      for (size_t i = 0; i < idx.size(); ++i) {
        if (idx[i] >= double(mesh.positions.size()))
          fail(fmt::format("{}: index {} is {}, but there are only {} vertices", what, i, idx[i], mesh.positions.size()));
        mesh.indices[i] = uint32_t(idx[i]);
      }
    } else {  // non-indexed: every three consecutive vertices form a triangle
      mesh.indices.resize(mesh.positions.size());
      std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
    }
    if (mesh.indices.size() % 3 != 0)
      fail(fmt::format("{}: {} indices is not a multiple of 3", what, mesh.indices.size()));
  }

  // The POSITION deltas of one target, kept sparse. Sparse accessors without a bufferView are
  // read straight from their sparse block; dense ones are scanned for non-zero deltas.
  SparseDelta readMorphTarget(const std::map<std::string, int>& target, size_t vertexCount, const Mat3& linear,
                              const std::string& what) const {
    SparseDelta out;
    auto position = target.find("POSITION");
    if (position == target.end()) return out;  // NORMAL/TANGENT-only targets: normals are recomputed anyway
    const tinygltf::Accessor& a = reader_.accessor(position->second, what);
    reader_.checkLayout(a, position->second, 3, false, what);
    if (a.count != vertexCount)
      fail(fmt::format("{}: POSITION accessor {} has {} elements for {} vertices", what, position->second, a.count, vertexCount));

    std::vector<std::pair<uint32_t, Vec3>> moved;
    if (a.bufferView < 0 && a.sparse.isSparse) {
      const SparseBlock block = reader_.readSparse(a, position->second, 3, what);
      for (size_t i = 0; i < block.indices.size(); ++i)
        moved.emplace_back(block.indices[i], Vec3(float(block.values[3 * i]), float(block.values[3 * i + 1]), float(block.values[3 * i + 2])));
      // glTF requires strictly increasing sparse indices; accept any order, later entries win.
      std::stable_sort(moved.begin(), moved.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
      for (size_t i = 0; i + 1 < moved.size();) {
        if (moved[i].first == moved[i + 1].first) moved.erase(moved.begin() + ptrdiff_t(i));
        else ++i;
      }
    } else if (a.bufferView >= 0) {
      const std::vector<double> xyz = reader_.readDense(position->second, 3, false, what);
      for (size_t v = 0; v < vertexCount; ++v)
        moved.emplace_back(uint32_t(v), Vec3(float(xyz[3 * v]), float(xyz[3 * v + 1]), float(xyz[3 * v + 2])));
    }  // else: no bufferView, no sparse block: the target does not move this primitive

    for (const auto& [vertex, delta] : moved) {
      if (!delta.allFinite()) fail(fmt::format("{}: vertex {} has a non-finite delta", what, vertex));
      if (delta.isZero(0.0f)) continue;  // keep only the vertices the target moves
      out.vertices.push_back(vertex);
      out.deltas.push_back(linear * delta);  // a displacement transforms by the linear part only
    }
    return out;
  }

  // nodes[0].extras.landmarks68: [{primitive, vertex, ...}, ...] with primitive indexing the
  // primitives of node 0's mesh.
  void readLandmarks() {
    if (model_.nodes.empty()) return;
    const tinygltf::Value& extras = model_.nodes[0].extras;
    if (!extras.IsObject() || !extras.Has("landmarks68")) return;
    const tinygltf::Value& list = extras.Get("landmarks68");
    const std::string where = "nodes[0].extras.landmarks68";
    if (!list.IsArray()) fail(where + " is not an array");
    auto first = firstPrimitiveOfNode_.find(0);
    if (first == firstPrimitiveOfNode_.end()) {
      asset_.warnings.push_back(where + " ignored: node 0 has no mesh in the default scene");
      return;
    }
    const size_t primitiveCount = model_.meshes[size_t(model_.nodes[0].mesh)].primitives.size();
    for (size_t i = 0; i < list.ArrayLen(); ++i) {
      const tinygltf::Value& entry = list.Get(int(i));
      const auto integer = [&](const char* key) {
        if (!entry.IsObject() || !entry.Has(key) || !entry.Get(key).IsNumber())
          fail(fmt::format("{}[{}] has no numeric '{}'", where, i, key));
        const double v = entry.Get(key).GetNumberAsDouble();
        if (!(v >= 0.0 && v < 4294967296.0) || v != std::floor(v))
          fail(fmt::format("{}[{}].{} = {} is not a non-negative integer", where, i, key, v));
        return uint64_t(v);
      };
      const uint64_t primitive = integer("primitive");
      const uint64_t vertex = integer("vertex");
      if (primitive >= primitiveCount)
        fail(fmt::format("{}[{}]: primitive {} does not exist (node 0's mesh has {})", where, i, primitive, primitiveCount));
      const size_t flat = first->second + size_t(primitive);
      if (vertex >= asset_.primitives[flat].mesh.vertexCount())
        fail(fmt::format("{}[{}]: vertex {} is out of range ({} has {} vertices)", where, i, vertex,
                         asset_.primitives[flat].part, asset_.primitives[flat].mesh.vertexCount()));
      asset_.landmarks.push_back(Landmark{int(i), int(flat), uint32_t(vertex)});
    }
  }

  const fs::path& path_;
  const tinygltf::Model& model_;
  GltfAsset& asset_;
  AccessorReader reader_;
  size_t visits_ = 0;
  std::vector<bool> visited_;  // per node: met while walking the default scene
  std::vector<bool> warnedParents_;  // per node: the "more than one parent" warning was given
  std::vector<Affine3d> restWorld_;  // per node met in the walk: its rest world transform
  std::unordered_map<std::string, int> targetIndex_;
  std::unordered_map<int, std::vector<int>> targetSlotsByMesh_;
  std::unordered_map<int, size_t> firstPrimitiveOfNode_;
};

// ------------------------------------------------------------------------------------------
// Animations (spec 3.11)
// ------------------------------------------------------------------------------------------

std::optional<GltfAnimationPath> parseAnimationPath(const std::string& path) {
  if (path == "translation") return GltfAnimationPath::Translation;
  if (path == "rotation") return GltfAnimationPath::Rotation;
  if (path == "scale") return GltfAnimationPath::Scale;
  if (path == "weights") return GltfAnimationPath::Weights;
  return std::nullopt;
}

std::optional<GltfInterpolation> parseInterpolation(const std::string& name) {
  if (name == "LINEAR") return GltfInterpolation::Linear;
  if (name == "STEP") return GltfInterpolation::Step;
  if (name == "CUBICSPLINE") return GltfInterpolation::CubicSpline;
  return std::nullopt;
}

// Spec 3.11.2, table of channel.target.path: the output accessor type of each path, and
// whether normalized integers may stand in for floats (rotation and weights only).
int outputComponentsFor(GltfAnimationPath path) {
  switch (path) {
    case GltfAnimationPath::Translation:
    case GltfAnimationPath::Scale: return 3;
    case GltfAnimationPath::Rotation: return 4;
    case GltfAnimationPath::Weights: return 1;
  }
  return 0;
}

bool acceptsNormalizedIntegers(GltfAnimationPath path) {
  return path == GltfAnimationPath::Rotation || path == GltfAnimationPath::Weights;
}

bool isSmallInteger(int componentType) {
  return componentType == TINYGLTF_COMPONENT_TYPE_BYTE || componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         componentType == TINYGLTF_COMPONENT_TYPE_SHORT || componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
}

// Reads and validates every animation; each channel gets its sampler's keys copied in, so a
// channel is self-contained for evaluation (samplers are small next to meshes).
class AnimationReader {
 public:
  AnimationReader(const fs::path& path, const tinygltf::Model& model) : path_(path), model_(model), reader_(path, model) {}

  std::vector<GltfAnimation> readAll() const {
    std::vector<GltfAnimation> out;
    for (size_t a = 0; a < model_.animations.size(); ++a) out.push_back(readAnimation(a));
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { failFile(path_, what); }

  GltfAnimation readAnimation(size_t index) const {
    const tinygltf::Animation& source = model_.animations[index];
    GltfAnimation out;
    out.name = source.name;
    const std::string animationWhat = fmt::format("animation {} ('{}')", index, source.name);
    for (size_t c = 0; c < source.channels.size(); ++c) {
      const std::string what = fmt::format("{}, channel {}", animationWhat, c);
      GltfAnimationChannel channel = readChannel(source, source.channels[c], what);
      // Spec 3.11.2: within one animation, a node property is the target of one channel only.
      if (const GltfAnimationChannel* earlier = findChannel(out, channel.node, channel.path))
        fail(fmt::format("{}: node {} ('{}') {} is already animated by channel {}", what, channel.node, channel.nodeName,
                         gltfAnimationPathName(channel.path), earlier - out.channels.data()));
      out.channels.push_back(std::move(channel));
    }
    return out;
  }

  GltfAnimationChannel readChannel(const tinygltf::Animation& animation, const tinygltf::AnimationChannel& source,
                                   const std::string& what) const {
    GltfAnimationChannel out;
    if (source.target_node < 0 || size_t(source.target_node) >= model_.nodes.size())
      fail(fmt::format("{}: target node {} does not exist ({} nodes)", what, source.target_node, model_.nodes.size()));
    out.node = source.target_node;
    out.nodeName = model_.nodes[size_t(out.node)].name;
    const std::optional<GltfAnimationPath> path = parseAnimationPath(source.target_path);
    if (!path)
      fail(fmt::format("{}: unknown target path '{}' (expected translation, rotation, scale or weights)", what,
                       source.target_path));
    out.path = *path;
    if (source.sampler < 0 || size_t(source.sampler) >= animation.samplers.size())
      fail(fmt::format("{}: sampler {} does not exist ({} samplers)", what, source.sampler, animation.samplers.size()));
    const tinygltf::AnimationSampler& sampler = animation.samplers[size_t(source.sampler)];
    const std::string samplerWhat = fmt::format("{} (sampler {})", what, source.sampler);
    const std::optional<GltfInterpolation> interpolation = parseInterpolation(sampler.interpolation);
    if (!interpolation)
      fail(fmt::format("{}: unknown interpolation '{}' (expected LINEAR, STEP or CUBICSPLINE)", samplerWhat,
                       sampler.interpolation));
    out.interpolation = *interpolation;
    out.valueSize = out.path == GltfAnimationPath::Weights ? morphTargetCount(out.node, what)
                                                            : size_t(outputComponentsFor(out.path));
    out.times = readTimes(sampler.input, out.interpolation, samplerWhat);
    out.values = readValues(sampler.output, out, samplerWhat);
    return out;
  }

  // A weights channel drives the morph targets of the node's mesh (spec 3.11.2).
  size_t morphTargetCount(int nodeIndex, const std::string& what) const {
    const tinygltf::Node& node = model_.nodes[size_t(nodeIndex)];
    if (node.mesh < 0) fail(fmt::format("{}: animates the weights of node {} ('{}'), which has no mesh", what, nodeIndex, node.name));
    if (size_t(node.mesh) >= model_.meshes.size())
      fail(fmt::format("{}: node {} ('{}') refers to mesh {}, which does not exist", what, nodeIndex, node.name, node.mesh));
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    const size_t count = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    if (count == 0)
      fail(fmt::format("{}: animates the weights of node {} ('{}'), whose mesh {} ('{}') has no morph targets", what,
                       nodeIndex, node.name, node.mesh, mesh.name));
    return count;
  }

  // Spec 3.11.3: SCALAR float times in seconds, time[0] >= 0, strictly increasing; CUBICSPLINE
  // needs two keys to have a segment at all.
  std::vector<float> readTimes(int accessorIndex, GltfInterpolation interpolation, const std::string& what) const {
    const std::string inputWhat = what + " input";
    const tinygltf::Accessor& a = reader_.accessor(accessorIndex, inputWhat);
    if (a.type != TINYGLTF_TYPE_SCALAR || a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      fail(fmt::format("{}: accessor {} is {} with componentType {}; key times must be SCALAR FLOAT (5126)", inputWhat,
                       accessorIndex, accessorTypeName(a.type), a.componentType));
    const std::vector<double> times = reader_.readDense(accessorIndex, 1, false, inputWhat);
    const size_t minimumKeys = interpolation == GltfInterpolation::CubicSpline ? 2 : 1;
    if (times.size() < minimumKeys)
      fail(fmt::format("{}: accessor {} has {} key times; {} needs at least {}", inputWhat, accessorIndex, times.size(),
                       gltfInterpolationName(interpolation), minimumKeys));
    for (size_t k = 0; k < times.size(); ++k) {
      if (!std::isfinite(times[k])) fail(fmt::format("{}: key time {} is not finite", inputWhat, k));
      if (k == 0 && times[k] < 0.0) fail(fmt::format("{}: the first key time is {} s; times must be >= 0", inputWhat, times[k]));
      if (k > 0 && !(times[k] > times[k - 1]))
        fail(fmt::format("{}: key times must be strictly increasing, but key {} at {} s follows {} s", inputWhat, k,
                         times[k], times[k - 1]));
    }
    return std::vector<float>(times.begin(), times.end());
  }

  std::vector<float> readValues(int accessorIndex, const GltfAnimationChannel& channel, const std::string& what) const {
    const std::string outputWhat = what + " output";
    const tinygltf::Accessor& a = reader_.accessor(accessorIndex, outputWhat);
    checkOutputFormat(a, accessorIndex, channel.path, outputWhat);
    const size_t keys = channel.times.size();
    const size_t perKey = channel.interpolation == GltfInterpolation::CubicSpline ? 3 : 1;  // in-tangent, value, out-tangent
    const size_t elementsPerValue = channel.path == GltfAnimationPath::Weights ? channel.valueSize : 1;
    const size_t expected = keys * perKey * elementsPerValue;
    if (a.count != expected)
      fail(fmt::format("{}: accessor {} has {} elements, expected {} ({} keys{}{})", outputWhat, accessorIndex, a.count,
                       expected, keys, perKey == 3 ? " x 3 for CUBICSPLINE" : "",
                       elementsPerValue > 1 ? fmt::format(" x {} morph targets", elementsPerValue) : ""));
    const std::vector<double> values = reader_.readDense(accessorIndex, outputComponentsFor(channel.path), false, outputWhat);
    for (size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i])) fail(fmt::format("{}: value {} is not finite", outputWhat, i));
    if (channel.path == GltfAnimationPath::Rotation) rejectZeroQuaternions(values, perKey, outputWhat);
    return std::vector<float>(values.begin(), values.end());
  }

  // Spec 3.11.2: translation and scale are FLOAT; rotation and weights may also be normalized
  // (unsigned) byte or short, decoded by decodeComponent.
  void checkOutputFormat(const tinygltf::Accessor& a, int index, GltfAnimationPath path, const std::string& what) const {
    const int components = outputComponentsFor(path);
    if (componentCount(a.type) != components)  // matrices land here too
      fail(fmt::format("{}: accessor {} is {}, but a {} channel needs {}", what, index, accessorTypeName(a.type),
                       gltfAnimationPathName(path), components == 1 ? "SCALAR" : components == 3 ? "VEC3" : "VEC4"));
    if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) return;
    if (!acceptsNormalizedIntegers(path))
      fail(fmt::format("{}: accessor {} has componentType {}; {} values must be FLOAT (5126)", what, index,
                       a.componentType, gltfAnimationPathName(path)));
    if (!isSmallInteger(a.componentType) || !a.normalized)
      fail(fmt::format("{}: accessor {} has componentType {}{}; {} values must be FLOAT or normalized (unsigned) byte or "
                       "short", what, index, a.componentType, a.normalized ? "" : " without normalized",
                       gltfAnimationPathName(path)));
  }

  // A zero quaternion has no rotation to normalize to; tangents (CUBICSPLINE) may be zero.
  void rejectZeroQuaternions(const std::vector<double>& values, size_t perKey, const std::string& what) const {
    for (size_t k = 0; k * perKey * 4 < values.size(); ++k) {
      const size_t start = (k * perKey + (perKey == 3 ? 1 : 0)) * 4;
      const double norm2 = values[start] * values[start] + values[start + 1] * values[start + 1] +
                           values[start + 2] * values[start + 2] + values[start + 3] * values[start + 3];
      if (norm2 == 0.0) fail(fmt::format("{}: the rotation of key {} is the zero quaternion", what, k));
    }
  }

  const fs::path& path_;
  const tinygltf::Model& model_;
  AccessorReader reader_;
};

}  // namespace

GltfAsset loadGltfAsset(const fs::path& path) {
  GltfAsset asset;
  asset.path = path;
  const tinygltf::Model model = parseModel(path, asset.warnings);
  try {
    SceneFlattener(path, model, asset).run();
    asset.animations = AnimationReader(path, model).readAll();
  } catch (const std::bad_alloc&) {
    failFile(path, "out of memory while reading (corrupt element counts?)");
  }
  return asset;
}

}  // namespace lacrima
