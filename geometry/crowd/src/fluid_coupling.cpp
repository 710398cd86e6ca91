// A liquid's particles pushing crowd agents; see fluid_coupling.hpp.
#include "lacrima/crowd/fluid_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace lacrima::crowd {

namespace {

// A ground cell as one sortable key.
uint64_t cellKey(long i, long j) { return (uint64_t(uint32_t(int32_t(i))) << 32) | uint64_t(uint32_t(int32_t(j))); }
long cellCoordinate(double x, double size) { return long(std::floor(x / size)); }

// The particles sorted by ground cell (and index within a cell): each cell's particles are one run.
struct CellIndex {
  std::vector<std::pair<uint64_t, uint32_t>> entries;
  explicit CellIndex(const std::vector<Vec3d>& positions, double size) {
    entries.reserve(positions.size());
    for (uint32_t i = 0; i < positions.size(); ++i)
      entries.emplace_back(cellKey(cellCoordinate(positions[i].x(), size), cellCoordinate(positions[i].z(), size)), i);
    std::sort(entries.begin(), entries.end());
  }
  template <typename Visit>
  void forEachIn(uint64_t key, const Visit& visit) const {
    auto it = std::lower_bound(entries.begin(), entries.end(), std::make_pair(key, uint32_t(0)));
    for (; it != entries.end() && it->first == key; ++it) visit(it->second);
  }
};

}  // namespace

double FluidContact::groundSpeed() const {
  return mass > 0.0 ? std::hypot(momentum.x(), momentum.z()) / mass : 0.0;
}

std::vector<FluidContact> fluidContacts(const std::vector<Vec2d>& agentPositions, const std::vector<Vec3d>& particlePositions,
                                        const std::vector<Vec3d>& particleVelocities, double particleMass,
                                        const CouplingParams& params) {
  if (particlePositions.size() != particleVelocities.size())
    throw std::invalid_argument("fluidContacts: one velocity per particle");
  if (!(params.cellSize >= params.particleRadius + params.agentRadius))
    throw std::invalid_argument("fluidContacts: cells must be at least r_p + r_a wide, or collisions are missed");
  const CellIndex cells(particlePositions, params.cellSize);
  const double reach = params.particleRadius + params.agentRadius;
  std::vector<FluidContact> contacts(agentPositions.size());
  std::vector<uint32_t> colliding;
  for (size_t a = 0; a < agentPositions.size(); ++a) {
    const long ci = cellCoordinate(agentPositions[a].x(), params.cellSize);
    const long cj = cellCoordinate(agentPositions[a].y(), params.cellSize);
    colliding.clear();
    for (long dj = -1; dj <= 1; ++dj)
      for (long di = -1; di <= 1; ++di)
        cells.forEachIn(cellKey(ci + di, cj + dj), [&](uint32_t i) {
          const Vec2d ground(particlePositions[i].x(), particlePositions[i].z());
          if ((ground - agentPositions[a]).norm() < reach) colliding.push_back(i);
        });
    std::sort(colliding.begin(), colliding.end());  // sums in index order
    FluidContact& contact = contacts[a];
    for (uint32_t i : colliding) {
      contact.momentum += particleMass * particleVelocities[i];  // eq. 5
      contact.mass += particleMass;
      contact.meanHeight += particlePositions[i].y();
      ++contact.particles;
    }
    if (contact.particles > 0) contact.meanHeight /= double(contact.particles);
  }
  return contacts;
}

Vec2d coupledVelocity(double agentMass, const Vec2d& walkingVelocity, double endurance, const FluidContact& contact) {
  const double tau = std::clamp(endurance, 0.0, 1.0);
  const Vec2d walkingMomentum = agentMass * walkingVelocity;                      // p_B
  const Vec2d fluidMomentum(contact.momentum.x(), contact.momentum.z());          // p_F on the ground
  return (walkingMomentum + tau * fluidMomentum) / (agentMass + tau * contact.mass);  // eq. 9
}

bool carriedAsRagdoll(double endurance, const FluidContact& contact, const CouplingParams& params) {
  return contact.particles > 0 && endurance >= params.ragdollEndurance && contact.groundSpeed() > params.ragdollSpeed;
}

}  // namespace lacrima::crowd
