// Probe-ray sampling of a diffusion profile (King et al. 2013; pbrt-v3 §15.4); see
// subsurface_probe.hpp.
#include "subsurface_probe.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "shading_side.hpp"

namespace lacrima {

namespace {

// Normal, tangent s, tangent t. King et al. and pbrt-v3 take 1/2, 1/4, 1/4; on a face most
// tangent probes run beside the skin and find nothing, and 0.8, 0.1, 0.1 measured 1.8x less
// variance on the default shot (docs/performance.md). The tangents still cover what the normal
// probe sees edge-on (a crease, the side of the nose), with MIS.
constexpr std::array<float, 3> kAxisProbability = {0.8f, 0.1f, 0.1f};
constexpr int kMaxCandidates = 8;

// The projection axes about the entry's normal: axes[0] the normal, then the two tangents.
std::array<Vec3, 3> projectionAxes(const Vec3& normal) {
  const ShadingFrame frame = ShadingFrame::fromNormal(normal);
  return {frame.n, frame.s, frame.t};
}

// Channel probabilities proportional to the albedo (the energy each channel's profile holds): the
// combined density is then proportional to the sum of the channels' profiles, so a probe's weights
// always sum to the same total and only their colour varies from probe to probe.
Color channelProbabilities(const DiffusionProfile& profile) {
  const float sum = profile.albedo().sum();
  return sum > 0.0f ? Color(profile.albedo() / sum) : Color::Zero();
}

int pickAxis(float u) { return u < kAxisProbability[0] ? 0 : (u < kAxisProbability[0] + kAxisProbability[1] ? 1 : 2); }

// u rescaled to [0, 1) within channel c's interval of the cumulative probabilities (pickChannel):
// a second choice made from it is stratified within the first.
float remainderWithin(const Color& probabilities, int channel, float u) {
  float below = 0.0f;
  for (int c = 0; c < channel; ++c) below += std::max(probabilities[c], 0.0f);
  const float within = (u - below) / probabilities[channel];
  return std::clamp(within, 0.0f, 0.99999994f);
}

// The density (per unit area of the exit surface) with which a probe from `entry` reaches `exit`
// (normal `exitNormal`) before the choice among candidates: the sum over the three axes and the
// channels (probabilities `channels`), each radius measured in the plane normal to its axis.
// A channel's chords stay inside the sphere of its maximum radius about the entry, so a channel
// whose sphere does not hold the exit adds nothing, whatever its radius in the disk: a point on
// curved skin may lie inside a channel's disk radius yet beyond its chord's end. pbrt-v3's
// SeparableBSSRDF::Pdf_Sp counts such terms; they overstate the density of the wide (red)
// profile's far points, whose weight then comes out low: a furnace sphere returned 0.989 in red.
float probeDensity(const DiffusionProfile& profile, const std::array<Vec3, 3>& axes, const Color& channels,
                   const Vec3& entry, const Vec3& exit, const Vec3& exitNormal) {
  const Vec3 offset = exit - entry;
  const float distanceSquared = offset.squaredNorm();
  Color reaching = channels;  // the channels' probabilities, 0 for those whose chords end short of exit
  for (int c = 0; c < 3; ++c)
    if (distanceSquared >= profile.maxRadius(c) * profile.maxRadius(c)) reaching[c] = 0.0f;
  float density = 0.0f;
  for (int a = 0; a < 3; ++a) {
    const float along = offset.dot(axes[a]);
    // The radius in the plane normal to the axis; floored so a point on the axis stays finite.
    const float radius = std::sqrt(std::max(distanceSquared - along * along, 1e-14f));
    const float cosine = std::abs(exitNormal.dot(axes[a]));
    for (int c = 0; c < 3; ++c)
      if (reaching[c] > 0.0f)
        density += kAxisProbability[a] * reaching[c] * profile.radiusPdf(c, radius) * cosine / (2.0f * kPi * radius);
  }
  return density;
}

// The crossing a probe takes among the `count` its chord found, and the probability it had.
struct CandidateChoice {
  int index = 0;
  float probability = 1.0f;
};

// Each crossing is taken with probability proportional to the profile at its distance from the
// entry (summed over the channels): a chord through a lid or the side of the nose also crosses
// the far side, which the profile gives next to nothing, and a uniform choice (King et al. 2013)
// would spend half its probes there and double the weight of the others. Any choice with known,
// non-zero probabilities is unbiased (the weight divides by it); this one makes the weights of a
// chord's crossings nearly equal.
CandidateChoice chooseCandidate(const DiffusionProfile& profile, const Ray& chord, const Vec3& entry,
                                const SurfaceCrossing* candidates, int count, float u) {
  if (count == 1) return {};
  std::array<float, kMaxCandidates> importance{};
  float total = 0.0f;
  for (int i = 0; i < count; ++i) {
    const Vec3 crossing = chord.origin + candidates[i].rayDistance * chord.direction;
    importance[i] = profile.eval(std::max((crossing - entry).norm(), 1e-7f)).sum();
    total += importance[i];
  }
  if (!(total > 0.0f)) {  // every crossing beyond every channel's reach: rounding at the sphere's edge
    const int index = std::min(int(u * float(count)), count - 1);
    return {index, 1.0f / float(count)};
  }
  const float target = u * total;
  float below = 0.0f;
  int chosen = 0;
  for (int i = 0; i < count; ++i) {
    if (importance[i] <= 0.0f) continue;  // never taken: its probability would be 0
    chosen = i;
    below += importance[i];
    if (target < below) break;
  }
  return {chosen, importance[chosen] / total};
}

}  // namespace

std::optional<SubsurfaceExit> probeDiffusionExit(const EmbreeScene& scene, const DiffusionProfile& profile,
                                                 const ProbeSurface& surface, const std::vector<float>& dielectricIndex,
                                                 const Vec3& entry, const Vec3& outwardNormal, float time,
                                                 const ProbeNumbers& u, uint64_t& rays) {
  const std::array<Vec3, 3> axes = projectionAxes(outwardNormal);
  const Color channels = channelProbabilities(profile);
  if ((channels <= 0.0f).all()) return std::nullopt;  // black skin: nothing leaves
  const int channel = pickChannel(channels, u.channelAndAxis);
  const int axis = pickAxis(remainderWithin(channels, channel, u.channelAndAxis));
  const float rMax = profile.maxRadius(channel);
  const float radius = profile.sampleRadius(channel, u.radius);
  const float angle = 2.0f * kPi * u.angle;
  // The disk's two directions are the other two axes.
  const Vec3& across1 = axes[(axis + 1) % 3];
  const Vec3& across2 = axes[(axis + 2) % 3];
  const float halfChord = std::sqrt(std::max(rMax * rMax - radius * radius, 0.0f));
  const Vec3 onDisk = entry + radius * (std::cos(angle) * across1 + std::sin(angle) * across2);
  // Every skin crossing of the chord in one traversal; only the chosen one gets a hit set-up.
  const Ray chord{onDisk + halfChord * axes[axis], -axes[axis], time, 0.0f, 2.0f * halfChord};
  std::array<SurfaceCrossing, kMaxCandidates> candidates;
  ++rays;
  const int count = scene.crossingsOf(chord, surface.materialId, candidates.data(), kMaxCandidates);
  if (count == 0) return std::nullopt;
  const CandidateChoice choice = chooseCandidate(profile, chord, entry, candidates.data(), count, u.candidate);
  SurfaceHit chosen;
  scene.hitAt(chord, candidates[choice.index], chosen);
  const Vec3 ng = surface.entryOnWindingSide ? chosen.geometricNormal : Vec3(-chosen.geometricNormal);
  const Vec3 ns = onGeometricSide(chosen.shadingNormal, ng);
  const float density = probeDensity(profile, axes, channels, entry, chosen.position, ng);
  if (!(density > 0.0f)) return std::nullopt;
  const float distance = (chosen.position - entry).norm();
  Color weight = profile.eval(std::max(distance, 1e-7f)) / (choice.probability * density);
  // Radiance scales with the square of the index of the medium it is in (subsurface_walk.hpp).
  const float ratio = indexOutsideSkin(scene, dielectricIndex, entry, outwardNormal, time, rays) /
                      indexOutsideSkin(scene, dielectricIndex, chosen.position, ng, time, rays);
  weight *= ratio * ratio;
  return SubsurfaceExit{chosen.position, ng, ns, weight};
}

}  // namespace lacrima
