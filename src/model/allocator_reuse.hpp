#pragma once
// Allocator settings for many short runs in one process (sweep points, a study's transients).

namespace vi {

// Keeps freed heap memory in the process for the next allocation instead of handing it back to the
// system at once (glibc: blocks up to 32 MiB from the heap, the heap's top trimmed only beyond
// 256 MiB free). Each exact run allocates and frees its contact decompositions (a few MiB at
// m = 50); handed back, every run takes them again as fresh zeroed pages, about 5 % of a sweep
// point's CPU time. Idempotent; a no-op on other C libraries.
void keep_freed_memory_for_reuse();

}  // namespace vi
