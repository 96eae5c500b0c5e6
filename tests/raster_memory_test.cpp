// What the headless render does to save memory must not change a pixel:
// - TriangleBatches (raster/triangle_batches.h) cuts the mesh passes' draws into flushed batches. Blended,
//   depth-tested triangles whose order decides every pixel come out the same, float for float, drawn whole or in
//   batches of any size, across ranges that end mid-batch. Control: the same triangles with two ranges swapped
//   differ, so the comparison sees order.
// - A colour target without alpha (RenderTarget::resize) holds the same RGB as one with it, reads back alpha 1,
//   and renderOffscreen's 8-bit image is the same through either. Control: the target with alpha keeps a
//   cleared alpha that the one without does not.
// - A vertex array no mesh part has (texture coordinates, tangents) is left out of the upload and its attribute
//   reads a constant 0: the torus without them draws exactly as with arrays of zeros. Control: one normal
//   changed in those arrays' copy changes the image.
#include "gl/gl_api.h"
#include "gl_fixture.h"
#include "image/png.h"
#include "raster/offscreen.h"
#include "raster/raster_renderer.h"
#include "raster/render_target.h"
#include "raster/triangle_batches.h"
#include "scene/mesh_geometry.h"
#include "scene/scene_load.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace shadelab;

namespace {

constexpr int kSize = 96;

GLuint compileStage(GLenum stage, const char* text) {
    const GLuint s = glCreateShader(stage);
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = GL_FALSE;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    EXPECT_EQ(ok, GL_TRUE) << "test shader did not compile";
    return s;
}

// Position (x, y, z) and colour (r, g, b, a) per vertex, drawn as they are with alpha blending.
GLuint colourProgram() {
    const GLuint v = compileStage(GL_VERTEX_SHADER, R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_colour;
out vec4 v_colour;
void main() { v_colour = a_colour; gl_Position = vec4(a_position, 1.0); })");
    const GLuint f = compileStage(GL_FRAGMENT_SHADER, R"(#version 330 core
in vec4 v_colour;
layout(location = 0) out vec4 o_colour;
void main() { o_colour = v_colour; })");
    const GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    return p;
}

struct TriangleSoup {
    GLuint vao = 0, vbo = 0, ibo = 0, program = 0;
    size_t indices = 0;
    ~TriangleSoup() {
        glDeleteProgram(program);
        glDeleteBuffers(1, &vbo);
        glDeleteBuffers(1, &ibo);
        glDeleteVertexArrays(1, &vao);
    }
};

// `count` overlapping translucent triangles at random depths: with blending and the depth test, the order
// in which they reach the target decides almost every pixel.
void makeSoup(TriangleSoup& soup, size_t count) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f), unit(0.0f, 1.0f);
    std::vector<float> vertices;
    std::vector<uint32_t> indices;
    for (size_t t = 0; t < count; ++t) {
        const float cx = pos(rng), cy = pos(rng), z = pos(rng) * 0.9f;
        const float r = unit(rng), g = unit(rng), b = unit(rng), a = 0.2f + 0.6f * unit(rng);
        for (int k = 0; k < 3; ++k) {
            vertices.insert(vertices.end(), {cx + 0.6f * pos(rng), cy + 0.6f * pos(rng), z, r, g, b, a});
            indices.push_back(uint32_t(indices.size()));
        }
    }
    soup.indices = indices.size();
    soup.program = colourProgram();
    glGenVertexArrays(1, &soup.vao);
    glBindVertexArray(soup.vao);
    glGenBuffers(1, &soup.vbo);
    glBindBuffer(GL_ARRAY_BUFFER, soup.vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &soup.ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, soup.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 7 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 7 * sizeof(float), reinterpret_cast<const void*>(12));
    glBindVertexArray(0);
}

// Draws the soup's index ranges (first, count) in the order given, through batches of `batch` triangles.
ImageF drawSoup(const TriangleSoup& soup, raster::RenderTarget& target,
                const std::vector<std::pair<size_t, size_t>>& ranges, size_t batch) {
    target.resize(kSize, kSize, false);
    target.bind();
    const float clear[4] = {0.1f, 0.1f, 0.1f, 1.0f}, far = 1.0f;
    glClearBufferfv(GL_COLOR, 0, clear);
    glClearBufferfv(GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(soup.program);
    glBindVertexArray(soup.vao);
    raster::TriangleBatches batches(batch);
    for (const auto& [first, count] : ranges) batches.draw(first, count);
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_BLEND);
    ImageF out;
    target.readColor(out);
    return out;
}

size_t differingFloats(const ImageF& a, const ImageF& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) n += std::memcmp(&a.rgba[i], &b.rgba[i], sizeof(float)) != 0;
    return n;
}

void savePair(const ImageF& a, const ImageF& b, const std::string& name) {
    writePng(test::outputPath(name + "_whole.png"), toImage8(a, Encoding::Srgb, DisplaySettings{}, nullptr));
    writePng(test::outputPath(name + "_batched.png"), toImage8(b, Encoding::Srgb, DisplaySettings{}, nullptr));
}

}  // namespace

class RasterMemoryTest : public test::GlTest {};

