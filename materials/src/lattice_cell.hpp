#pragma once
// The cell of a cubic lattice of spacing `scale` that holds a world position, and the position
// within it: shared by the cellular fields of the skin's relief (pores.cpp, furrows.cpp).
#include <cmath>
#include <cstdint>

#include "lacrima/base/math.hpp"

namespace lacrima {

struct LatticeCell {
  int64_t i, j, k;  // the cell's integer coordinates
  Vec3 local;       // the position relative to the cell's corner, in lattice units ([0, 1) each)
};

inline LatticeCell latticeCellOf(const Vec3& p, float scale) {
  // Double for the floor so that large world coordinates keep their cells; relative to the cell
  // corner, so that the float differences the fields take stay small.
  const Vec3d q = p.cast<double>() / double(scale);
  const int64_t ci = int64_t(std::floor(q.x())), cj = int64_t(std::floor(q.y())), ck = int64_t(std::floor(q.z()));
  return {ci, cj, ck, (q - Vec3d(double(ci), double(cj), double(ck))).cast<float>()};
}

}  // namespace lacrima
