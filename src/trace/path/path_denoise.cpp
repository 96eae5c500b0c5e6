#include "trace/path/path_denoise.h"

#include "trace/luminance.h"

#include <algorithm>

namespace shadelab::trace {

std::vector<float> luminanceVariance(const PathRender& render) {
    const int w = render.width(), h = render.height();
    std::vector<float> v(size_t(w) * size_t(h), 0.0f);
    float largest = 0.0f;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float se = luminance(render.standardError(x, y));
            v[size_t(y) * size_t(w) + size_t(x)] = se * se;
            largest = std::max(largest, se * se);
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (render.pixelSamples(x, y) < 2) v[size_t(y) * size_t(w) + size_t(x)] = largest;
    return v;
}

ImageF denoisedImage(const PathRender& render, const SurfacePasses& passes, const DenoiseSettings& settings) {
    DenoiseSettings s = settings;
    if (s.threads == 0) s.threads = render.settings().threads;
    return denoise(render.image(), luminanceVariance(render), passes, s);
}

}  // namespace shadelab::trace
