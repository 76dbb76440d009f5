// The allocator tuning: after it, an 8 MiB block (an activation tensor of a training step) comes from the heap
// and is reused, where glibc's default serves it by mmap and unmaps it on free.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/host_memory.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace t2imu {
namespace {

TEST(HostMemory, LargeBlocksComeFromTheHeapAndAreKept) {
#if !defined(__GLIBC__)
    GTEST_SKIP() << "glibc only";
#else
    keep_freed_memory_for_reuse();
    const size_t size = 8u << 20;
    const size_t mmapped_before = mallinfo2().hblkhd;
    void* block = std::malloc(size);
    ASSERT_NE(block, nullptr);
    static_cast<volatile char*>(block)[size - 1] = 1;
    EXPECT_LT(mallinfo2().hblkhd, mmapped_before + size) << "the 8 MiB block was mmapped";
    std::free(block);
    const size_t heap_after_free = mallinfo2().arena;
    void* again = std::malloc(size);
    EXPECT_EQ(mallinfo2().arena, heap_after_free) << "the heap grew again: the freed block was given back";
    std::free(again);
#endif
}

}  // namespace
}  // namespace t2imu
