// The allocator settings for many short runs (model/allocator_reuse.hpp).

#include <gtest/gtest.h>

#include <cstdlib>

#include "model/allocator_reuse.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vi {
namespace {

// A block of a few MiB, the size of a contact decomposition at m = 50, comes from the heap and
// stays there when freed, instead of being mapped and unmapped on each run.
TEST(AllocatorReuse, AFewMebibytesComeFromTheHeapAndStay) {
#if !defined(__GLIBC__) || VI_SANITIZE_BUILD
    GTEST_SKIP() << "glibc's own allocator only (the sanitizers replace it)";
#else
    keep_freed_memory_for_reuse();
    keep_freed_memory_for_reuse();  // idempotent
    const std::size_t before = mallinfo2().hblks;
    void* volatile p = std::malloc(std::size_t{4} << 20);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(mallinfo2().hblks, before);  // not a mapping of its own
    std::free(p);
    const std::size_t kept = mallinfo2().fordblks;
    EXPECT_GE(kept, std::size_t{4} << 20);  // freed, still held for the next run
#endif
}

}  // namespace
}  // namespace vi
