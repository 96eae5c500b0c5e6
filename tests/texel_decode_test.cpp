// 8-bit texels: the rasterizer's reading of an uploaded texture (MeshTextures' GL_SRGB8_ALPHA8 /
// GL_RGBA8 levels, texelFetch as mesh.frag uses it) against the floats the tracer decodes through
// shading/texel_decode.h's tables, for all 256 codes of every channel and every mip level: within
// kGlTexelDecodeError, and the measured difference printed (llvmpipe is not bit-exact: its sRGB decoding is a
// polynomial). Also: the mip chain's fast sRGB encoder equals image/encode.h's encodeChannel. Negative
// controls: an sRGB texture that the tracer would read as linear, and a table entry 1/255 off, must fail.
#include "shading/texel_decode.h"
#include "gl/program.h"
#include "gl_fixture.h"
#include "image/encode.h"
#include "raster/mesh_textures.h"
#include "raster/render_target.h"
#include "scene/texture.h"
#include "test_output.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

using namespace shadelab;

namespace {

// 256 × 3 texels: red runs through every code along x, the other channels mix x and y, so every code appears
// in every channel; the odd height exercises the folded last row of the mip chain.
std::shared_ptr<const Texture> allCodes(bool srgb) {
    const int w = 256, h = 3;
    std::vector<uint8_t> rgba(size_t(w) * size_t(h) * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            uint8_t* p = &rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
            p[0] = uint8_t(x);
            p[1] = uint8_t((x * 7 + y * 31) & 255);
            p[2] = uint8_t(255 - x);
            p[3] = uint8_t((x * 13 + y) & 255);
        }
    return makeTexture(srgb ? "codes_srgb" : "codes_linear", rgba.data(), w, h, srgb);
}

// Level `level` of `tex` as the rasterizer reads it, row 0 first (as the texture stores it).
ImageF fetchLevel(const Texture& tex, raster::MeshTextures& uploaded, const std::shared_ptr<const Texture>& ptr,
                  int level) {
    const TextureLevel& l = tex.levels[size_t(level)];
    static gl::Program program = gl::Program::build(gl::ShaderLibrary(), "fullscreen.vert", "texel_probe.frag");
    raster::RenderTarget target;
    target.resize(l.width, l.height, false);
    target.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, uploaded.texture(ptr));
    glUniform1i(program.uniform("t_texel"), 0);
    glUniform1i(program.uniform("u_level"), level);
    gl::VertexArray vao = gl::VertexArray::create();
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    ImageF gl;
    target.readColor(gl);
    // readColor puts GL's bottom row (texel row 0 here) last.
    ImageF out(l.width, l.height);
    for (int y = 0; y < l.height; ++y)
        std::memcpy(out.pixel(0, y), gl.pixel(0, l.height - 1 - y), size_t(l.width) * 4 * sizeof(float));
    return out;
}

struct Mismatch {
    int count = 0;       // channel values more than kGlTexelDecodeError apart
    int inexact = 0;     // channel values not bit-identical
    int total = 0;       // channel values compared
    float worst = 0.0f;  // largest difference
};

// Every texel of every level, GL against `decode` (the tracer's reading).
template <class Decode>
Mismatch compareAllLevels(const std::shared_ptr<const Texture>& tex, Decode decode, const std::string& csv) {
    raster::MeshTextures uploaded;
    Mismatch m;
    std::ofstream report(test::outputPath(csv));
    report << "level,x,y,channel,gl,table\n";
    for (size_t level = 0; level < tex->levels.size(); ++level) {
        const ImageF gl = fetchLevel(*tex, uploaded, tex, int(level));
        for (int y = 0; y < gl.height; ++y)
            for (int x = 0; x < gl.width; ++x) {
                const glm::vec4 want = decode(level, x, y);
                for (int k = 0; k < 4; ++k) {
                    const float got = gl.pixel(x, y)[k];
                    ++m.total;
                    if (std::memcmp(&got, &want[k], sizeof(float)) == 0) continue;
                    ++m.inexact;
                    m.worst = std::max(m.worst, std::abs(got - want[k]));
                    if (std::abs(got - want[k]) <= shading::kGlTexelDecodeError) continue;
                    if (m.count++ < 64)
                        report << level << ',' << x << ',' << y << ',' << k << ',' << got << ',' << want[k] << '\n';
                }
            }
    }
    return m;
}

class TexelDecode : public test::GlTest {};

