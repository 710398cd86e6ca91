#pragma once
// The non-delta BSDF configurations exercised by the statistical tests: every family, several
// roughness values, light arriving from outside and (for the dielectric) from inside, near normal
// (|cos| = 0.99) and grazing (|cos| = 0.15) incidence. Wet skin (wet_skin.hpp) is skin params
// with a film coverage > 0.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lacrima/materials/material.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "materials_support.hpp"

namespace lacrima::test {

struct BsdfCase {
  std::string name;
  MaterialParams params;
  float cosThetaO;  // negative: wo inside the medium (below the surface)
  float wetCoverage = 0.0f;  // > 0: a WetSkinBsdf over the SkinParams with this film coverage
};

// makeBsdf, or the wet skin when wetCoverage > 0 (params must then be SkinParams).
inline std::unique_ptr<Bsdf> makeCaseBsdf(const MaterialParams& params, float wetCoverage) {
  if (wetCoverage > 0.0f) return std::make_unique<WetSkinBsdf>(SkinBsdf(std::get<SkinParams>(params)), wetCoverage);
  return makeBsdf(params);
}

inline Vec3 caseWo(const BsdfCase& c) { return directionFromCosPhi(c.cosThetaO, 0.3); }

inline std::vector<BsdfCase> chi2Cases() {
  std::vector<BsdfCase> cases;
  for (const auto& [incidence, cosO] : {std::pair{"normal", 0.99f}, std::pair{"grazing", 0.15f}}) {
    cases.push_back({std::string("diffuse_") + incidence, DiffuseParams{}, cosO});
  }
  for (const auto& [label, roughness] : {std::pair{"r035", 0.35f}, std::pair{"r015", 0.15f}}) {
    for (const auto& [incidence, cosO] : {std::pair{"normal", 0.99f}, std::pair{"grazing", 0.15f}}) {
      SkinParams p;
      p.roughness = roughness;
      cases.push_back({std::string("skin_") + label + "_" + incidence, p, cosO});
    }
  }
  // Dual-lobe skin: (sharper roughness, broader roughness, weight of the broader lobe).
  struct DualLobe {
    const char* label;
    float r1, r2, mix;
  };
  for (const DualLobe& d : {DualLobe{"r03_r06_w05", 0.3f, 0.6f, 0.5f}, DualLobe{"r015_r07_w02", 0.15f, 0.7f, 0.2f},
                            DualLobe{"r035_r05_w09", 0.35f, 0.5f, 0.9f}}) {
    for (const auto& [incidence, cosO] : {std::pair{"normal", 0.99f}, std::pair{"grazing", 0.15f}}) {
      SkinParams p;
      p.roughness = d.r1;
      p.roughness2 = d.r2;
      p.lobeMix = d.mix;
      cases.push_back({std::string("skin_dual_") + d.label + "_" + incidence, p, cosO});
    }
  }
  // Skin with subsurface: the specular lobes alone (the random walk replaces the base).
  for (const auto& [incidence, cosO] : {std::pair{"normal", 0.99f}, std::pair{"grazing", 0.15f}}) {
    SkinParams p;
    p.roughness = 0.3f;
    p.roughness2 = 0.6f;
    p.lobeMix = 0.5f;
    p.subsurface = SubsurfaceParams{};
    cases.push_back({std::string("skin_subsurface_") + incidence, p, cosO});
  }
  // Wet skin: half and fully covered, over a dual-lobe skin.
  for (const auto& [label, coverage] : {std::pair{"c05", 0.5f}, std::pair{"c1", 1.0f}}) {
    for (const auto& [incidence, cosO] : {std::pair{"normal", 0.99f}, std::pair{"grazing", 0.15f}}) {
      SkinParams p;
      p.roughness2 = 0.6f;
      p.lobeMix = 0.3f;
      cases.push_back({std::string("wet_skin_") + label + "_" + incidence, p, cosO, coverage});
      // Over subsurface skin: the coat and the skin's lobes alone (the walk serves both bases).
      p.subsurface = SubsurfaceParams{};
      cases.push_back({std::string("wet_skin_subsurface_") + label + "_" + incidence, p, cosO, coverage});
    }
  }
  for (const auto& [label, roughness] : {std::pair{"r02", 0.2f}, std::pair{"r05", 0.5f}, std::pair{"r09", 0.9f}}) {
    for (const auto& [side, sign] : {std::pair{"outside", 1.0f}, std::pair{"inside", -1.0f}}) {
      for (const auto& [incidence, cosO] : {std::pair{"normal", 0.99f}, std::pair{"grazing", 0.15f}}) {
        RoughDielectricParams p;
        p.roughness = roughness;
        cases.push_back({std::string("rough_dielectric_") + label + "_" + side + "_" + incidence, p, sign * cosO});
      }
    }
  }
  return cases;
}

}  // namespace lacrima::test
