// ShotReader (shot_reader.hpp): the section "flesh" (docs/shot-format.md).
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kFleshMaterials = {"fixedCorotated", "stVenantKirchhoff"};  // readFlesh's order
const std::vector<std::string> kFleshIntegrators = {"backwardEuler", "midpoint"};         // readFlesh's order

}  // namespace

// A simulated flesh volume (docs/shot-format.md "flesh"; ShotFlesh).
void ShotReader::readFlesh(const Json& v, const std::string& pointer) {
  ObjectReader o(c_, v, pointer,
                 {"asset", "part", "regions", "depth", "tetSize", "youngsModulus", "poisson", "density", "damping",
                  "substeps", "material", "integrator"});
  if (!o.ok()) return;
  const size_t before = c_.errorCount();
  ShotFlesh flesh;
  flesh.pointer = pointer;
  const auto asset = readAssetPart(o, flesh.part);
  if (asset) flesh.asset = *asset;
  if (asset) {
    if (o.has("regions"))
      readSkinRegions(o, *asset, flesh.part, flesh.regions);
    else
      o.missing("regions", "an array of regions {\"center\", \"radius\"} of the skin to simulate the flesh under");
  }
  if (auto x = o.number("depth", Range::above(0))) flesh.volume.depth = *x;
  // The largest tetrahedron's edge: TetGen's volume bound is that of a regular tetrahedron.
  if (auto x = o.number("tetSize", Range::above(0))) flesh.volume.maxTetVolume = flesh::regularTetVolume(*x);
  if (auto x = o.number("youngsModulus", Range::above(0))) flesh.youngsModulus = *x;
  if (auto x = o.number("poisson", Range::open(-1, 0.5))) flesh.poissonRatio = *x;
  if (auto x = o.number("density", Range::above(0))) flesh.dynamics.density = *x;
  if (auto x = o.integer("substeps", Range::closed(1, 64))) flesh.substeps = int(*x);
  static constexpr flesh::FleshMaterial materials[] = {flesh::FleshMaterial::FixedCorotated,
                                                       flesh::FleshMaterial::StVenantKirchhoff};
  if (const auto i = readChoice(o, "material", kFleshMaterials, "flesh material")) flesh.material = materials[*i];
  static constexpr flesh::FleshIntegrator integrators[] = {flesh::FleshIntegrator::BackwardEuler,
                                                           flesh::FleshIntegrator::ImplicitMidpoint};
  if (const auto i = readChoice(o, "integrator", kFleshIntegrators, "integrator")) flesh.dynamics.integrator = integrators[*i];
  if (const Json* d = o.find("damping")) {
    ObjectReader r(c_, *d, o.at("damping"), {"mass", "stiffness"});
    if (r.ok()) {
      if (auto x = r.number("mass", Range::atLeast(0))) flesh.dynamics.massDamping = *x;
      if (auto x = r.number("stiffness", Range::atLeast(0))) flesh.dynamics.stiffnessDamping = *x;
    }
  }
  if (c_.errorCount() == before && asset) shot_.flesh.push_back(flesh);
}

}  // namespace lacrima::shotfile
