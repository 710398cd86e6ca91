#pragma once
// Per-vertex loops split between threads over fixed ranges of vertex indices. Each vertex is computed
// as a serial loop would (same operations, same order), so any split gives the same bits.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>
#include <cstdint>

namespace lacrima {

inline constexpr uint32_t kVerticesPerTask = 8192;

// body(begin, end) for consecutive ranges covering [0, count).
template <typename Body>
void forVertexRanges(size_t count, Body body) {
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(count), kVerticesPerTask),
                    [&](const tbb::blocked_range<uint32_t>& r) { body(r.begin(), r.end()); });
}

}  // namespace lacrima
