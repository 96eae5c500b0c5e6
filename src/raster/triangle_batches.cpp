// TriangleBatches: ranges cut at batch boundaries, a flush after each full batch.
#include "raster/triangle_batches.h"

#include "gl/gl_api.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace shadelab::raster {

size_t TriangleBatches::sizeForCurrentContext() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    if (!renderer) return 0;
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader"})
        if (std::strstr(renderer, software)) return kSoftwareBatch;
    return 0;
}

void TriangleBatches::draw(size_t firstIndex, size_t indexCount) {
    const auto drawIndices = [](size_t first, size_t count) {
        glDrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(first * sizeof(uint32_t)));
    };
    if (batch_ == 0) {
        drawIndices(firstIndex, indexCount);
        return;
    }
    for (size_t triangles = indexCount / 3; triangles > 0;) {
        const size_t n = std::min(triangles, batch_ - pending_);
        drawIndices(firstIndex, n * 3);
        firstIndex += n * 3;
        triangles -= n;
        pending_ += n;
        if (pending_ == batch_) {
            glFlush();
            pending_ = 0;
        }
    }
}

}  // namespace shadelab::raster
