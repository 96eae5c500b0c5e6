// The GLSL ES 3.00 dialect (gl/shader_dialect.h) proven natively, on Mesa's OpenGL ES 3 context through EGL:
// every colour program the raster renderer can build, and its other programs, compile and link there, and
// scenes rendered through the raster renderer in that context equal the desktop context's renders under the
// strict design.md §4 gates (shadow maps, environment cubes, a mirror plane clipping a mesh by discard).
// Negative controls: desktop-only GLSL (gl_ClipDistance, an implicit int-to-float conversion) fails to
// compile there while the desktop context takes it, and the comparison fails with one light 5 % brighter.
#include "gl/gl_api.h"
#include "gl/headless_context.h"
#include "gl/program.h"
#include "gl/shader_dialect.h"
#include "image/png.h"
#include "raster/shader_variant.h"
#include "raster/shadow_block.h"
#include "render_compare.h"
#include "scene/scene_load.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace shadelab;

namespace {

namespace fs = std::filesystem;
constexpr int kWidth = 192, kHeight = 128;

// Each test makes its own context current and ends it: one EGL display at a time, no context shared.
std::unique_ptr<gl::HeadlessContext> esContext() { return gl::createEglEsContext(); }
std::unique_ptr<gl::HeadlessContext> desktopContext() { return gl::createHeadlessContext(); }

// Every value of every #define the colour programs take, each at least once, and the combinations the
// shaders branch on together (model with terms; shadow kind with light type and plane masks; pbr's
// image-based lighting with energy compensation).
std::vector<raster::ShaderVariant> everyVariant() {
    using raster::ShaderVariant;
    std::vector<ShaderVariant> out;
    const auto lit = [](int model, int terms, int lights, bool more) {
        ShaderVariant v;
        v.model = model;
        v.terms = terms;
        v.lights = lights;
        v.moreLights = more;
        for (int i = 0; i < lights; ++i) {
            v.point[size_t(i)] = i % 2 == 1;
            v.attenuated[size_t(i)] = i == 1;
        }
        return v;
    };
    for (int model = 0; model < 3; ++model)
        for (int terms = 0; terms < 8; ++terms) out.push_back(lit(model, terms, 2, false));
    for (int lights = 0; lights <= raster::kMaxShadowedLights; ++lights)
        for (bool more : {false, true}) out.push_back(lit(0, 7, lights, more));
    const int kinds[3] = {raster::kShadowOrtho, raster::kShadowPerspective, raster::kShadowCube};
    ShaderVariant shadowedPbr;
    for (int model = 0; model < 3; ++model)
        for (int rotation = 0; rotation < 3; ++rotation)
            for (bool pcf : {false, true}) {
                ShaderVariant v = lit(model, 7, 3, true);
                v.shadows = true;
                v.pcf = pcf;
                v.planes = 2;
                for (int i = 0; i < 3; ++i) {
                    const size_t k = size_t(i);
                    v.shadowKind[k] = kinds[(i + rotation) % 3];
                    v.point[k] = v.shadowKind[k] != raster::kShadowOrtho;
                    v.attenuated[k] = v.point[k] && i != rotation;
                    v.planeMask[k] = (i + rotation) % 4;
                    v.firstLayer[k] = i;
                }
                out.push_back(v);
                if (model == 2 && rotation == 0 && pcf) shadowedPbr = v;
            }
    ShaderVariant unshadowedLight = out.back();
    unshadowedLight.shadowKind[1] = raster::kShadowNone;
    out.push_back(unshadowedLight);
    for (int ibl = 0; ibl < 3; ++ibl)
        for (bool compensation : {false, true})
            for (bool shadows : {false, true}) {
                ShaderVariant v = shadows ? shadowedPbr : lit(2, 7, 2, false);
                v.ibl = ibl;
                v.energyCompensation = compensation;
                out.push_back(v);
            }
    return out;
}

struct Built {
    int programs = 0;
    std::vector<std::string> failures;  // "vertex + fragment [defines]: message"
};

void build(const gl::ShaderLibrary& lib, const std::string& vert, const std::string& frag, const std::string& defines,
           Built& built) {
    ++built.programs;
    try {
        gl::Program::build(lib, vert, frag, defines);
    } catch (const InputError& e) {
        built.failures.push_back(vert + " + " + frag + ": " + e.what());
    }
}

// Every program RasterRenderer can compile, in `lib`'s dialect: the colour programs of every variant and
// kind, mesh.frag with every SL_MATERIAL_MAPS set, the shadow passes, the backdrop and the partial merge; and
// the other full-screen programs of shaders/ (viewer and probes), which a web page may use too.
Built buildEveryProgram(const gl::ShaderLibrary& lib) {
    Built built;
    const std::vector<raster::ShaderVariant> variants = everyVariant();
    for (const raster::ShaderVariant& v : variants)
        for (const char* stem : {"mesh", "sphere", "plane"})
            for (bool environment : {false, true})
                build(lib, std::string(stem) + ".vert", std::string(stem) + ".frag",
                      raster::colorProgramDefines(v.defines(), 0, environment), built);
    // mesh.frag's maps with every light and shadow kind: under Phong, and under pbr with a map's lighting.
    const raster::ShaderVariant* shadowed = nullptr;
    for (const raster::ShaderVariant& v : variants)
        if (v.shadows && v.model == 0 && !shadowed) shadowed = &v;
    for (const raster::ShaderVariant* v : {shadowed, &variants.back()})
        for (int maps = 1; maps < 64; ++maps)
            for (bool environment : {false, true})
                build(lib, "mesh.vert", "mesh.frag", raster::colorProgramDefines(v->defines(), maps, environment),
                      built);
    build(lib, "shadow_mesh.vert", "shadow_depth.frag", "", built);
    build(lib, "shadow_sphere.vert", "shadow_sphere.frag", "", built);
    build(lib, "fullscreen.vert", "environment_backdrop.frag", raster::ShaderVariant().defines(), built);
    for (const char* frag : {"partial_merge.frag", "accumulate.frag", "texel_probe.frag", "view_transform_probe.frag",
                             "lighting_probe.frag"})
        build(lib, "fullscreen.vert", frag, "", built);
    // The viewer's image view, with the defines src/app/image_view.cpp compiles it with.
    for (int mode = 0; mode < 4; ++mode)
        for (int flags = 0; flags < 8; ++flags)
            build(lib, "fullscreen.vert", "view_image.frag",
                  "#define VIEW_MODE " + std::to_string(mode) + "\n#define SRGB " + std::to_string(flags & 1) +
                      "\n#define OUTLINE " + std::to_string((flags >> 1) & 1) + "\n#define VIEW_TRANSFORM " +
                      std::to_string(flags >> 2) + "\n",
                  built);
    build(lib, "view_arrows.vert", "view_arrows.frag", "", built);
    return built;
}

std::string listed(const std::vector<std::string>& lines) {
    std::string s;
    for (size_t i = 0; i < lines.size() && i < 20; ++i) s += "\n  " + lines[i];
    return s;
}

TEST(EsDialect, TheEsContextIsOpenGlEs3) {
    const auto ctx = esContext();
    EXPECT_EQ(ctx->info().version.rfind("OpenGL ES 3", 0), 0u) << ctx->info().version;
    EXPECT_EQ(gl::currentContextDialect(), gl::ShaderDialect::Essl300);
}

TEST(EsDialect, EveryRasterProgramCompilesAndLinks) {
    const auto ctx = esContext();
    const Built built = buildEveryProgram(gl::ShaderLibrary("", gl::ShaderDialect::Essl300));
    std::printf("%d programs built in GLSL ES 3.00 (%s), %zu failed\n", built.programs, ctx->info().version.c_str(),
                built.failures.size());
    EXPECT_GT(built.programs, 500);
    EXPECT_TRUE(built.failures.empty()) << built.failures.size() << " failed:" << listed(built.failures);
}

// A folder with the embedded shaders and one of desktop-only GLSL: an int where a float is meant (desktop
// GLSL converts it, ES 3.00 §4.1.10 does not).
fs::path shadersWithDesktopOnlyFile() {
    const fs::path dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "desktop_only_shaders";
    fs::create_directories(dir);
    for (const gl::EmbeddedShader& s : gl::embeddedShaders()) std::ofstream(dir / s.name, std::ios::binary) << s.text;
    std::ofstream(dir / "implicit_conversion.frag")
        << "layout(location = 0) out vec4 o_color;\nvoid main() {\n    float x = 1;\n    o_color = vec4(x);\n}\n";
    return dir;
}

// Negative controls: the ES compiler is strict. What the desktop context compiles, it refuses.
TEST(EsDialect, DesktopOnlyGlslFailsUnderEsAndCompilesOnDesktop) {
    const fs::path dir = shadersWithDesktopOnlyFile();
    const std::string clipDistance = raster::colorProgramDefines(everyVariant().front().defines(), 0, false) +
                                     "#undef SL_CLIP_DISTANCE\n#define SL_CLIP_DISTANCE 1\n";
    for (bool es : {true, false}) {
        const auto ctx = es ? esContext() : desktopContext();
        const gl::ShaderLibrary lib(dir.string(), es ? gl::ShaderDialect::Essl300 : gl::ShaderDialect::Glsl330);
        Built built;
        build(lib, "mesh.vert", "mesh.frag", clipDistance, built);
        build(lib, "fullscreen.vert", "implicit_conversion.frag", "", built);
        if (es) {
            ASSERT_EQ(built.failures.size(), 2u) << listed(built.failures);
            EXPECT_NE(built.failures[0].find("mesh.vert"), std::string::npos) << built.failures[0];
            EXPECT_NE(built.failures[1].find("implicit_conversion.frag: line 3"), std::string::npos)
                << built.failures[1];
            std::printf("ES refuses, as it must:%s\n", listed(built.failures).c_str());
        } else {
            EXPECT_TRUE(built.failures.empty()) << listed(built.failures);
        }
    }
}

// The scenes rendered in both contexts: the lecture demo (shadow maps, an environment cube, a checker floor)
// and the torus sunk into a mirror floor (a mesh clipped at the mirror plane, by gl_ClipDistance on desktop
// and by a discard in ES).
std::vector<std::pair<std::string, Scene>> comparedScenes() {
    std::vector<std::pair<std::string, Scene>> scenes;
    scenes.emplace_back("default", loadScene(std::string(SHADELAB_SOURCE_DIR) + "/assets/scenes/default.json"));
    const fs::path mirror = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "torus_mirror.json";
    fs::create_directories(mirror.parent_path());
    std::ofstream(mirror) << R"({"shadelab": 1,
      "camera": {"position": [0, 2.6, 6.5], "target": [0, 0.4, 0], "up": [0, 1, 0], "fovY": 38},
      "model": "blinn-phong", "ambient": [0.1, 0.1, 0.12], "background": [0.03, 0.03, 0.04],
      "terms": {"shadows": false, "reflections": true},
      "lights": [{"type": "point", "position": [-3, 5, 4], "color": [0.9, 0.85, 0.8]}],
      "objects": [
        {"type": "plane", "normal": [0, 1, 0], "offset": 0,
         "material": {"ma": 0.2, "md": 0.3, "ms": 0.0, "s": 1, "kr": 0.6}},
        {"type": "mesh", "source": ")" +
                                 std::string(SHADELAB_SOURCE_DIR) + R"(/assets/models/torus.gltf",
         "transform": {"translate": [-0.5, 0.15, 0], "scale": 1.0}, "material": {"s": 64}},
        {"type": "sphere", "center": [1.6, 0.5, 0.8], "radius": 0.5,
         "material": {"ma": [0.2, 0.35, 0.6], "md": [0.2, 0.35, 0.6], "ms": 0.5, "s": 64}}]})";
    scenes.emplace_back("torus_mirror", loadScene(mirror.string()));
    return scenes;
}