TEST_F(RasterMemoryTest, BatchedDrawsEqualWholeDraws) {
    TriangleSoup soup;
    makeSoup(soup, 1500);
    // Uneven ranges, as a model's parts are: batches fill across them and cut inside them.
    const size_t n = soup.indices;
    const std::vector<std::pair<size_t, size_t>> ranges = {
        {0, 3 * 10}, {30, 3 * 700}, {2130, 3 * 1}, {2133, 3 * 299}, {3030, n - 3030}};
    raster::RenderTarget target;
    const ImageF whole = drawSoup(soup, target, ranges, 0);
    for (size_t batch : {size_t(1), size_t(7), raster::TriangleBatches::kSoftwareBatch, size_t(100000)}) {
        const ImageF batched = drawSoup(soup, target, ranges, batch);
        const size_t diff = differingFloats(whole, batched);
        EXPECT_EQ(diff, 0u) << "batches of " << batch << ": " << diff << " floats differ; images in "
                            << test::outputPath("");
        if (diff) savePair(whole, batched, "batches" + std::to_string(batch));
    }
    // Control: two ranges drawn the other way round change the blend and the depth test's outcome.
    std::vector<std::pair<size_t, size_t>> swapped = ranges;
    std::swap(swapped[1], swapped[3]);
    EXPECT_GT(differingFloats(whole, drawSoup(soup, target, swapped, raster::TriangleBatches::kSoftwareBatch)),
              size_t(kSize * kSize / 20));
    test::expectNoGlErrors("drawing the soup");
}

TEST_F(RasterMemoryTest, LlvmpipeGetsBatchesAndTheSizeIsNamed) {
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const size_t expected =
        renderer.find("llvmpipe") != std::string::npos ? raster::TriangleBatches::kSoftwareBatch : size_t(0);
    EXPECT_EQ(raster::TriangleBatches::sizeForCurrentContext(), expected) << renderer;
}

TEST_F(RasterMemoryTest, ATargetWithoutAlphaHoldsTheSameColour) {
    raster::RenderTarget withAlpha, withoutAlpha;
    withAlpha.resize(kSize, kSize, false, true);
    withoutAlpha.resize(kSize, kSize, false, false);
    const float clear[4] = {0.2f, 0.4f, 0.6f, 0.25f};
    ImageF a, b;
    for (auto [target, image] : {std::pair{&withAlpha, &a}, std::pair{&withoutAlpha, &b}}) {
        target->bind();
        glClearBufferfv(GL_COLOR, 0, clear);
        target->readColor(*image);
    }
    for (int c = 0; c < 3; ++c) EXPECT_EQ(b.pixel(5, 7)[c], clear[c]);
    EXPECT_EQ(b.pixel(5, 7)[3], 1.0f);   // read back as RGBA: no alpha is 1
    EXPECT_EQ(a.pixel(5, 7)[3], 0.25f);  // control: the target with alpha keeps it

    // The headless render's 8-bit image is the same through either target; its linear image keeps alpha.
    Scene scene = loadScene(test::sourcePath("assets/scenes/torus.json"));
    raster::RasterRenderer r;
    r.uploadMeshes(scene);
    raster::OffscreenOptions o;
    o.width = 160;
    o.height = 90;
    const raster::OffscreenResult rgb = raster::renderOffscreen(r, scene, o);
    EXPECT_TRUE(r.targetAlpha()) << "renderOffscreen gives the renderer's own choice back";
    o.keepLinear = true;
    const raster::OffscreenResult rgba = raster::renderOffscreen(r, scene, o);
    EXPECT_EQ(rgb.pixels.data, rgba.pixels.data);
    if (rgb.pixels.data != rgba.pixels.data) {
        writePng(test::outputPath("torus_rgb_target.png"), rgb.pixels);
        writePng(test::outputPath("torus_rgba_target.png"), rgba.pixels);
    }
    EXPECT_EQ(rgba.linear.width, 160);
}

TEST_F(RasterMemoryTest, ArraysNoPartHasReadAsZeros) {
    Scene scene = loadScene(test::sourcePath("assets/scenes/torus.json"));
    ASSERT_FALSE(scene.meshes.empty());
    raster::RasterRenderer r;
    raster::OffscreenOptions o;
    o.width = 200;
    o.height = 120;
    const auto render = [&](const Scene& s) {
        r.uploadMeshes(s);
        return raster::renderOffscreen(r, s, o).pixels;
    };
    for (const MeshPart& part : scene.meshes[0].parts) ASSERT_TRUE(part.geometry->texcoords0.empty());
    const Image8 without = render(scene);
    // The same parts with every optional array present, all zeros.
    const auto withZeroArrays = [](Scene s, bool nudgeANormal) {
        for (Mesh& m : s.meshes)
            for (MeshPart& part : m.parts) {
                MeshGeometry g = *part.geometry;
                g.texcoords0.assign(g.positions.size(), glm::vec2(0.0f));
                g.texcoords1.assign(g.positions.size(), glm::vec2(0.0f));
                g.tangents.assign(g.positions.size(), glm::vec4(0.0f));
                if (nudgeANormal)
                    for (size_t i = 0; i < g.normals.size(); i += 7) g.normals[i] = -g.normals[i];
                part.geometry = shareGeometry(std::move(g));
            }
        return s;
    };
    const Image8 with = render(withZeroArrays(scene, false));
    EXPECT_EQ(without.data, with.data) << "images in " << test::outputPath("");
    if (without.data != with.data) {
        writePng(test::outputPath("torus_arrays_left_out.png"), without);
        writePng(test::outputPath("torus_zero_arrays.png"), with);
    }
    EXPECT_NE(with.data, render(withZeroArrays(scene, true)).data) << "control: changed normals must show";
}
