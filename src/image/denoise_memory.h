// The denoiser's working memory (image/denoise_layout.h), kept from one call to the next: a preview denoises
// every frame at one size, and fresh memory costs the kernel a page fault and a page cleared per 4 KiB, a
// third of the filter's time at 720p. One block is kept, of at most kKeptFloats; a call that finds it taken
// (another thread denoising) or too small allocates its own. The floats come uninitialised. Not for other
// files.
#pragma once

#include <cstddef>
#include <memory>

namespace shadelab::denoise_detail {

// 256 MiB: a 4K image's planes; larger blocks go back to the system at once.
constexpr size_t kKeptFloats = size_t(64) << 20;

class DenoiseMemory {
public:
    explicit DenoiseMemory(size_t floats);
    ~DenoiseMemory();
    DenoiseMemory(const DenoiseMemory&) = delete;
    DenoiseMemory& operator=(const DenoiseMemory&) = delete;

    float* data() const { return block_.get(); }

private:
    std::unique_ptr<float[]> block_;
    size_t floats_ = 0;
};

}  // namespace shadelab::denoise_detail
