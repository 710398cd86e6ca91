#include "lacrima/base/allocator_tuning.hpp"

#include <cstdlib>  // on glibc, defines __GLIBC__ (features.h)
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lacrima {

void keepFreedMemoryForReuse() {
#if defined(__GLIBC__)
  constexpr int kLargestHeapBlock = 32 << 20;  // glibc's largest mmap threshold (64-bit)
  constexpr int kKeptFreeBytes = 1 << 30;
  // Either setting also stops glibc from moving the threshold itself (mallopt(3)).
  mallopt(M_MMAP_THRESHOLD, kLargestHeapBlock);
  mallopt(M_TOP_PAD, kKeptFreeBytes);
#endif
}

void returnFreedMemoryPromptly() {
#if defined(__GLIBC__)
  constexpr int kGlibcDefault = 128 << 10;  // both thresholds' defaults, mallopt(3)
  mallopt(M_MMAP_THRESHOLD, kGlibcDefault);
  mallopt(M_TOP_PAD, kGlibcDefault);
#endif
}

}  // namespace lacrima
