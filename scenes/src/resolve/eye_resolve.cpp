// Eyes resolved at load; see eye_resolve.hpp.
#include "resolve/eye_resolve.hpp"

#include <fmt/format.h>

#include "asset_pose.hpp"
#include "read/json_source.hpp"

namespace lacrima::shotfile {

namespace {

// The one primitive of `part` (eye shells and lash cards are single primitives in the ICT face).
std::optional<size_t> singlePrimitive(const ShotAsset& asset, const std::string& part) {
  std::optional<size_t> found;
  for (size_t i = 0; i < asset.gltf->primitives.size(); ++i) {
    if (asset.gltf->primitives[i].part != part) continue;
    if (found) return std::nullopt;
    found = i;
  }
  return found;
}

void resolveLashes(const Shot& shot, ShotEye& eye, const AssetPose& pose, std::vector<EyeProblem>& problems) {
  ShotLashes& lashes = *eye.lashes;
  const std::string at = childPointer(childPointer(eye.pointer, "lashes"), "part");
  const ShotAsset& asset = shot.assets[eye.asset];
  const auto primitive = singlePrimitive(asset, lashes.part);
  if (!primitive) {
    problems.push_back({at, fmt::format("part '{}' must be a single primitive of lash cards", lashes.part)});
    return;
  }
  lashes.primitive = *primitive;
  try {
    const TriangleMesh cards = posedPrimitive(asset, pose, *primitive);
    lashes.strips = findLashStrips(cards, eye.model->center, fmt::format("part '{}'", lashes.part));
    lashes.lashes = placeLashes(lashes.strips, eye.model->center, eye.model->up,
                                kLashReachInEyeRadii * eye.model->radius, lashes.params);
  } catch (const InputError& e) {
    problems.push_back({at, e.what()});
    return;
  }
  if (lashes.lashes.empty() && lashes.params.upper + lashes.params.lower > 0)
    problems.push_back({at, fmt::format("no strip of part '{}' lies within {} mm of the eye's centre", lashes.part,
                                        kLashReachInEyeRadii * eye.model->radius * 1e3f)});
}

}  // namespace

std::vector<EyeProblem> resolveEyes(Shot& shot) {
  std::vector<EyeProblem> problems;
  for (ShotEye& eye : shot.eyes) {
    ShotAsset& asset = shot.assets[eye.asset];
    const std::string partPointer = childPointer(eye.pointer, "part");
    const auto primitive = singlePrimitive(asset, eye.part);
    if (!primitive) {
      problems.push_back({partPointer, fmt::format("part '{}' must be a single primitive (the eyeball shell)", eye.part)});
      continue;
    }
    eye.primitive = *primitive;
    const AssetPose pose = assetPoseAt(asset, double(shot.frameStart));
    try {
      eye.model = std::make_shared<const EyeModel>(
          analyseEye(posedPrimitive(asset, pose, *primitive), eye.params, fmt::format("part '{}'", eye.part)));
    } catch (const InputError& e) {
      problems.push_back({partPointer, e.what()});
      continue;
    }
    if (eye.lashes) resolveLashes(shot, eye, pose, problems);
    // The eye replaces its shell, the lashes their cards.
    asset.primitiveMaterials[eye.primitive] = -1;
    if (eye.lashes) asset.primitiveMaterials[eye.lashes->primitive] = -1;
  }
  return problems;
}

}  // namespace lacrima::shotfile
