#pragma once
// Items listed by bucket (grid cell, bin), stored flat: a counting sort. Bucket b's items are
// items[first[b]] to items[first[b + 1]], in the order they were visited. Spatial grids build one
// per frame or per query batch (the wet film's pieces and skin vertices by cell, a bead's skin
// triangles by shadow), so it is two passes over the pairs and two allocations, no vector per bucket.
#include <cstdint>
#include <span>
#include <vector>

namespace lacrima {

struct BucketLists {
  std::vector<uint32_t> first;  // per bucket, where its items start (one more at the end)
  std::vector<uint32_t> items;  // item indices, bucket after bucket

  size_t bucketCount() const { return first.empty() ? 0 : first.size() - 1; }
  std::span<const uint32_t> in(size_t bucket) const {
    return {items.data() + first[bucket], items.data() + first[bucket + 1]};
  }
};

// forEachPair(visit) must call visit(item, bucket) for every pair, the same pairs in the same order
// each time it is called (it is called twice: to count, then to fill).
template <typename ForEachPair>
BucketLists makeBucketLists(size_t bucketCount, ForEachPair forEachPair) {
  BucketLists lists;
  lists.first.assign(bucketCount + 1, 0);
  forEachPair([&](uint32_t, size_t bucket) { ++lists.first[bucket + 1]; });
  for (size_t b = 1; b < lists.first.size(); ++b) lists.first[b] += lists.first[b - 1];
  lists.items.resize(lists.first.back());
  std::vector<uint32_t> filled(lists.first.begin(), lists.first.end() - 1);
  forEachPair([&](uint32_t item, size_t bucket) { lists.items[filled[bucket]++] = item; });
  return lists;
}

}  // namespace lacrima
