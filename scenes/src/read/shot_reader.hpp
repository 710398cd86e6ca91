#pragma once
// The reading phase of loadShot (shot_loader.cpp): ShotReader reads a parsed shot file section by
// section into a Shot, checking every value (each problem goes to the Checker with its JSON pointer,
// and reading goes on). It opens no file: what the shot names inside its files (the files themselves,
// parts, blendshapes, landmarks, glTF cameras) is recorded in ShotUses (shot_uses.hpp) for the
// loading and binding phases (load/shot_files.hpp, load/shot_binding.hpp). What needs the assets
// posed (surface points, flow paths, eyes, flesh, SPH colliders) is resolved after those
// (shot_resolve.hpp).
// One file per section of the shot file, shot_reader_<section>.cpp; what several sections read alike
// is in shot_reader.cpp.
#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "read/json_source.hpp"
#include "lacrima/scenes/shot.hpp"
#include "read/shot_checker.hpp"
#include "read/shot_uses.hpp"
#include "shot_geometry.hpp"  // RectangleEdges

namespace lacrima::shotfile {

// The index in `names` of the string at `key`; nothing when the key is absent, or, with an error
// naming the key and the closest name (or all of them), when it is none of them:
// "unknown <what> 'x'; did you mean 'y'?".
std::optional<size_t> readChoice(ObjectReader& o, const char* key, const std::vector<std::string>& names,
                                 const char* what);

// Adds `s` to `list` unless it is empty or already there.
void appendUnique(std::vector<std::string>& list, const std::string& s);

// The names a shot can use for a primitive: its part, its primitive name, its material name.
std::vector<std::string> primitiveNames(const GltfPrimitive& p);

// A textured material on a mesh without uvs shades with its constants there: a warning, once per
// mesh (`what` names it).
void warnTexturesWithoutUvs(Checker& c, Shot& shot, const std::string& pointer, uint32_t materialId,
                            const std::string& what);

class ShotReader {
 public:
  ShotReader(Checker& c, Shot& shot, ShotUses& uses)
      : c_(c), shot_(shot), uses_(uses), baseDir_(shot.path.parent_path()) {}

  // Reads the root object: every section given, in the order in which they name each other.
  void read(const Json& root);

 private:
  Checker& c_;
  Shot& shot_;
  ShotUses& uses_;
  std::filesystem::path baseDir_;

  // Reads a required section; returns what the reader returns (false when it is missing).
  template <typename F>
  bool readSection(ObjectReader& o, const std::string& key, const std::string& expectation, F&& reader) {
    const Json* v = o.find(key);
    if (!v) {
      o.missing(key, expectation);
      return false;
    }
    return reader(*v);
  }

  template <typename F>
  void readArray(const Json& v, const std::string& pointer, const char* what, F&& reader) {
    if (!v.is_array()) {
      c_.error(pointer, Anchor::Value, fmt::format("expected an array of {}, found {}", what, describeValue(v)));
      return;
    }
    for (size_t i = 0; i < v.size(); ++i) reader(v[i], childPointer(pointer, i));
  }

  // ---- shot_reader.cpp: what several sections read alike -----------------------------------

  std::filesystem::path resolve(const std::string& value) const;
  FileUse fileUse(const std::string& pointer, const std::string& written) const;
  std::optional<std::string> readType(const Json& v, const std::string& pointer, const std::vector<std::string>& types,
                                      const char* what);
  std::vector<std::string> materialNames() const;
  int materialReference(const Json& v, const std::string& pointer);
  bool readMaterialMember(ObjectReader& o, std::string& name, uint32_t& id);
  bool readNamedMaterial(ObjectReader& o, const std::string& key, uint32_t& id);
  std::optional<size_t> readAssetPart(ObjectReader& o, std::string& partOut);
  void usePart(ObjectReader& o, size_t asset, const std::string& part);
  void readAnchor(ObjectReader& o, const std::string& key, size_t asset, const std::string& part,
                  ShotSurfaceAnchor& anchor);
  std::optional<AnimatedVec3> readAnimatedMember(ObjectReader& o, const std::string& key);
  std::optional<Mat3> readRotation(const Json& v, const std::string& pointer);
  ShotTransform readTransform(const Json& v, const std::string& pointer);
  void readSkinRegions(ObjectReader& o, size_t asset, const std::string& part, std::vector<ShotSkinRegion>& regions);

