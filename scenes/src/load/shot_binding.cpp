// The binding phase: what the shot description uses of its loaded assets; see shot_binding.hpp.
#include "load/shot_binding.hpp"

#include <fmt/format.h>

#include <cmath>

#include "asset_parts.hpp"
#include "load/surface_anchor_check.hpp"
#include "read/suggest.hpp"
#include "shot_geometry.hpp"

namespace lacrima::shotfile {

namespace {

void checkPart(const PartUse& use, const ShotAsset& asset, Checker& c) {
  if (hasPart(*asset.gltf, use.part)) return;
  c.error(use.pointer, Anchor::Value,
          fmt::format("asset '{}' has no part '{}'{}", asset.name, use.part,
                      suggestionOrList(use.part, partNames(*asset.gltf), "its parts", "it has no primitives")));
}

// The glTF camera the shot names, or null (reported).
const GltfCamera* findGltfCamera(const CameraUse& use, const Shot& shot, Checker& c) {
  const ShotAsset& asset = shot.assets[*use.gltfAsset];
  std::vector<std::string> names;
  for (const GltfCamera& camera : asset.gltf->cameras) {
    if (camera.name == shot.camera.gltfCamera) return &camera;
    names.push_back(camera.name);
  }
  c.error(use.gltfCameraPointer, Anchor::Value,
          fmt::format("asset '{}' has no camera '{}'{}", asset.name, shot.camera.gltfCamera,
                      suggestionOrList(shot.camera.gltfCamera, names, "its cameras", "it has no cameras")));
  return nullptr;
}

// The renderer camera at the first frame: placed by the look-at point or the glTF camera (with its
// asset's transform, whose scale does not scale the camera), its field of view from "fov",
// "focalLength" or the glTF camera's yfov, and a thin lens of aperture focalLength / fStop.
void deriveCamera(ShotCamera& cam, const ShotAsset* asset, const GltfCamera* gltfCamera) {
  Camera& out = cam.camera;
  float viewDistance = 1.0f;
  if (cam.kind == ShotCamera::Kind::LookAt) {
    out.cameraToWorld = *lookAtCameraToWorld(cam.position, cam.lookAt, cam.up);
    viewDistance = (cam.lookAt - cam.position).norm();
  } else {
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

void bindCamera(const CameraUse& use, Shot& shot, Checker& c) {
  if (shot.camera.kind == ShotCamera::Kind::LookAt) {
    deriveCamera(shot.camera, nullptr, nullptr);
    return;
  }
  if (!use.gltfAsset || !shot.assets[*use.gltfAsset].gltf) return;
  if (const GltfCamera* camera = findGltfCamera(use, shot, c))
    deriveCamera(shot.camera, &shot.assets[*use.gltfAsset], camera);
}

}  // namespace

void bindShotUses(const ShotUses& uses, Shot& shot, Checker& c) {
  for (const AssetUse& use : uses.assets)
    if (shot.assets[use.asset].gltf) bindAsset(use, shot, c);
  for (const PartUse& use : uses.parts)
    if (const ShotAsset& asset = shot.assets[use.asset]; asset.gltf) checkPart(use, asset, c);
  // An anchor on a part the asset does not have is not checked: the part's error says it.
  for (const SurfaceAnchorUse& use : uses.anchors)
    if (const ShotAsset& asset = shot.assets[use.asset]; asset.gltf && hasPart(*asset.gltf, use.part))
      checkSurfaceAnchor(c, *use.value, use.pointer, *asset.gltf, use.part);
  if (uses.camera) bindCamera(*uses.camera, shot, c);
}

}  // namespace lacrima::shotfile