TEST_F(TexelDecode, SrgbTexelFetchEqualsTheTable) {
    const auto tex = allCodes(true);
    ASSERT_EQ(tex->levels.size(), 9u);  // 256×3, 128×1, ..., 1×1
    const Mismatch m = compareAllLevels(
        tex, [&](size_t level, int x, int y) { return tex->texel(level, x, y); }, "texel_decode_srgb.csv");
    std::printf("sRGB: %d of %d channel values not bit-identical, worst %.3g (bound %.3g)\n", m.inexact, m.total,
                double(m.worst), double(shading::kGlTexelDecodeError));
    EXPECT_EQ(m.count, 0) << "worst difference " << m.worst << " (texel_decode_srgb.csv)";
}

TEST_F(TexelDecode, LinearTexelFetchEqualsTheTable) {
    const auto tex = allCodes(false);
    const Mismatch m = compareAllLevels(
        tex, [&](size_t level, int x, int y) { return tex->texel(level, x, y); }, "texel_decode_linear.csv");
    std::printf("UNORM8: %d of %d channel values not bit-identical, worst %.3g (bound %.3g)\n", m.inexact, m.total,
                double(m.worst), double(shading::kGlTexelDecodeError));
    EXPECT_EQ(m.count, 0) << "worst difference " << m.worst << " (texel_decode_linear.csv)";
}

TEST_F(TexelDecode, NegativeControlsAreCaught) {
    // An sRGB texture decoded as linear (a tracer that skipped the decode) differs almost everywhere.
    const auto tex = allCodes(true);
    const Mismatch skipped = compareAllLevels(
        tex,
        [&](size_t level, int x, int y) {
            const TextureLevel& l = tex->levels[level];
            const uint8_t* p = &l.texels[(size_t(y) * size_t(l.width) + size_t(x)) * 4];
            const auto& u = shading::unormDecodeTable();
            return glm::vec4(u[p[0]], u[p[1]], u[p[2]], u[p[3]]);
        },
        "texel_decode_skipped.csv");
    EXPECT_GT(skipped.count, 256 * 3);
    // A table off by one code's step in one entry is caught, though the bound tolerates llvmpipe's rounding.
    const int code = 128;
    const Mismatch step = compareAllLevels(
        tex,
        [&](size_t level, int x, int y) {
            glm::vec4 v = tex->texel(level, x, y);
            if (level == 0 && x == code && y == 0) v.r = shading::srgbDecodeTable()[code + 1];
            return v;
        },
        "texel_decode_step.csv");
    EXPECT_EQ(step.count, 1);
}

// The mip chain's fast sRGB encoder against image/encode.h's (double precision, round half up): a fine sweep
// of [0, 1], and one ulp either side of each code's threshold, where a wrong table would show.
TEST(TexelEncode, FastSrgbEncoderEqualsEncodeChannel) {
    int wrong = 0;
    auto check = [&](float v) {
        const uint8_t want = encodeChannel(v, Encoding::Srgb), got = encodeTexelChannel(v, true);
        if (want != got && wrong++ < 10) ADD_FAILURE() << "v=" << v << ": " << int(got) << " vs " << int(want);
    };
    for (int i = 0; i <= 1 << 20; ++i) check(float(i) / float(1 << 20));
    for (int c = 1; c < 256; ++c) {
        // The least float whose code is c, by bisection on encodeChannel itself.
        float lo = 0.0f, hi = 1.0f;
        while (std::nextafter(lo, 1.0f) < hi) {
            const float mid = lo + (hi - lo) / 2;
            (encodeChannel(mid, Encoding::Srgb) >= c ? hi : lo) = mid == lo ? std::nextafter(lo, 1.0f) : mid;
        }
        for (float v : {std::nextafter(hi, 0.0f), hi, std::nextafter(hi, 1.0f)}) check(v);
    }
    for (float v : {-1.0f, 0.0f, 1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN()})
        EXPECT_EQ(encodeTexelChannel(v, true), std::isnan(v) ? 0 : encodeChannel(v, Encoding::Srgb)) << v;
    EXPECT_EQ(wrong, 0);
    // Linear codes round half up too.
    for (int c = 0; c < 256; ++c) EXPECT_EQ(encodeTexelChannel(c / 255.0f, false), c);
    EXPECT_EQ(encodeTexelChannel(0.5f / 255.0f, false), 1);
}

}  // namespace
