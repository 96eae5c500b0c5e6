// parallelFor: body(task) for every task in [0, count) on `threads` workers (the caller's thread among
// them), tasks handed out one at a time through an atomic counter. Results that depend only on the task
// are then the same for any thread count. The workers are joined before it returns, even if one throws;
// the first exception is rethrown on the caller's thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace shadelab {

template <typename F>
void parallelFor(int count, int threads, F body) {
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    const auto work = [&] {
        try {
            for (int t = next++; t < count; t = next++) body(t);
        } catch (...) {
            next = count;  // the others stop at their next task
            const std::lock_guard<std::mutex> lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    const int n = std::max(1, std::min(threads, count));
    try {
        for (int i = 1; i < n; ++i) pool.emplace_back(work);
    } catch (...) {
        next = count;
        for (std::thread& t : pool) t.join();
        throw;
    }
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace shadelab
