// renderOffscreen: bands × supersampling × the one float→8-bit conversion.
#include "raster/offscreen.h"

#include "gl/gl_api.h"
#include "scene/sample_grid.h"
#include "util/input_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>

namespace shadelab::raster {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Averages k×k blocks of `hi` (k·W wide, k·rows tall) into `lo` (W wide, rows tall), in linear float.
void boxDownsample(const ImageF& hi, int k, ImageF& lo) {
    const float inv = 1.0f / float(k * k);
    for (int y = 0; y < lo.height; ++y)
        for (int x = 0; x < lo.width; ++x) {
            float sum[4] = {0, 0, 0, 0};
            for (int b = 0; b < k; ++b)
                for (int a = 0; a < k; ++a) {
                    const float* p = hi.pixel(x * k + a, y * k + b);
                    for (int c = 0; c < 4; ++c) sum[c] += p[c];
                }
            float* q = lo.pixel(x, y);
            for (int c = 0; c < 4; ++c) q[c] = sum[c] * inv;
        }
}

}  // namespace

glm::vec2 gridSampleOffset(int k, int index) {
    const int a = index % k, b = index / k;
    return {(float(a) + 0.5f) / float(k) - 0.5f, (float(b) + 0.5f) / float(k) - 0.5f};
}

OffscreenResult renderOffscreen(RasterRenderer& renderer, const Scene& scene, const OffscreenOptions& o) {
    const int k = gridSamplesPerSide(o.spp);
    const int hiW = o.width * k, hiH = o.height * k;
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (hiW > maxSize)
        throw SettingError("size", std::to_string(o.width) + " pixels wide at " + std::to_string(o.spp) +
                                       " samples per pixel needs a " + std::to_string(hiW) +
                                       "-pixel-wide target; this GL allows " + std::to_string(maxSize));

    OffscreenResult r;
    r.pixels.width = o.width;
    r.pixels.height = o.height;
    r.pixels.channels = 3;
    r.pixels.data.resize(size_t(o.width) * size_t(o.height) * 3);
    if (o.coverage) r.coverage.resize(size_t(o.width) * size_t(o.height));
    if (o.keepLinear) r.linear = ImageF(o.width, o.height);

    // Bands hold whole output rows (multiples of k sub-rows) and stay near the target budget.
    const int outRowsPerBand =
        std::max(1, (o.height + bandCount(hiW, hiH, o.maxTargetBytes) - 1) / bandCount(hiW, hiH, o.maxTargetBytes));
    const int coverageSample = k / 2;  // the tracer's choice: the pixel centre when k is odd
    // Only the linear image hands the alpha on; the 8-bit conversion reads RGB. The caller's choice comes
    // back at the end (the viewer's own frames keep theirs).
    struct AlphaChoice {
        RasterRenderer& renderer;
        const bool before = renderer.targetAlpha();
        ~AlphaChoice() { renderer.setTargetAlpha(before); }
    } restore{renderer};
    renderer.setTargetAlpha(o.keepLinear);
    ImageF hiStrip, loStrip;
    std::vector<uint32_t> bandCoverage;
    for (int outTop = 0; outTop < o.height; outTop += outRowsPerBand) {
        const int outRows = std::min(outRowsPerBand, o.height - outTop);
        Clock::time_point t0 = Clock::now();
        renderer.draw(scene, hiW, hiH, o.coverage, Band{outTop * k, outRows * k});
        glFinish();
        r.drawMs += msSince(t0);
        t0 = Clock::now();
        ++r.bands;
        const RenderTarget& target = renderer.target();
        if (k == 1 && !o.keepLinear) {
            target.readColor8(r.pixels, outTop, o.encoding, o.display, &r.nonFinite);
        } else {
            // Strips of output rows (16 when supersampled): read k·16 sub-rows, average, convert.
            const int strip = k == 1 ? 64 : 16;
            for (int row = 0; row < outRows; row += strip) {
                const int rows = std::min(strip, outRows - row);
                if (loStrip.height != rows) loStrip = ImageF(o.width, rows);
                if (k == 1) {
                    target.readColorRows(row, rows, loStrip);
                } else {
                    if (hiStrip.height != rows * k) hiStrip = ImageF(hiW, rows * k);
                    target.readColorRows(row * k, rows * k, hiStrip);
                    boxDownsample(hiStrip, k, loStrip);
                }
                Image8 converted = toImage8(loStrip, o.encoding, o.display, &r.nonFinite);
                std::memcpy(&r.pixels.data[size_t(outTop + row) * size_t(o.width) * 3], converted.data.data(),
                            converted.data.size());
                if (o.keepLinear) std::copy(loStrip.rgba.begin(), loStrip.rgba.end(), r.linear.pixel(0, outTop + row));
            }
        }
        if (o.coverage) {
            target.readCoverage(bandCoverage);
            for (int y = 0; y < outRows; ++y)
                for (int x = 0; x < o.width; ++x)
                    r.coverage[size_t(outTop + y) * size_t(o.width) + size_t(x)] =
                        bandCoverage[size_t(y * k + coverageSample) * size_t(hiW) + size_t(x * k + coverageSample)];
        }
        r.readMs += msSince(t0);
    }
    return r;
}

}  // namespace shadelab::raster
