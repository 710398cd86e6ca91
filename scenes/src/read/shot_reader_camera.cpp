// ShotReader (shot_reader.hpp): the section "camera" (docs/shot-format.md). The renderer camera is
// derived from it once a glTF camera it names is found (load/shot_binding.cpp).
#include <fmt/format.h>

#include "shot_geometry.hpp"
#include "read/shot_reader.hpp"
#include "read/suggest.hpp"

namespace lacrima::shotfile {

bool ShotReader::readCamera(const Json& v) {
  // Counted before the reader: an unknown key it reports ("FOV", did you mean 'fov'?) stands in
  // for the missing 'fov', which is then not reported again (found by tools/hardening.sh: the
  // camera was derived without a field of view and crashed).
  const size_t before = c_.errorCount();
  ObjectReader o(
      c_, v, "/camera",
      {"position", "lookAt", "up", "gltf", "fov", "focalLength", "sensorHeight", "fStop", "focusDistance",
       "focus", "shutter"});
  if (!o.ok()) return false;
  ShotCamera& cam = shot_.camera;
  CameraUse use;

  if (const Json* g = o.find("gltf")) {
    cam.kind = ShotCamera::Kind::Gltf;
    for (const char* key : {"position", "lookAt", "up"})
      if (o.has(key))
        o.error(key,
                fmt::format("'{}' cannot be combined with 'gltf': the glTF camera gives the position and "
                            "orientation",
                            key),
                Anchor::Key);
    ObjectReader go(c_, *g, o.at("gltf"), {"asset", "camera"});
    const auto assetName = go.string("asset", true);
    const auto cameraName = go.string("camera", true);
    if (assetName) {
      cam.gltfAsset = *assetName;
      std::vector<std::string> assetNames;
      for (size_t a = 0; a < shot_.assets.size(); ++a) {
        assetNames.push_back(shot_.assets[a].name);
        if (shot_.assets[a].name == *assetName && !use.gltfAsset) use.gltfAsset = a;
      }
      if (!use.gltfAsset)
        go.error("asset", fmt::format("undefined asset '{}'{}", *assetName,
                                      suggestionOrList(*assetName, assetNames, "assets", "the shot has no assets")));
    }
    if (cameraName) cam.gltfCamera = *cameraName;
    use.gltfCameraPointer = go.at("camera");
  } else {
    cam.kind = ShotCamera::Kind::LookAt;
    // Position and look-at point may be keyed; the checks below apply to their first keys.
    const auto animatedPosition = readAnimatedMember(o, "position");
    const auto animatedLookAt = readAnimatedMember(o, "lookAt");
    const auto position = animatedPosition ? std::optional<Vec3>(animatedPosition->constant) : std::nullopt;
    const auto lookAt = animatedLookAt ? std::optional<Vec3>(animatedLookAt->constant) : std::nullopt;
    const auto up = o.vec3("up");
    if (animatedPosition) cam.animatedPosition = *animatedPosition;
    if (animatedLookAt) cam.animatedLookAt = *animatedLookAt;
    if (position) cam.position = *position;
    if (lookAt) cam.lookAt = *lookAt;
    if (up) cam.up = *up;
    if (position && lookAt) {
      const Vec3 view = *lookAt - *position;
      if (!(view.norm() > 0.0f))
        o.error("lookAt", "'lookAt' must differ from 'position'");
      else if (up && parallel(view, *up))
        o.error("up", "'up' must not be parallel to the view direction (lookAt - position)");
      else if (!o.has("up") && parallel(view, cam.up))
        o.error("lookAt", "the view direction is parallel to the default 'up' [0, 1, 0]; give 'up'");
    }
  }

  const auto fov = o.number("fov", Range::open(0, 180));
  const auto focalLength = o.number("focalLength", Range::above(0));
  const auto sensorHeight = o.number("sensorHeight", Range::above(0));
  const auto fStop = o.number("fStop", Range::above(0));
  const auto focusDistance = o.number("focusDistance", Range::above(0));
  if (o.has("fov") && o.has("focalLength"))
    o.error("focalLength", "give either 'fov' or 'focalLength', not both", Anchor::Key);
  else if (!o.has("fov") && !o.has("focalLength") && cam.kind == ShotCamera::Kind::LookAt)
    o.missing("fov", "vertical field of view in degrees; or 'focalLength' in mm");
  const auto focus = readChoice(o, "focus", {"lookAt", "surface"}, "focus");
  const bool focusOnSurface = focus && *focus == 1;
  if (o.has("focus") && o.has("focusDistance"))
    o.error("focus", "give either 'focusDistance' or 'focus', not both", Anchor::Key);
  else if (fStop && !o.has("focusDistance") && !focusOnSurface && cam.kind == ShotCamera::Kind::Gltf)
    o.missing("focusDistance",
              "metres; with 'fStop', a glTF camera has no look-at point to focus on: give it, or "
              "\"focus\": \"surface\"");
  if (fov) cam.fovDegrees = float(*fov);
  if (focalLength) cam.focalLengthMm = float(*focalLength);
  if (sensorHeight) cam.sensorHeightMm = float(*sensorHeight);
  if (fStop) cam.fStop = float(*fStop);
  if (focusDistance) cam.focusDistance = float(*focusDistance);
  cam.focusOnSurface = focusOnSurface;
  if (focusOnSurface && !fStop)
    shot_.warnings.push_back(c_.warning(o.at("focus"), Anchor::Value,
                                        "'focus' has no effect without 'fStop': a pinhole camera has everything "
                                        "in focus"));
  if (const Json* s = o.find("shutter")) readShutter(*s, o.at("shutter"));

  if (c_.errorCount() != before) return false;
  uses_.camera = use;
  return true;
}

// {"open": frames, "close": frames} relative to each frame.
void ShotReader::readShutter(const Json& v, const std::string& pointer) {
  ObjectReader o(c_, v, pointer, {"open", "close"});
  const auto open = o.number("open", Range::closed(-1, 1), true);
  const auto close = o.number("close", Range::closed(-1, 1), true);
  if (!open || !close) return;
  if (*close < *open) {
    o.error("close", fmt::format("the shutter must close after it opens: close {} < open {}", *close, *open));
    return;
  }
  shot_.shutter = std::make_pair(*open, *close);
}

}  // namespace lacrima::shotfile
