#pragma once
// One camera path's contributions sorted into the light-path AOVs (light_paths.hpp), for the
// integrator. Does nothing when it has nowhere to write (no pass is rendered).
#include "lacrima/base/math.hpp"
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/renderer/light_paths.hpp"

namespace lacrima {

class LightPathSplit {
 public:
  // passes: kLightPathCount colours, zeroed by the caller; null: no split.
  explicit LightPathSplit(Color* passes) : passes_(passes) {}
  bool active() const { return passes_ != nullptr; }

  // Light the camera sees with no scattering on the way: an emitter or the environment.
  void seenDirectly(const Color& contribution, LightPath pass) {
    if (passes_) at(pass) += contribution;
  }
  // Light from an emitter or the environment that the path hit at `depth` (0: the camera saw it,
  // as `seenAs`; 1: the first bounce's direction hit it, direct; deeper: indirect).
  void lightHit(const Color& contribution, int depth, LightPath seenAs) {
    if (depth == 0) seenDirectly(contribution, seenAs);
    else afterFirstBounce(contribution, depth == 1);
  }
  // The first vertex's next-event estimate, with the lobes of f towards the light.
  void firstVertexDirect(const Color& contribution, const BsdfLobes& lobes) {
    if (passes_) split(contribution, sharesOf(lobes), true);
  }
  // Light that went through the skin below the first vertex.
  void belowFirstVertex(const Color& contribution) {
    if (passes_) at(LightPath::Subsurface) += contribution;
  }
  // How the path left its first vertex: below the skin, by a delta lobe, or by a sampled direction
  // whose f has these lobes.
  void leftBelowTheSkin() { below_ = true; }
  void leftByDeltaLobe(bool transmitted) {
    shares_ = {};
    (transmitted ? shares_.transmission : shares_.glossy) = Color::Ones();
  }
  void leftWithLobes(const BsdfLobes& lobes) { shares_ = sharesOf(lobes); }
  // Light gathered after the first bounce: direct when it is the light the bounce's direction hit.
  void afterFirstBounce(const Color& contribution, bool direct) {
    if (!passes_) return;
    if (below_) at(LightPath::Subsurface) += contribution;
    else split(contribution, shares_, direct);
  }

 private:
  // Each lobe's share of f, per channel (they add up to 1 where f is not 0).
  static BsdfLobes sharesOf(const BsdfLobes& lobes) {
    const Color total = lobes.sum();
    const Color divisor = (total > 0.0f).select(total, Color::Ones());  // no division by 0, even unused
    const auto share = [&](const Color& lobe) -> Color { return (total > 0.0f).select(lobe / divisor, 0.0f); };
    return {share(lobes.diffuse), share(lobes.glossy), share(lobes.transmission)};
  }
  void split(const Color& contribution, const BsdfLobes& shares, bool direct) {
    at(direct ? LightPath::DiffuseDirect : LightPath::DiffuseIndirect) += contribution * shares.diffuse;
    at(direct ? LightPath::SpecularDirect : LightPath::SpecularIndirect) += contribution * shares.glossy;
    at(direct ? LightPath::TransmissionDirect : LightPath::TransmissionIndirect) += contribution * shares.transmission;
  }
  Color& at(LightPath pass) { return passes_[size_t(pass)]; }

  Color* passes_;
  BsdfLobes shares_;    // of the first bounce's direction
  bool below_ = false;  // the path went on from an exit below the skin
};

}  // namespace lacrima
