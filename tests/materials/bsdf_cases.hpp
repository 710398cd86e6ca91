#pragma once
// The non-delta BSDF configurations exercised by the statistical tests: every family, several
// roughness values, light arriving from outside and (for the dielectric) from inside, near normal
// (|cos| = 0.99) and grazing (|cos| = 0.15) incidence.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lacrima/materials/material.hpp"
#include "test_support.hpp"

namespace lacrima::test {

struct BsdfCase {
  std::string name;
  MaterialParams params;
  float cosThetaO;  // negative: wo inside the medium (below the surface)
};

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
