// ShotReader (shot_reader.hpp): the section "camera" (docs/shot-format.md), and the renderer camera
// derived from it.
#include <fmt/format.h>

#include <cmath>

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
  const GltfCamera* gltfCamera = nullptr;
  const ShotAsset* gltfAsset = nullptr;

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
      for (const ShotAsset& a : shot_.assets) {
        assetNames.push_back(a.name);
        if (a.name == *assetName) gltfAsset = &a;
      }
      if (!gltfAsset)
        go.error("asset", fmt::format("undefined asset '{}'{}", *assetName,
                                      suggestionOrList(*assetName, assetNames, "assets", "the shot has no assets")));
    }
    if (cameraName) cam.gltfCamera = *cameraName;
    if (cameraName && gltfAsset && gltfAsset->gltf) {
      std::vector<std::string> cameraNames;
      for (const GltfCamera& gc : gltfAsset->gltf->cameras) {
        cameraNames.push_back(gc.name);
        if (gc.name == *cameraName && !gltfCamera) gltfCamera = &gc;
      }
      if (!gltfCamera)
        go.error("camera",
                 fmt::format("asset '{}' has no camera '{}'{}", gltfAsset->name, *cameraName,
                             suggestionOrList(*cameraName, cameraNames, "its cameras", "it has no cameras")));
    }
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
  // An asset that failed to load has no cameras; its own error is already reported.
  if (cam.kind == ShotCamera::Kind::Gltf && (!gltfAsset || !gltfCamera)) return false;
  deriveCamera(cam, gltfAsset, gltfCamera);
  return true;
}

void ShotReader::deriveCamera(ShotCamera& cam, const ShotAsset* asset, const GltfCamera* gltfCamera) {
  Camera& out = cam.camera;
  float viewDistance = 1.0f;
  if (cam.kind == ShotCamera::Kind::LookAt) {
    out.cameraToWorld = *lookAtCameraToWorld(cam.position, cam.lookAt, cam.up);
    viewDistance = (cam.lookAt - cam.position).norm();
  } else {
    // The asset's transform applies; its scale does not scale the camera.
    const Affine3 full = asset->transform.matrix() * gltfCamera->cameraToAsset;
    out.cameraToWorld = Affine3::Identity();
    out.cameraToWorld.linear() = full.rotation();
    out.cameraToWorld.translation() = full.translation();
  }
  if (cam.fovDegrees)
    out.verticalFovRadians = degreesToRadians(*cam.fovDegrees);
  else if (cam.focalLengthMm)
    out.verticalFovRadians = 2.0f * std::atan(cam.sensorHeightMm / (2.0f * *cam.focalLengthMm));
  else
    out.verticalFovRadians = gltfCamera->yfovRadians;
  out.focusDistance = cam.focusDistance.value_or(viewDistance);
  out.focusOnSurface = cam.focusOnSurface;
  out.lensRadius = 0.0f;
  if (cam.fStop) {
    const float focalLengthMm =
        cam.focalLengthMm.value_or(cam.sensorHeightMm / (2.0f * std::tan(0.5f * out.verticalFovRadians)));
    out.lensRadius = focalLengthMm * 1e-3f / (2.0f * *cam.fStop);
  }
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
