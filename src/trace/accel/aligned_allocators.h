// Allocators for the traversal's arrays: cache-line alignment for the builder's scratch, and transparent huge
// pages for the arrays every ray walks.
//
// Why huge pages: an incoherent ray touches about nine nodes and leaves spread over the whole tree, so with
// 4 KiB pages nearly every visit also misses the first-level TLB, and a tree of a few megabytes (2CylinderEngine:
// 4.4 MiB of nodes, 4 MiB of positions) outgrows even the second level. Backed by 2 MiB pages the same arrays
// need a handful of entries: the incoherent-ray benchmark ran 2 to 5 % faster (bench/README.md).
// Which arrays ask: only the finished ones (the builder's per-thread subtrees stay on ordinary pages, whose
// untouched reserve costs nothing), and only from 2 MiB (below, the rounding would cost more than the pages
// save) up to 64 MiB. Above that the first touch of huge pages dominates: on the development VM a 4.2 M-triangle
// tree (300 MiB of nodes and positions) built 0.4 to 1.1 s slower, because the kernel zeroes and the host backs
// each fresh 2 MiB page, while its rays, bound by memory latency, ran no faster.
// The request is advice (madvise MADV_HUGEPAGE, honoured where /sys/kernel/mm/transparent_hugepage/enabled is
// "madvise" or "always"); where the kernel declines, the memory is ordinary and everything works the same.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shadelab::trace {

inline constexpr size_t kHugePageBytes = size_t(2) << 20;
inline constexpr size_t kMaxHugePageArrayBytes = size_t(64) << 20;

// 64-byte aligned storage for std::vector. With HugePages, an array of kHugePageBytes to kMaxHugePageArrayBytes
// takes whole 2 MiB-aligned huge pages instead, advised as such.
template <class T, bool HugePages>
struct AlignedAllocator {
    using value_type = T;
    template <class U>
    struct rebind {
        using other = AlignedAllocator<U, HugePages>;
    };
    AlignedAllocator() = default;
    template <class U>
    AlignedAllocator(const AlignedAllocator<U, HugePages>&) {}

    static bool huge(size_t bytes) { return HugePages && bytes >= kHugePageBytes && bytes <= kMaxHugePageArrayBytes; }
    T* allocate(size_t n) {
        const size_t bytes = n * sizeof(T);
        if (!huge(bytes)) return static_cast<T*>(::operator new(bytes, std::align_val_t(64)));
        const size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
        void* p = std::aligned_alloc(kHugePageBytes, rounded);
        if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal leaves ordinary pages
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) {
        if (!huge(n * sizeof(T)))
            ::operator delete(p, std::align_val_t(64));
        else
            std::free(p);
    }
    // Stateless: any two allocate and free alike.
    template <class U>
    bool operator==(const AlignedAllocator<U, HugePages>&) const {
        return true;
    }
    template <class U>
    bool operator!=(const AlignedAllocator<U, HugePages>&) const {
        return false;
    }
};

template <class T>
using CacheLineAllocator = AlignedAllocator<T, false>;
template <class T>
using HugePageAllocator = AlignedAllocator<T, true>;

}  // namespace shadelab::trace
