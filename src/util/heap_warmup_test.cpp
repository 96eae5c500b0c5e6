// Tests for util/heap_warmup.h: once a warm-up has run, a large block that this thread allocates arrives with
// its pages already resident (counted with mincore before any byte is written); the control is the same block
// allocated before the warm-up, which has none. Each runs in a child process, since the warm-up changes
// malloc's settings for the whole process.
#include "util/heap_warmup.h"

#include <gtest/gtest.h>

#include <sys/mman.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

#if defined(__GLIBC__) && defined(MADV_POPULATE_WRITE) && !defined(__SANITIZE_ADDRESS__)
constexpr size_t kPage = 4096;
constexpr size_t kBlock = size_t(8) << 20;

// Resident whole pages inside [p, p + bytes), and how many whole pages there are.
std::pair<size_t, size_t> residentPages(const void* p, size_t bytes) {
    const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + kPage - 1) & ~(kPage - 1);
    const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kPage - 1);
    std::vector<unsigned char> flags((end - begin) / kPage);
    if (mincore(reinterpret_cast<void*>(begin), end - begin, flags.data()) != 0) return {0, flags.size()};
    size_t resident = 0;
    for (unsigned char f : flags) resident += f & 1;
    return {resident, flags.size()};
}

// The child's side of each test: its exit code says whether the pages were as expected.
int laterBlockArrivesResident() {
    void* before = std::malloc(kBlock);  // the control: a fresh mapping, nothing resident yet
    const auto [coldResident, pages] = residentPages(before, kBlock);
    std::free(before);
    {
        shadelab::HeapWarmup warmup(size_t(32) << 20);
        warmup.populate();
    }  // returns once the pages are ready
    void* after = std::malloc(kBlock);
    const auto [warmResident, samePages] = residentPages(after, kBlock);
    std::fprintf(stderr, "resident pages of %zu: %zu before the warm-up, %zu after\n", pages, coldResident,
                 warmResident);
    std::free(after);
    return coldResident * 10 < pages && warmResident == samePages ? 0 : 1;
}

// Reserved but never populated (the input was refused): nothing became resident but the 2 MiB pages that
// malloc's own headers touched, the block's and the heap top's after it (512 small pages each).
int unpopulatedWarmupCostsNoMemory() {
    shadelab::HeapWarmup warmup(size_t(32) << 20);
    void* block = std::malloc(kBlock);
    const auto [resident, pages] = residentPages(block, kBlock);
    std::fprintf(stderr, "resident pages of %zu: %zu\n", pages, resident);
    std::free(block);
    return resident <= 2 * 512 && resident < pages ? 0 : 1;
}

int declinedWarmupLeavesMallocAlone() {
    for (size_t bytes : {size_t(4096), shadelab::kHeapWarmupLargestBlock + 1}) {
        shadelab::HeapWarmup declined(bytes);
        declined.populate();
    }
    void* block = std::malloc(kBlock);  // still a fresh mapping: malloc's settings were left alone
    const auto [resident, pages] = residentPages(block, kBlock);
    std::fprintf(stderr, "resident pages of %zu: %zu\n", pages, resident);
    std::free(block);
    return resident * 10 < pages ? 0 : 1;
}

class HeapWarmupDeathTest : public ::testing::Test {
protected:
    void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(HeapWarmupDeathTest, LaterBlocksArriveResident) {
    EXPECT_EXIT(std::exit(laterBlockArrivesResident()), ::testing::ExitedWithCode(0), "resident pages");
}

TEST_F(HeapWarmupDeathTest, ReservingAloneMakesNothingResident) {
    EXPECT_EXIT(std::exit(unpopulatedWarmupCostsNoMemory()), ::testing::ExitedWithCode(0), "resident pages");
}

TEST_F(HeapWarmupDeathTest, SmallOrHugeRequestsChangeNothing) {
    EXPECT_EXIT(std::exit(declinedWarmupLeavesMallocAlone()), ::testing::ExitedWithCode(0), "resident pages");
}
#endif

}  // namespace