  // ---- shot_reader_render.cpp: "frames", "output", "render" --------------------------------

  bool readFrames(const Json& v);
  void readOutput(const Json& v, bool framesOk);
  bool readRender(const Json& v);
  void readAovs(ObjectReader& render, RenderSettings& s);
  void readAdaptive(ObjectReader& render, RenderSettings& s);
  void readBounces(ObjectReader& render, RenderSettings& s);
  void readSampler(ObjectReader& o, RenderSettings& s);
  void readFilter(ObjectReader& render, RenderSettings& s);
  void readCaustics(ObjectReader& o, RenderSettings& s);

  // ---- shot_reader_materials.cpp: "materials" ----------------------------------------------

  void readMaterials(const Json& v);
  void readMaterial(const Json& v, const std::string& pointer, Material& m);
  void readSubsurfaceMethod(ObjectReader& o, SubsurfaceParams& subsurface);
  void readTextures(ObjectReader& material, const std::vector<std::string>& roles, MaterialTextures& textures);
  std::optional<IrisPatternParams> readAlbedoPattern(const Json& v, const std::string& pointer);
  std::optional<TextureMap> readTextureMap(const Json& v, const std::string& pointer, bool colour);

  // ---- shot_reader_assets.cpp: "assets" ----------------------------------------------------

  void readAsset(const Json& v, const std::string& pointer);

  // ---- shot_reader_camera.cpp: "camera" ----------------------------------------------------

  bool readCamera(const Json& v);
  void readShutter(const Json& v, const std::string& pointer);

  // ---- shot_reader_environment.cpp: "environment" ------------------------------------------

  void readEnvironment(const Json& v);

  // ---- shot_reader_lights.cpp: "lights" ----------------------------------------------------

  void readLight(const Json& v, const std::string& pointer);

  // ---- shot_reader_shapes.cpp: "shapes" ----------------------------------------------------

  std::optional<RectangleEdges> readRectangle(ObjectReader& o, const Vec3* center);
  void readShape(const Json& v, const std::string& pointer);
  void readAttachment(const Json& v, const std::string& pointer, ShotShape& shape);

  // ---- shot_reader_tears.cpp: "tears" (dripping, shedding) ---------------------------------

  void readTear(const Json& v, const std::string& pointer);
  void readTearPath(ObjectReader& o, std::vector<Vec3>& path);
  void readSheddingTear(const Json& v, const std::string& pointer);

  // ---- shot_reader_liquid_tears.cpp: "tears" of type "liquid" ------------------------------

  void readLiquidTear(const Json& v, const std::string& pointer);
  void readWellingTimes(ObjectReader& o, ShotLiquidTear& tear);
  void readWellingRate(ObjectReader& o, ShotLiquidTear& tear);
  void readPinning(ObjectReader& o, ShotLiquidTear& tear);
  void readRivulet(ObjectReader& o, LiquidTearParams& p);
  void readContactAngles(ObjectReader& o, ContactAngleHysteresis& angles);
  void readContactAngleRegions(ObjectReader& o, size_t asset, ShotLiquidTear& tear);

  // ---- shot_reader_details.cpp: "details" --------------------------------------------------

  void readDetail(const Json& v, const std::string& pointer);
  std::optional<BasicDetailPattern> readPattern(ObjectReader& o);
  void readSubdivision(const Json& v, const std::string& pointer, ShotDetail& detail);

  // ---- shot_reader_eyes.cpp: "eyes" --------------------------------------------------------

  void readEye(const Json& v, const std::string& pointer);
  void readLashes(const Json& v, const std::string& pointer, size_t asset, ShotEye& eye);

  // ---- shot_reader_flesh.cpp: "flesh" ------------------------------------------------------

  void readFlesh(const Json& v, const std::string& pointer);

  // ---- shot_reader_sph.cpp: "sph" ----------------------------------------------------------

  void readSph(const Json& v, const std::string& pointer);
  void readSphRelease(const Json& v, const std::string& pointer, bool drop, ShotSph& liquid);
  void readSphCollider(const Json& v, const std::string& pointer, ShotSph& liquid);
};

}  // namespace lacrima::shotfile
