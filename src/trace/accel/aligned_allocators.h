// Allocators for the traversal's arrays: cache-line alignment for the builder's scratch, and transparent huge
// pages for the arrays every ray walks. Neither zeroes what a vector sizes (construct, below).
//
// Why huge pages: an incoherent ray touches about nine nodes and leaves spread over the whole tree, so with
// 4 KiB pages nearly every visit also misses the first-level TLB, and a tree of a few megabytes (2CylinderEngine:
// 4.4 MiB of nodes, 4 MiB of positions) outgrows even the second level. Backed by 2 MiB pages the same arrays
// need a handful of entries: the incoherent-ray benchmark ran 2 to 5 % faster (bench/README.md).
// Which arrays ask: the finished ones, the builder's references and its per-thread subtrees (whose untouched
// reserve costs nothing on either kind of page), and only from 2 MiB (below, the rounding would cost more than
// the pages save) up to 1 GiB. On the development VM each first touch of a 4 KiB page costs 6-12 us
// (a paravirtualised guest), so the 4.2 M-triangle build's 430 MB of references, nodes and positions took about
// 1 s of faults on ordinary pages; on huge pages, written by the threads that fill them and never zeroed first,
// that build took 1.5-1.8 s instead of 2.4-3.2 s (bench/README.md, 2026-12-07). An earlier measurement, when
// the arrays were zero-filled on one thread first, found huge pages 0.4-1.1 s slower: the kernel zeroes each
// fresh 2 MiB page, and the host backs it, at its first touch, whose cost varies with the host's state.
// The request is advice (madvise MADV_HUGEPAGE, honoured where /sys/kernel/mm/transparent_hugepage/enabled is
// "madvise" or "always"); where the kernel declines, the memory is ordinary and everything works the same.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace shadelab::trace {

inline constexpr size_t kHugePageBytes = size_t(2) << 20;
inline constexpr size_t kMaxHugePageArrayBytes = size_t(1) << 30;

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
    // A vector's resize (and emplace_back without arguments) leaves the elements default-initialised, which
    // for the trivial types here means untouched: every array here is written whole right after it is sized,
    // in parallel by the threads that fill it, so that write is each page's first touch, instead of a
    // zero fill on one thread first (on the development VM a first touch costs 6-12 us per 4 KiB page: zeroing
    // the 4.2 M-triangle build's references and positions, 285 MB, took 0.75 s of its 2.5 s).
    template <class U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
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
