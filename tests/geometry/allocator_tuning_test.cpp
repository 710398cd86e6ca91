// keepFreedMemoryForReuse: freed mesh-sized buffers stay mapped in the heap for the next ones.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <vector>

#include "lacrima/base/allocator_tuning.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace lacrima {
namespace allocator_tuning_test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kOwnAllocator = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
constexpr bool kOwnAllocator = true;
#else
constexpr bool kOwnAllocator = false;
#endif
#else
constexpr bool kOwnAllocator = false;
#endif

TEST(AllocatorTuning, FreedBuffersStayMappedForTheNextOnes) {
#if defined(__GLIBC__)
  if (kOwnAllocator) GTEST_SKIP() << "a sanitizer's allocator replaces glibc's malloc";
  keepFreedMemoryForReuse();
  // Sixty 1 MiB blocks, as a frame's posed fields: touched, then all freed.
  constexpr size_t kBlock = 1 << 20, kBlocks = 60;
  std::vector<void*> blocks;
  for (size_t i = 0; i < kBlocks; ++i) {
    blocks.push_back(std::malloc(kBlock));
    ASSERT_NE(blocks.back(), nullptr);
    std::memset(blocks.back(), 1, kBlock);
  }
  for (void* block : blocks) std::free(block);
  // glibc's defaults mmap each such block and unmap it when freed (or trim the heap's top), so
  // the heap would hold next to nothing free now; tuned, it keeps all of them.
  const struct mallinfo2 info = mallinfo2();
  EXPECT_GE(info.fordblks, kBlocks * kBlock) << "free bytes the heap still holds";
#else
  GTEST_SKIP() << "malloc is not glibc's";
#endif
}

// After returnFreedMemoryPromptly and a trim a mesh-sized block is mmapped again (and unmapped
// when freed); under keepFreedMemoryForReuse it comes from the heap.
TEST(AllocatorTuning, PromptReturnMmapsBigBlocksAgain) {
#if defined(__GLIBC__)
  if (kOwnAllocator) GTEST_SKIP() << "a sanitizer's allocator replaces glibc's malloc";
  const auto mmappedWhileHolding = [](size_t bytes) {
    [[maybe_unused]] static void* volatile escaped;  // so that the compiler cannot elide the malloc/free pair
    void* block = std::malloc(bytes);
    escaped = block;
    std::memset(block, 1, bytes);
    const size_t mmapped = mallinfo2().hblkhd;
    std::free(block);
    return mmapped;
  };
  keepFreedMemoryForReuse();
  const size_t before = mallinfo2().hblkhd;
  EXPECT_LT(mmappedWhileHolding(8 << 20), before + (8 << 20)) << "tuned: the block comes from the heap";
  returnFreedMemoryPromptly();
  malloc_trim(0);  // as `lacrima render` does after each frame: the heap's top is handed back
  // Larger than the free chunk the first block may have left inside the heap.
  EXPECT_GE(mmappedWhileHolding(16 << 20), before + (16 << 20)) << "prompt return: the block is mmapped";
  keepFreedMemoryForReuse();  // as the test executable's main left it
#else
  GTEST_SKIP() << "malloc is not glibc's";
#endif
}

}  // namespace allocator_tuning_test
}  // namespace lacrima
