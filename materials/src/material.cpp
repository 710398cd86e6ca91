// makeBsdf: the one place where a material description becomes a BSDF.
#include "lacrima/materials/material.hpp"

#include <type_traits>

#include "lacrima/materials/diffuse.hpp"
#include "lacrima/materials/rough_dielectric.hpp"
#include "lacrima/materials/skin.hpp"
#include "lacrima/materials/smooth_dielectric.hpp"

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

}  // namespace lacrima
