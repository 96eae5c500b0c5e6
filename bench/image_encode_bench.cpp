// image_encode_bench: the two steps from a rendered float image to PNG bytes at 1920x1080, the size the
// README's renders use: toImage8 (linear float → 8-bit sRGB through its tables, on a gradient that covers the
// whole range and clamps below 0) and encodePng (filters, zlib at its fast level, row bands compressed in
// parallel) on a rendered frame, clean and with noise (as a path-traced image has), which is what zlib finds
// hard. Both are stages of `shadelab render --timings` ("readback + conversion" and "PNG encode"). These were
// the image tests' TimingFullHd cases, which timed without checking anything. And the OpenEXR path that
// `render -o x.exr` takes instead (encodeExr of the linear frame, float and half; "EXR encode" in --timings) and
// its read (parseExr, what `compare a.exr b.exr` pays per file), and the conversion through a display that is
// not Standard (-1 stop, filmic: the view transform per channel before the tables). Prints medians of N runs.
// Usage: image_encode_bench [runs] [width] [height]
#include "bench_timing.h"
#include "image/encode.h"
#include "image/exr.h"
#include "image/png.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <random>
#include <thread>
#include <vector>

namespace {

using namespace shadelab;
using shadelab::bench::Clock;
using shadelab::bench::median;
using shadelab::bench::msSince;

// A rendered-looking frame in linear light: a graded background and three Lambert + Blinn-Phong spheres
// (the frame png_test.cpp round-trips), so that the encoder sees large smooth areas and sharp silhouettes.
ImageF renderedFrame(int w, int h) {
    ImageF f(w, h);
    const float L[3] = {0.577f, 0.577f, -0.577f};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = f.pixel(x, y);
            float bg = 0.05f + 0.1f * float(y) / float(h);
            p[0] = p[1] = bg, p[2] = bg * 1.5f, p[3] = 1;
            for (int s = 0; s < 3; ++s) {
                const float cx = w * (0.25f + 0.25f * s), cy = h * 0.5f, r = h * 0.2f;
                const float nx = (x - cx) / r, ny = (cy - y) / r, d = 1 - nx * nx - ny * ny;
                if (d <= 0) continue;
                const float N[3] = {nx, ny, -std::sqrt(d)}, Hv[3] = {0.45f, 0.45f, -0.77f};
                const float NoL = std::max(0.0f, N[0] * L[0] + N[1] * L[1] + N[2] * L[2]);
                const float spec = std::pow(std::max(0.0f, N[0] * Hv[0] + N[1] * Hv[1] + N[2] * Hv[2]), 64.0f);
                for (int c = 0; c < 3; ++c) p[c] = 0.02f + (c == s ? 0.8f : 0.1f) * NoL + spec;
            }
        }
    return f;
}

// Red along x, green along y, blue a diagonal wave from -0.4 to 1.0.
ImageF gradient(int w, int h) {
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = float(x) / float(w), p[1] = float(y) / float(h);
            p[2] = 0.3f + 0.7f * std::sin(float(x + y) * 0.01f), p[3] = 1;
        }
    return img;
}

// The 8-bit frame with Gaussian noise (sigma 0.05 of full scale) added to every channel.
Image8 noisy(const Image8& frame) {
    ImageF f(frame.width, frame.height);
    std::mt19937 rng(7);
    std::normal_distribution<float> noise(0.0f, 0.05f);
    for (size_t i = 0; i < f.rgba.size(); ++i) f.rgba[i] = frame.data[i / 4 * 3 + i % 4 % 3] / 255.0f + noise(rng);
    return toImage8(f, Encoding::Linear, DisplaySettings{}, nullptr);
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 11;
    const int width = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1920;
    const int height = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1080;
    try {
        const ImageF linear = gradient(width, height);
        const Image8 frame = toImage8(renderedFrame(width, height), Encoding::Srgb, DisplaySettings{},
                                      nullptr);  // also builds the tables
        const Image8 grainy = noisy(frame);
        std::printf("image_encode_bench: %dx%d, %u hardware threads, %d runs\n", width, height,
                    std::thread::hardware_concurrency(), runs);

        const ImageF rendered = renderedFrame(width, height);
        const ExrImage layers = exrFromImage(rendered);
        std::vector<double> convert, filmic, clean, rough, exrFloat, exrHalf, exrRead;
        const DisplaySettings filmicDisplay{-1.0, ViewTransform::Filmic};
        size_t cleanBytes = 0, roughBytes = 0, floatBytes = 0, halfBytes = 0;
        for (int r = 0; r < runs; ++r) {
            auto t0 = Clock::now();
            const Image8 out = toImage8(linear, Encoding::Srgb, DisplaySettings{}, nullptr);
            convert.push_back(msSince(t0));
            if (out.data.size() != size_t(width) * size_t(height) * 3) {
                std::fprintf(stderr, "image_encode_bench: toImage8 returned %zu bytes\n", out.data.size());
                return 1;
            }
            t0 = Clock::now();
            const Image8 tone = toImage8(linear, Encoding::Srgb, filmicDisplay, nullptr);
            filmic.push_back(msSince(t0));
            if (tone.data.size() != out.data.size()) return 1;
            t0 = Clock::now();
            cleanBytes = encodePng(frame).size();
            clean.push_back(msSince(t0));
            t0 = Clock::now();
            roughBytes = encodePng(grainy).size();
            rough.push_back(msSince(t0));
            t0 = Clock::now();
            const std::string f = encodeExr(layers, ExrPrecision::Float);
            exrFloat.push_back(msSince(t0));
            floatBytes = f.size();
            t0 = Clock::now();
            halfBytes = encodeExr(layers, ExrPrecision::Half).size();
            exrHalf.push_back(msSince(t0));
            t0 = Clock::now();
            const ExrImage back = parseExr(f, "bench.exr");
            exrRead.push_back(msSince(t0));
            if (back.layers.empty() || back.layers[0].samples != layers.layers[0].samples) {
                std::fprintf(stderr, "image_encode_bench: the EXR did not round-trip\n");
                return 1;
            }
        }
        std::printf("toImage8 (RGBA32F -> RGB8, sRGB): median %.2f ms\n", median(convert));
        std::printf("toImage8 (RGBA32F -> RGB8, -1 stop, filmic, sRGB): median %.2f ms\n", median(filmic));
        std::printf("encodePng, rendered frame: median %.2f ms, %zu bytes\n", median(clean), cleanBytes);
        std::printf("encodePng, rendered frame + noise: median %.2f ms, %zu bytes\n", median(rough), roughBytes);
        std::printf("encodeExr, rendered frame, float: median %.2f ms, %zu bytes\n", median(exrFloat), floatBytes);
        std::printf("encodeExr, rendered frame, half: median %.2f ms, %zu bytes\n", median(exrHalf), halfBytes);
        std::printf("parseExr, rendered frame, float: median %.2f ms\n", median(exrRead));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "image_encode_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
