#include "image/denoise_memory.h"

#include <mutex>
#include <utility>

namespace shadelab::denoise_detail {
namespace {

std::mutex keptMutex;
std::unique_ptr<float[]> kept;  // guarded by keptMutex
size_t keptFloats = 0;          // guarded by keptMutex

}  // namespace

DenoiseMemory::DenoiseMemory(size_t floats) {
    {
        const std::lock_guard<std::mutex> lock(keptMutex);
        if (kept && keptFloats >= floats) {
            block_ = std::move(kept);
            floats_ = keptFloats;
            keptFloats = 0;
            return;
        }
    }
    block_.reset(new float[floats]);
    floats_ = floats;
}

DenoiseMemory::~DenoiseMemory() {
    if (floats_ > kKeptFloats) return;
    const std::lock_guard<std::mutex> lock(keptMutex);
    if (!kept || keptFloats < floats_) {
        kept = std::move(block_);
        keptFloats = floats_;
    }
}

}  // namespace shadelab::denoise_detail
