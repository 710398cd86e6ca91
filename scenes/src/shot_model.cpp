// Small helpers of the plain-data Shot.
#include "lacrima/scenes/shot.hpp"

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

Affine3 ShotTransform::matrix() const {
  Affine3 m = Affine3::Identity();
  m.translate(translate);
  m.linear() = rotation * scale.asDiagonal();
  return m;
}

}  // namespace lacrima