test::Rendered renderIn(bool es, const Scene& scene) {
    const auto ctx = es ? esContext() : desktopContext();
    raster::RasterRenderer r;  // destroyed before its context
    r.uploadMeshes(scene);
    raster::OffscreenOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.coverage = true;
    raster::OffscreenResult out = raster::renderOffscreen(r, scene, o);
    return {std::move(out.pixels), std::move(out.coverage)};
}

TEST(EsDialect, RasterImagesEqualTheDesktopContexts) {
    for (const auto& [name, scene] : comparedScenes()) {
        const test::Rendered desktop = renderIn(false, scene);
        const test::Rendered es = renderIn(true, scene);
        const CompareResult c = test::gateWithEvidence(es, desktop, CompareGates{}, "es_vs_desktop_" + name);
        EXPECT_TRUE(c.pass) << name;
        EXPECT_EQ(es.coverage, desktop.coverage) << name;
        // Negative control: the first light 5 % brighter in the ES render fails the same gates.
        Scene brighter = scene;
        ASSERT_FALSE(brighter.lights.empty());
        brighter.lights[0].color *= 1.05f;
        const CompareResult control =
            test::gateWithEvidence(renderIn(true, brighter), desktop, CompareGates{}, "es_vs_desktop_control_" + name);
        EXPECT_FALSE(control.pass) << name << ": a brighter light passed the gates";
        // The images to look at, pass or fail.
        writePng(test::outputPath("es_" + name + ".png"), es.pixels);
    }
}

}  // namespace
