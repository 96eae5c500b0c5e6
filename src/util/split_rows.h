// splitRows: runs a row loop on up to two threads (the calling one and one more), for the texture work the
// glTF import and the rasterizer's upload do on large images. Each part gets a contiguous range of rows, so
// the result is the same as one loop's. `work` must not throw.
#pragma once

#include <algorithm>
#include <thread>

namespace shadelab {

// Calls work(begin, end) over [0, rows): twice, on halves, when rows · rowCost reaches `minWork` and the
// machine has more than one hardware thread; otherwise once.
template <class Work>
void splitRows(int rows, long long rowCost, long long minWork, Work work) {
    if (rows < 2 || static_cast<long long>(rows) * rowCost < minWork || std::thread::hardware_concurrency() < 2) {
        work(0, rows);
        return;
    }
    const int half = rows / 2;
    std::thread other([&work, half, rows] { work(half, rows); });
    work(0, half);
    other.join();
}

}  // namespace shadelab
