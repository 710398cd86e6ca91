// Small helpers of the plain-data Shot.
#include "lacrima/scenes/shot.hpp"

#include <algorithm>
#include <cmath>

namespace lacrima {

int Shot::findMaterial(const std::string& name) const {
  for (size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return int(i);
  return -1;
}

std::vector<Material> Shot::frameMaterials() const {
  std::vector<Material> all = materials;
  all.insert(all.end(), assetMaterials.begin(), assetMaterials.end());
  return all;
}

RenderSettings renderSettingsAt(const Shot& shot, int frameNumber) {
  RenderSettings settings = shot.render;
  settings.frameNumber = frameNumber;
  return settings;
}

bool ShotAsset::animated() const {
  const auto keyed = [](const AssetChannel& c) { return c.value.animated(); };
  return performance.has_value() || gltfAnimation.has_value() || std::any_of(animatedBlendshapes.begin(), animatedBlendshapes.end(), keyed) ||
         std::any_of(joints.begin(), joints.end(), keyed) ||
         std::any_of(controlValues.begin(), controlValues.end(), keyed);
}

double ShotGltfAnimation::secondsAt(double frame) const {
  const double t = speed * (frame - startFrame) / fps;
  if (!(duration > 0.0)) return 0.0;
  if (loop) {
    const double wrapped = std::fmod(t, duration);
    return wrapped < 0.0 ? wrapped + duration : wrapped;
  }
  return std::clamp(t, 0.0, duration);
}

namespace {

// The samples around `frame` (linear between them, held before the first and after the last).
struct SamplePair {
  size_t i0, i1;
  float t;
};
SamplePair samplesAround(const ShotPerformance& p, double frame) {
  const double position = std::clamp(frame - p.startFrame, 0.0, double(p.samples.size() - 1));
  const size_t i0 = size_t(position);
  return {i0, std::min(i0 + 1, p.samples.size() - 1), float(position - double(i0))};
}

}  // namespace

void ShotPerformance::addWeightsAt(double frame, std::vector<float>& weights) const {
  if (samples.empty()) return;
  const auto [i0, i1, t] = samplesAround(*this, frame);
  for (size_t c = 0; c < targets.size(); ++c)
    if (targets[c] != kNone) weights[targets[c]] += (1.0f - t) * samples[i0][c] + t * samples[i1][c];
}

std::vector<std::pair<size_t, float>> ShotPerformance::jointsAt(double frame) const {
  std::vector<std::pair<size_t, float>> out;
  if (samples.empty()) return out;
  const auto [i0, i1, t] = samplesAround(*this, frame);
  for (size_t c = 0; c < joints.size(); ++c)
    if (joints[c] != kNone) out.emplace_back(joints[c], (1.0f - t) * samples[i0][c] + t * samples[i1][c]);
  return out;
}

AreaLight ShotLight::at(int frame) const {
  AreaLight posed = light;
  if (centerCurve) posed.center = centerCurve->evaluate(float(frame));
  // A constant intensity of 1 leaves the radiance bitwise as written.
  if (intensity.animated() || intensity.constant != 1.0f) posed.radiance *= intensity.at(frame);
  return posed;
}

Affine3 ShotTransform::matrix() const {
  Affine3 m = Affine3::Identity();
  m.translate(translate);
  m.linear() = rotation * scale.asDiagonal();
  return m;
}

}  // namespace lacrima
