#pragma once
// Nested dielectrics with priorities (Schmidt & Budge 2002, "Simple Nested Dielectrics in Ray
// Traced Images", JGT 7(2)): a path carries the stack of dielectric media it is inside. Where
// volumes overlap (tear film on the cornea, a drop on a wet film), the medium with the highest
// priority fills the overlap; a surface met inside a higher-priority medium is a "false"
// interface that the path crosses without scattering. A real interface separates the hit
// medium from the highest-priority other medium present, so it refracts with the pair of
// indices actually present instead of the medium's index against air.
//
// Rules (priority 0 is the default and keeps the plain model exactly):
//   - entering or leaving is decided by the geometric normal (it points out of the medium);
//   - "others" = the stack without the hit medium's own entry; "current" = the highest-priority
//     medium of the others, ties going to the most recently entered;
//   - the hit is false when current has a higher priority, or when the hit medium has priority
//     >= 1 and current is the same material (overlapping drops of one liquid merge);
//   - a real priority-0 surface is an interface with air (as before nested dielectrics); a real
//     surface of priority >= 1 is an interface with current (air when the stack is empty).
// The stack has a fixed capacity (no allocation per ray): entering beyond it is not recorded,
// so inside more than kCapacity nested volumes the innermost ones are not seen as surrounding
// media (their inner surfaces meet the outer medium's index); nothing crashes.
#include <array>
#include <cstdint>

namespace lacrima {

struct MediumEntry {
  uint32_t materialId = 0;
  int priority = 0;
};

// What a path meets at a dielectric surface.
struct InterfaceCrossing {
  bool isFalse = false;   // skip it: no scattering, no Fresnel, only the stack changes
  int otherMaterial = -1;  // the medium on the other side of a real interface; -1 = air
};

class MediumStack {
 public:
  static constexpr int kCapacity = 8;

  int size() const { return size_; }
  const MediumEntry& operator[](int i) const { return entries_[i]; }

  // Ignored when the stack is full (see the header comment).
  void enter(const MediumEntry& medium) {
    if (size_ < kCapacity) entries_[size_++] = medium;
  }

  // Removes the most recent entry of materialId; nothing when the path is not inside it.
  void leave(uint32_t materialId) {
    const int i = mostRecent(materialId);
    if (i < 0) return;
    for (int j = i; j + 1 < size_; ++j) entries_[j] = entries_[j + 1];
    --size_;
  }

  void cross(const MediumEntry& medium, bool entering) {
    if (entering) enter(medium);
    else leave(medium.materialId);
  }

  // Classifies a surface of `hit` met while entering or leaving it (rules above).
  InterfaceCrossing classify(const MediumEntry& hit, bool entering) const {
    const int skip = entering ? -1 : mostRecent(hit.materialId);
    const int current = currentIndex(skip);
    if (current < 0) return {false, -1};
    const MediumEntry& other = entries_[current];
    if (other.priority > hit.priority || (hit.priority > 0 && other.materialId == hit.materialId)) return {true, -1};
    if (hit.priority == 0) return {false, -1};
    return {false, int(other.materialId)};
  }

 private:
  // Index of the most recent entry of materialId, or -1.
  int mostRecent(uint32_t materialId) const {
    for (int i = size_ - 1; i >= 0; --i)
      if (entries_[i].materialId == materialId) return i;
    return -1;
  }

  // Highest priority, most recent on ties, ignoring index `skip`; -1 when there is none.
  int currentIndex(int skip) const {
    int best = -1;
    for (int i = 0; i < size_; ++i)
      if (i != skip && (best < 0 || entries_[i].priority >= entries_[best].priority)) best = i;
    return best;
  }

  std::array<MediumEntry, kCapacity> entries_{};
  int size_ = 0;
};

}  // namespace lacrima
