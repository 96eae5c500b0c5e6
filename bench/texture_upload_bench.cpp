// texture_upload_bench: 16 MiB of 8-bit RGBA textures (four 1024² images) made ready to draw,
// in the two stages shadelab takes: (a) scene/texture.h's makeTexture, the 8-bit level 0 kept and the mip
// chain built on the CPU (averaged in linear light, re-encoded to 8-bit sRGB), as the glTF importer does once
// per image; (b) raster/mesh_textures.h's upload of every level as the 8-bit codes (GL_SRGB8_ALPHA8 or
// GL_RGBA8; GL decodes them) into a headless GL context, up to glFinish. Budget for both together: 60 ms.
// Prints medians of N runs. Usage: texture_upload_bench [runs] [images] [side]
#include "bench_timing.h"
#include "gl/gl_api.h"
#include "gl/headless_context.h"
#include "raster/mesh_textures.h"
#include "scene/texture.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace shadelab;
    using namespace shadelab::bench;
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const int images = argc > 2 ? std::max(1, std::atoi(argv[2])) : 4;
    const int side = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1024;
    try {
        // A smooth gradient with a fine checker: every texel differs from its neighbours, as a photograph's do.
        std::vector<std::vector<uint8_t>> pixels(size_t(images), std::vector<uint8_t>(size_t(side) * size_t(side) * 4));
        for (int i = 0; i < images; ++i)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x) {
                    uint8_t* p = &pixels[size_t(i)][(size_t(y) * size_t(side) + size_t(x)) * 4];
                    p[0] = uint8_t((x * 255) / side);
                    p[1] = uint8_t((y * 255) / side);
                    p[2] = uint8_t(((x / 4 + y / 4) % 2) * 200 + i * 10);
                    p[3] = 255;
                }
        const double mib = double(images) * side * side * 4 / (1024.0 * 1024.0);
        std::unique_ptr<gl::HeadlessContext> context = gl::createHeadlessContext();
        std::printf("texture_upload_bench: %d images of %dx%d RGBA8 (%.1f MiB), %s, %d runs\n", images, side, side, mib,
                    context->info().renderer.c_str(), runs);
        std::vector<double> make, upload, total;
        for (int r = 0; r < runs; ++r) {
            auto t0 = Clock::now();
            std::vector<std::shared_ptr<const Texture>> textures;
            for (int i = 0; i < images; ++i)
                textures.push_back(
                    makeTexture("bench" + std::to_string(i), pixels[size_t(i)].data(), side, side, true));
            const double m = msSince(t0);
            auto t1 = Clock::now();
            {
                raster::MeshTextures uploaded;
                for (const auto& t : textures) uploaded.texture(t);
                glFinish();
                upload.push_back(msSince(t1));
            }
            make.push_back(m);
            total.push_back(m + upload.back());
        }
        std::printf("makeTexture (8-bit level 0 + mips, CPU): median %.1f ms\n", median(make));
        std::printf("upload (8-bit sRGB or UNORM, every level, glFinish): median %.1f ms\n", median(upload));
        std::printf("both: median %.1f ms (budget 60 ms)\n", median(total));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "texture_upload_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
