#pragma once
// A small glTF document builder for tests: float accessors appended to one BIN chunk, animation
// samplers and channels, written as a GLB (see glb_support.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/glb_support.hpp"

namespace lacrima::test {

class GltfBuilder {
 public:
  GltfBuilder() {
    json_["asset"] = {{"version", "2.0"}};
    json_["scene"] = 0;
  }

  nlohmann::json& json() { return json_; }

  // Float values as a new accessor (own bufferView); returns its index.
  int addAccessor(const std::vector<float>& values, const std::string& type) { return addAccessorOf(values, 5126, type); }

  // Values of any component type (uint8_t 5121, uint16_t 5123, float 5126, ...) as a new
  // accessor (own bufferView, tightly packed); type SCALAR, VEC2-4 or MAT4. Returns its index.
  template <typename T>
  int addAccessorOf(const std::vector<T>& values, int componentType, const std::string& type, bool normalized = false) {
    const size_t offset = appendValues(bin_, values);
    json_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    const size_t components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : type == "MAT4" ? 16 : 4;
    nlohmann::json accessor = {{"bufferView", json_["bufferViews"].size() - 1},
                               {"componentType", componentType},
                               {"count", values.size() / components},
                               {"type", type}};
    if (normalized) accessor["normalized"] = true;
    json_["accessors"].push_back(accessor);
    return int(json_["accessors"].size()) - 1;
  }

  // A one-primitive mesh with POSITION and one dense POSITION target per name; returns its index.
  int addMesh(const std::string& name, const std::vector<float>& positions, const std::vector<std::string>& targetNames,
              const std::vector<std::vector<float>>& targets) {
    nlohmann::json primitive = {{"attributes", {{"POSITION", addAccessor(positions, "VEC3")}}}};
    for (const auto& t : targets) primitive["targets"].push_back({{"POSITION", addAccessor(t, "VEC3")}});
    nlohmann::json mesh = {{"name", name}, {"primitives", {primitive}}};
    if (!targetNames.empty()) mesh["extras"] = {{"targetNames", targetNames}};
    json_["meshes"].push_back(mesh);
    return int(json_["meshes"].size()) - 1;
  }

  // A new (empty) animation; returns its index.
  int addAnimation(const std::string& name) {
    json_["animations"].push_back({{"name", name}, {"channels", nlohmann::json::array()}, {"samplers", nlohmann::json::array()}});
    return int(json_["animations"].size()) - 1;
  }

  void addChannel(int animation, int node, const std::string& path, const std::vector<float>& times,
                  const std::vector<float>& values, const std::string& type, const std::string& interpolation = "LINEAR") {
    const int input = addAccessor(times, "SCALAR");
    const int output = addAccessor(values, type);
    nlohmann::json& a = json_["animations"][size_t(animation)];
    a["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", interpolation}});
    a["channels"].push_back({{"sampler", a["samplers"].size() - 1}, {"target", {{"node", node}, {"path", path}}}});
  }

  void write(const std::filesystem::path& path) {
    nlohmann::json out = json_;
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    out["buffers"] = {{{"byteLength", bin_.size()}}};
    writeBytes(path, makeGlb(out, bin_));
  }

 private:
  nlohmann::json json_;
  std::vector<unsigned char> bin_;
};

}  // namespace lacrima::test
