// makeBsdf: the one place where a material description becomes a BSDF.
#include "lacrima/materials/material.hpp"

#include <type_traits>

#include "lacrima/materials/diffuse.hpp"
#include "lacrima/materials/rough_dielectric.hpp"
#include "lacrima/materials/skin.hpp"
#include "lacrima/materials/smooth_dielectric.hpp"
#include "lacrima/materials/thin_dielectric.hpp"

namespace lacrima {

std::unique_ptr<Bsdf> makeBsdf(const MaterialParams& params) {
  return std::visit(
      [](const auto& p) -> std::unique_ptr<Bsdf> {
        using P = std::decay_t<decltype(p)>;
        if constexpr (std::is_same_v<P, DiffuseParams>) {
          return std::make_unique<DiffuseBsdf>(p);
        } else if constexpr (std::is_same_v<P, SkinParams>) {
          return std::make_unique<SkinBsdf>(p);
        } else if constexpr (std::is_same_v<P, SmoothDielectricParams>) {
          return std::make_unique<SmoothDielectricBsdf>(p);
        } else {
          static_assert(std::is_same_v<P, RoughDielectricParams>, "makeBsdf: unhandled MaterialParams alternative");
          return std::make_unique<RoughDielectricBsdf>(p);
        }
      },
      params);
}

std::unique_ptr<Bsdf> makeThinSheetBsdf(const MaterialParams& params) {
  if (const auto* smooth = std::get_if<SmoothDielectricParams>(&params))
    return std::make_unique<ThinDielectricBsdf>(smooth->ior, smooth->tint);
  if (const auto* rough = std::get_if<RoughDielectricParams>(&params))
    return std::make_unique<ThinDielectricBsdf>(rough->ior, rough->tint);
  return nullptr;
}

std::optional<DielectricMedium> dielectricMedium(const MaterialParams& params) {
  if (const auto* smooth = std::get_if<SmoothDielectricParams>(&params)) return DielectricMedium{smooth->ior, smooth->priority};
  if (const auto* rough = std::get_if<RoughDielectricParams>(&params)) return DielectricMedium{rough->ior, rough->priority};
  return std::nullopt;
}

MaterialParams againstMedium(const MaterialParams& params, float outsideIor) {
  if (const auto* smooth = std::get_if<SmoothDielectricParams>(&params)) {
    SmoothDielectricParams p = *smooth;
    p.ior = smooth->ior / outsideIor;
    return p;
  }
  if (const auto* rough = std::get_if<RoughDielectricParams>(&params)) {
    const float ior = rough->ior / outsideIor;
    if (ior == 1.0f) return SmoothDielectricParams{ior, rough->tint, rough->priority};
    RoughDielectricParams p = *rough;
    p.ior = ior;
    return p;
  }
  return params;
}

}  // namespace lacrima
