// HeapWarmup (see heap_warmup.h).
#include "util/heap_warmup.h"

#include <cstdint>
#include <cstdlib>
#include <system_error>

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#endif

namespace shadelab {
namespace {

#if defined(__GLIBC__) && defined(MADV_HUGEPAGE) && defined(MADV_POPULATE_WRITE)
#define SHADELAB_HEAP_WARMUP 1
constexpr uintptr_t kPage = 4096, kHugePage = uintptr_t(2) << 20;

// Reserves `bytes` at the heap's top and returns the whole pages inside it, as addresses: the block is freed
// before return, and its pages are only advised, never read or written through a pointer.
bool reserveTop(size_t bytes, uintptr_t& begin, uintptr_t& end) {
    if (bytes > kHeapWarmupLargestBlock || mallopt(M_MMAP_THRESHOLD, int(kHeapWarmupLargestBlock)) == 0 ||
        mallopt(M_TRIM_THRESHOLD, 1 << 30) == 0)
        return false;
    void* block = std::malloc(bytes);
    if (!block) return false;
    const uintptr_t first = reinterpret_cast<uintptr_t>(block);
    // Whole pages inside the block only: its first and last page hold the allocator's own headers.
    begin = (first + kPage - 1) & ~(kPage - 1);
    end = (first + bytes) & ~(kPage - 1);
    std::free(block);  // merges into the top chunk; M_TRIM_THRESHOLD keeps it mapped
    return end > begin;
}
#endif

}  // namespace

HeapWarmup::HeapWarmup([[maybe_unused]] size_t bytes) {
#if SHADELAB_HEAP_WARMUP
    if (bytes < kHugePage || !reserveTop(bytes, begin_, end_)) return;
    bytes_ = bytes;
    // 2 MiB pages wherever the range holds whole ones: one fault (or one populated page) for 512.
    const uintptr_t hugeBegin = (begin_ + kHugePage - 1) & ~(kHugePage - 1), hugeEnd = end_ & ~(kHugePage - 1);
    if (hugeEnd > hugeBegin) madvise(reinterpret_cast<void*>(hugeBegin), hugeEnd - hugeBegin, MADV_HUGEPAGE);
#endif
}

void HeapWarmup::populate() {
#if SHADELAB_HEAP_WARMUP
    if (bytes_ == 0 || started_.exchange(true)) return;
    try {
        helper_ = std::thread([begin = begin_, end = end_] {
            madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
        });
    } catch (const std::system_error&) {
        // no thread to spare: the pages come one fault at a time, as without the warm-up
    }
#endif
}

void HeapWarmup::releaseFreedElsewhere() {
#if SHADELAB_HEAP_WARMUP
    if (bytes_ > 0) malloc_trim(bytes_);
#endif
}

HeapWarmup::~HeapWarmup() {
    if (helper_.joinable()) helper_.join();
}

}  // namespace shadelab
