// HeapWarmup: makes the heap pages that this thread is about to allocate ready on a helper thread, while this
// thread does other work, for a one-shot process whose big allocations are made by a library it cannot change.
//
// The case it is for: `shadelab render` on Mesa's software rasterizer. llvmpipe zero-fills every texture it
// creates, on the thread that creates it, and a 1920x1080 render's RGB32F colour target and depth buffer are
// 8,000 fresh 4 KiB pages. On the development VM (a paravirtualised guest) each first touch of a page costs
// 6-12 µs, so the targets took 65-100 ms of the draw before a triangle was shaded, while the second core sat
// idle through the 100 ms of GL context creation just before.
//
// What it does: glibc's malloc is told to serve blocks up to kHeapWarmupLargestBlock from the heap instead of
// fresh mappings, and to keep freed heap memory (M_MMAP_THRESHOLD, M_TRIM_THRESHOLD); a block of `bytes` is
// allocated and freed at once, so that the heap's top holds that much untouched address space, and transparent
// huge pages are asked for over it; populate() then has a helper thread fault it all in at once
// (MADV_POPULATE_WRITE). The thread's later allocations are carved from pages that are already there.
// Reserving costs no memory; populating makes the range resident, so the caller populates only once it knows
// the work will go ahead (the scene has loaded), and a refused input never costs the warmed memory. Everything
// is advice: where the kernel or the C library declines (no glibc, an older kernel, huge pages off),
// allocations behave as before.
//
// Process-wide and not undone (the malloc settings stay), so for one-shot commands only, never a library call;
// and `bytes` should not exceed what the process will allocate, because populated pages count as resident.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <thread>

namespace shadelab {

// The largest block served from the heap once a HeapWarmup exists, and the most it warms.
inline constexpr size_t kHeapWarmupLargestBlock = size_t(256) << 20;

class HeapWarmup {
public:
    explicit HeapWarmup(size_t bytes);  // reserves, on the thread whose allocations are to be served
    ~HeapWarmup();                      // waits for the helper thread

    // Starts the helper thread that makes the reserved pages resident; from any thread, once (later calls do
    // nothing), and nothing when the constructor declined.
    void populate();

    // Gives back to the system the free memory that other threads' heaps and this heap's holes keep under
    // these settings (a parsed file's buffers, say), leaving the warmed top in place.
    void releaseFreedElsewhere();
    HeapWarmup(const HeapWarmup&) = delete;
    HeapWarmup& operator=(const HeapWarmup&) = delete;

private:
    // Unused where the warm-up is not built (no glibc: the web build).
    [[maybe_unused]] size_t bytes_ = 0;  // reserved, or 0 when the warm-up declined
    [[maybe_unused]] uintptr_t begin_ = 0, end_ = 0;
    [[maybe_unused]] std::atomic<bool> started_{false};
    std::thread helper_;
};

}  // namespace shadelab
