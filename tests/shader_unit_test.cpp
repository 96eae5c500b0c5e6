// Shader-unit test: the GLSL lighting functions, run on the GPU over a sweep of N, L, V and s,
// must equal the same functions compiled as C++ within 1e-4. This proves the two are one implementation.
// The pbr BRDF has a sweep of its own over N, L, V, roughness and metallic, with its own negative control; the
// viewer's exposure and view transform one of theirs against the C++ of every PNG.
#include "gl/program.h"
#include "gl_fixture.h"
#include "image/encode.h"
#include "raster/render_target.h"
#include "scene/anisotropy.h"
#include "scene/material.h"
#include "shading/lighting.h"
#include "shading/sheen_lut.h"
#include "test_output.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <random>
#include <vector>

using namespace shadelab;

namespace {

constexpr int kW = 64, kH = 32;  // 2048 cases

gl::Texture floatTexture(const std::vector<glm::vec4>& data) {
    gl::Texture t = gl::Texture::create();
    glBindTexture(GL_TEXTURE_2D, t.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, kW, kH, 0, GL_RGBA, GL_FLOAT, data.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return t;
}

glm::vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> g;
    glm::vec3 v;
    do v = glm::vec3(g(rng), g(rng), g(rng));
    while (glm::length(v) < 1e-3f);
    return v;  // deliberately not normalised: shadeLight normalises
}

struct Case {
    glm::vec3 N, L, V;
    float s;  // pbr, disney: roughness
    int model;
    float metallic = 0.0f;
    float w = 0.0f;                          // params.w: the spot kernel's range
    glm::vec4 disney0{0.0f}, disney1{0.0f};  // disney: the packed parameters (DisneyParams::lobes0, lobes1)
};

// Random N and L; odd cases a random V, even ones V near the mirror direction, where the highlight is and
// errors would show.
Case randomGeometry(std::mt19937& rng, int i) {
    Case c{};
    c.N = randomDirection(rng);
    c.L = randomDirection(rng);
    c.V = (i % 2) ? randomDirection(rng)
                  : glm::normalize(shading::reflectLight(glm::normalize(c.N), glm::normalize(c.L))) +
                        0.2f * glm::normalize(randomDirection(rng));
    return c;
}

std::vector<Case> makeCases() {
    std::mt19937 rng(20261122);
    std::uniform_real_distribution<float> logS(0.0f, 3.0f);
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = std::pow(10.0f, logS(rng));  // [1, 1000], log-uniform
        c.model = (i / 2) % 2;
        cases.push_back(c);
    }
    // Exact corner cases: H = N, L = N = V, grazing light, s = 1 and 1000.
    cases[0] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 1000.0f, 0};
    cases[1] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 1000.0f, 1};
    cases[2] = {{0, 0, 1}, {1, 0, 1e-4f}, {-1, 0, 1e-4f}, 1.0f, 1};
    cases[3] = {{0, 1, 0}, {0, -1, 0}, {0, 1, 0}, 32.0f, 0};
    return cases;
}

// Runs lighting_probe.frag once per case (one texel each) and reads the results back.
ImageF runProbe(const std::vector<Case>& cases, const glm::vec3& Il, const glm::vec3& md, const glm::vec3& ms) {
    std::vector<glm::vec4> n, l, v, params, d0, d1;
    for (const Case& c : cases) {
        n.emplace_back(c.N, 0.0f);
        l.emplace_back(c.L, 0.0f);
        v.emplace_back(c.V, 0.0f);
        params.emplace_back(c.s, float(c.model), c.metallic, c.w);
        d0.push_back(c.disney0);
        d1.push_back(c.disney1);
    }
    gl::Program program = gl::Program::build(gl::ShaderLibrary(), "fullscreen.vert", "lighting_probe.frag");
    gl::Texture tn = floatTexture(n), tl = floatTexture(l), tv = floatTexture(v), tp = floatTexture(params);
    gl::Texture td0 = floatTexture(d0), td1 = floatTexture(d1);
    raster::RenderTarget target;
    target.resize(kW, kH, false);
    target.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program.id());
    const char* samplers[] = {"t_N", "t_L", "t_V", "t_params", "t_disney0", "t_disney1"};
    const gl::Texture* textures[] = {&tn, &tl, &tv, &tp, &td0, &td1};
    for (int i = 0; i < 6; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, textures[i]->id());
        glUniform1i(program.uniform(samplers[i]), i);
    }
    glUniform3fv(program.uniform("u_Il"), 1, glm::value_ptr(Il));
    glUniform3fv(program.uniform("u_md"), 1, glm::value_ptr(md));
    glUniform3fv(program.uniform("u_ms"), 1, glm::value_ptr(ms));
    gl::VertexArray vao = gl::VertexArray::create();
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glActiveTexture(GL_TEXTURE0);
    ImageF result;
    target.readColor(result);
    return result;
}

}  // namespace

class ShaderUnitTest : public test::GlTest {};

TEST_F(ShaderUnitTest, GlslLightingEqualsCppOverSweep) {
    const std::vector<Case> cases = makeCases();
    ASSERT_GE(cases.size(), 1000u);
    const glm::vec3 Il(1.0f, 0.7f, 0.3f), md(0.6f, 0.5f, 0.4f), ms(0.9f, 0.8f, 1.0f);
    const ImageF result = runProbe(cases, Il, md, ms);

    const float tol = 1e-4f;
    float worst = 0.0f;
    int worstIndex = -1, failures = 0;
    std::ofstream report(test::outputPath("shader_unit_sweep.csv"));
    report << "index,model,s,gpu_r,cpu_r,gpu_spec,cpu_spec\n";
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        int x = int(i) % kW, yGl = int(i) / kW;
        const float* gpu = result.pixel(x, kH - 1 - yGl);  // readColor put GL's bottom row last
        glm::vec3 cpu = shading::shadeLight(c.N, c.L, c.V, Il, md, ms, c.s, c.model, true, true);
        glm::vec3 Nn = glm::normalize(c.N), Ln = glm::normalize(c.L), Vn = glm::normalize(c.V);
        float spec =
            c.model == 0 ? shading::specularPhong(Nn, Ln, Vn, c.s) : shading::specularBlinnPhong(Nn, Ln, Vn, c.s);
        float err = std::max(
            {std::abs(gpu[0] - cpu.x), std::abs(gpu[1] - cpu.y), std::abs(gpu[2] - cpu.z), std::abs(gpu[3] - spec)});
        report << i << ',' << c.model << ',' << c.s << ',' << gpu[0] << ',' << cpu.x << ',' << gpu[3] << ',' << spec
               << '\n';
        if (err > worst) {
            worst = err;
            worstIndex = int(i);
        }
        if (err > tol) ++failures;
    }
    RecordProperty("max_abs_error", std::to_string(worst));
    std::printf("shader-unit sweep: %zu cases, max |GLSL - C++| = %.3g (case %d)\n", cases.size(), worst, worstIndex);
    EXPECT_EQ(failures, 0) << "max error " << worst << " at case " << worstIndex << "; all values in "
                           << test::outputPath("shader_unit_sweep.csv");
    // Negative control: the comparison must notice a 10 % change of shininess.
    int noticed = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);
        glm::vec3 cpu = shading::shadeLight(c.N, c.L, c.V, Il, md, ms, c.s * 1.1f, c.model, true, true);
        if (std::abs(gpu[0] - cpu.x) > tol) ++noticed;
    }
    EXPECT_GT(noticed, int(cases.size()) / 10) << "a 10% shininess change went unnoticed: the test cannot fail";
}

namespace {

// A spot light's arriving intensity (lightIntensityAt with a cone and a range), over directions inside, across
// and outside cones of random angles, and distances inside and beyond random ranges. The case's N is the spot's
// direction, V its attenuation; s and metallic carry the cone's scale and offset, model 9 selects the kernel.
struct SpotCase {
    glm::vec3 spotDir, L, attenuation;
    glm::vec2 cone;
    float range;
};

std::vector<SpotCase> makeSpotCases() {
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<SpotCase> cases;
    for (int i = 0; i < kW * kH; ++i) {
        SpotCase c{};
        c.spotDir = randomDirection(rng);
        const float outer = 1.5707963f * unit(rng);
        const float inner = i % 7 == 0 ? outer : outer * unit(rng);  // every 7th a hard edge
        c.cone = shading::spotConeScaleOffset(inner, outer);
        // The way from the light to the point at an angle from the axis around the cone's edge.
        const float angle = outer * 2.0f * unit(rng);
        glm::vec3 side = glm::cross(glm::normalize(c.spotDir), randomDirection(rng));
        side = glm::length(side) > 1e-4f ? glm::normalize(side) : glm::vec3(1, 0, 0);
        const glm::vec3 toPoint = std::cos(angle) * glm::normalize(c.spotDir) + std::sin(angle) * side;
        const float d = 0.1f + 10.0f * unit(rng);
        c.L = -d * toPoint;
        c.attenuation = i % 3 == 0 ? glm::vec3(1, 0, 0) : glm::vec3(1.0f, unit(rng), unit(rng));
        c.range = i % 4 == 0 ? 0.0f : 12.0f * unit(rng) + 0.1f;
        cases.push_back(c);
    }
    return cases;
}

}  // namespace

TEST_F(ShaderUnitTest, GlslSpotIntensityEqualsCpp) {
    const std::vector<SpotCase> spots = makeSpotCases();
    std::vector<Case> cases;
    for (const SpotCase& s : spots) {
        cases.push_back(Case{s.spotDir, s.L, s.attenuation, s.cone.x, 9, s.cone.y, s.range});
    }
    const glm::vec3 Il(1.0f, 0.7f, 0.3f);
    const ImageF result = runProbe(cases, Il, glm::vec3(0.0f), glm::vec3(0.0f));
    const float tol = 1e-4f;
    int failures = 0, inside = 0, edge = 0, outside = 0, noticed = 0;
    float worst = 0.0f;
    std::ofstream report(test::outputPath("shader_unit_spot.csv"));
    report << "index,gpu_r,cpu_r,gpu_cone,cpu_cone,cone_scale\n";
    for (size_t i = 0; i < spots.size(); ++i) {
        const SpotCase& s = spots[i];
        const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);
        const glm::vec4 cone(s.cone.x, s.cone.y, s.range, 1.0f);
        const glm::vec3 cpu = shading::lightIntensityAt(Il, true, s.attenuation, s.L, s.spotDir, cone);
        const float cpuCone = shading::spotAttenuation(s.spotDir, s.L, s.cone);
        // The cone factor's slope in cd is 2·a·scale: the GPU's and the CPU's cd, each a dot of normalised
        // vectors, differ by a few ulps (4 · 2^-24 allowed), which a narrow cone's large scale multiplies.
        const float allowed = tol + 2.0f * s.cone.x * 4.0f * 5.96e-8f;
        const float err = std::max(
            {std::abs(gpu[0] - cpu.x), std::abs(gpu[1] - cpu.y), std::abs(gpu[2] - cpu.z), std::abs(gpu[3] - cpuCone)});
        report << i << ',' << gpu[0] << ',' << cpu.x << ',' << gpu[3] << ',' << cpuCone << ',' << s.cone.x << '\n';
        worst = std::max(worst, err / allowed);
        if (err > allowed) ++failures;
        (cpuCone >= 1.0f ? inside : cpuCone <= 0.0f ? outside : edge) += 1;
        // Negative control: the outer angle widened by 0.05 rad must change the cone where it is not 0 or 1.
        const float cosOuter = -s.cone.y / s.cone.x;
        const float cosInner = cosOuter + 1.0f / s.cone.x;
        const float outer = std::acos(std::clamp(cosOuter, -1.0f, 1.0f));
        const float inner = std::acos(std::clamp(cosInner, -1.0f, 1.0f));
        const float wider =
            shading::spotAttenuation(s.spotDir, s.L, shading::spotConeScaleOffset(inner, outer + 0.05f));
        if (std::abs(gpu[3] - wider) > tol) ++noticed;
    }
    std::printf(
        "spot sweep: %zu cases (%d inside, %d across the edge, %d outside), worst |GLSL - C++| %.2f of "
        "its allowance\n",
        spots.size(), inside, edge, outside, worst);
    EXPECT_EQ(failures, 0) << "worst error " << worst << " of its allowance; all values in "
                           << test::outputPath("shader_unit_spot.csv");
    EXPECT_GT(inside, 100);
    EXPECT_GT(edge, 100);
    EXPECT_GT(outside, 100);
    EXPECT_GT(noticed, int(spots.size()) / 10) << "a wider outer cone went unnoticed: the test cannot fail";
}

namespace {

// The pbr sweep: roughness uniform in [0, 1] (0 exercises the α clamp), metallic 0, 1 or in between; half the
// cases look along the mirror direction, where GGX peaks.
std::vector<Case> makePbrCases() {
    std::mt19937 rng(20261128);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = unit(rng);
        c.model = shading::SL_MODEL_PBR;
        const int kind = (i / 2) % 3;
        c.metallic = kind == 0 ? 0.0f : kind == 1 ? 1.0f : unit(rng);
        cases.push_back(c);
    }
    cases[0] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 0.0f, shading::SL_MODEL_PBR, 0.0f};  // the clamped mirror peak
    cases[1] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 1.0f, shading::SL_MODEL_PBR, 1.0f};
    cases[2] = {{0, 0, 1}, {1, 0, 1e-4f}, {-1, 0, 1e-4f}, 0.5f, shading::SL_MODEL_PBR, 0.0f};  // grazing
    cases[3] = {{0, 1, 0}, {0, -1, 0}, {0, 1, 0}, 0.5f, shading::SL_MODEL_PBR, 1.0f};          // unlit side
    return cases;
}

// |GLSL − C++| relative to max(1, |C++|): GGX's peak reaches 1/(π α²) ≈ 10^5, where 1e-4 absolute is below
// float's resolution; below 1 this is the absolute difference.
float relativeError(float gpu, float cpu) { return std::abs(gpu - cpu) / std::max(1.0f, std::abs(cpu)); }

glm::vec3 cpuPbr(const Case& c, const glm::vec3& Il, const glm::vec3& baseColor, float roughness) {
    return shading::shadeLight(c.N, c.L, c.V, Il, shading::pbrDiffuseColor(baseColor, c.metallic),
                               shading::pbrF0(baseColor, c.metallic), roughness, c.model, true, true);
}

}  // namespace

TEST_F(ShaderUnitTest, GlslPbrEqualsCppOverSweep) {
    const std::vector<Case> cases = makePbrCases();
    ASSERT_GE(cases.size(), 2048u);
    const glm::vec3 Il(1.0f, 0.7f, 0.3f), baseColor(0.9f, 0.6f, 0.2f);
    const ImageF result = runProbe(cases, Il, baseColor, glm::vec3(0.0f));

    const float tol = 1e-4f;
    float worst = 0.0f;
    int worstIndex = -1, failures = 0;
    std::ofstream report(test::outputPath("shader_unit_pbr_sweep.csv"));
    report << "index,roughness,metallic,gpu_r,cpu_r,gpu_spec_g,cpu_spec_g\n";
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);
        const glm::vec3 cpu = cpuPbr(c, Il, baseColor, c.s);
        const glm::vec3 spec = shading::specularGGX(glm::normalize(c.N), glm::normalize(c.L), glm::normalize(c.V),
                                                    shading::pbrF0(baseColor, c.metallic), c.s);
        const float err = std::max({relativeError(gpu[0], cpu.x), relativeError(gpu[1], cpu.y),
                                    relativeError(gpu[2], cpu.z), relativeError(gpu[3], spec.y)});
        report << i << ',' << c.s << ',' << c.metallic << ',' << gpu[0] << ',' << cpu.x << ',' << gpu[3] << ','
               << spec.y << '\n';
        if (err > worst) {
            worst = err;
            worstIndex = int(i);
        }
        if (err > tol) ++failures;
    }
    RecordProperty("max_rel_error", std::to_string(worst));
    std::printf("shader-unit pbr sweep: %zu cases, max |GLSL - C++| / max(1, |C++|) = %.3g (case %d)\n", cases.size(),
                worst, worstIndex);
    EXPECT_EQ(failures, 0) << "max error " << worst << " at case " << worstIndex << "; all values in "
                           << test::outputPath("shader_unit_pbr_sweep.csv");
    // Negative controls: a 10 % change of roughness, and metallic flipped, must both be noticed.
    int roughnessNoticed = 0, metallicNoticed = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);
        if (relativeError(gpu[1], cpuPbr(c, Il, baseColor, c.s * 1.1f).y) > tol) ++roughnessNoticed;
        Case flipped = c;
        flipped.metallic = 1.0f - c.metallic;
        if (relativeError(gpu[1], cpuPbr(flipped, Il, baseColor, c.s).y) > tol) ++metallicNoticed;
    }
    EXPECT_GT(roughnessNoticed, int(cases.size()) / 10) << "a 10% roughness change went unnoticed";
    EXPECT_GT(metallicNoticed, int(cases.size()) / 10) << "flipping metallic went unnoticed";
}

namespace {

// The disney sweep: roughness, metallic and all eight parameters uniform in [0, 1], each of the optional lobes
// (subsurface, anisotropic, sheen, clearcoat) off in a quarter of the cases; half the cases look along the
// mirror direction, where the specular and clearcoat lobes peak.
std::vector<Case> makeDisneyCases() {
    std::mt19937 rng(20261204);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto maybe = [&](int i, int bit) { return (i >> bit) % 4 == 0 ? 0.0f : unit(rng); };
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = unit(rng);
        c.model = shading::SL_MODEL_DISNEY;
        const int kind = (i / 2) % 3;
        c.metallic = kind == 0 ? 0.0f : kind == 1 ? 1.0f : unit(rng);
        c.disney0 = glm::vec4(maybe(i, 2), unit(rng), unit(rng), maybe(i, 4));
        c.disney1 = glm::vec4(maybe(i, 6), unit(rng), maybe(i, 8), unit(rng));
        cases.push_back(c);
    }
    const glm::vec4 d0(0.0f, 0.5f, 0.0f, 0.0f), d1(0.0f, 0.5f, 0.0f, 1.0f);  // Disney's defaults
    cases[0] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 0.0f, shading::SL_MODEL_DISNEY, 0.0f, 0.0f, d0, d1};  // mirror peak
    cases[1] = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, 1.0f, shading::SL_MODEL_DISNEY, 1.0f, 0.0f, d0, glm::vec4(1.0f)};
    cases[2] = {{0, 0, 1}, {1, 0, 1e-4f}, {-1, 0, 1e-4f}, 0.5f, shading::SL_MODEL_DISNEY, 0.0f, 0.0f, d0, d1};
    cases[3] = {{0, 1, 0}, {0, -1, 0}, {0, 1, 0}, 0.5f, shading::SL_MODEL_DISNEY, 1.0f, 0.0f, d0, d1};  // unlit side
    return cases;
}

glm::vec3 cpuDisney(const Case& c, const glm::vec3& Il, const glm::vec3& baseColor) {
    return shading::shadeLightModel(c.N, c.L, c.V, Il, shading::pbrDiffuseColor(baseColor, c.metallic), glm::vec3(0.0f),
                                    c.s, c.model, true, true, glm::vec3(1.0f), baseColor, c.metallic, c.disney0,
                                    c.disney1);
}

}  // namespace

// disney: the principled BRDF's GLSL and C++ agree to 1e-4 (relative above 1) over 2,048 parameter sets; a 10 %
// change of the roughness, and 0.1 more of each optional lobe, are noticed (negative controls).
TEST_F(ShaderUnitTest, GlslDisneyEqualsCppOverSweep) {
    const std::vector<Case> cases = makeDisneyCases();
    ASSERT_GE(cases.size(), 2048u);
    const glm::vec3 Il(1.0f, 0.7f, 0.3f), baseColor(0.9f, 0.6f, 0.2f);
    const ImageF result = runProbe(cases, Il, baseColor, glm::vec3(0.0f));
    const float tol = 1e-4f;
    float worst = 0.0f;
    int worstIndex = -1, failures = 0;
    std::ofstream report(test::outputPath("shader_unit_disney_sweep.csv"));
    report << "index,roughness,metallic,subsurface,specular,specularTint,anisotropic,sheen,sheenTint,clearcoat,"
              "clearcoatGloss,gpu_r,cpu_r,gpu_spec_g,cpu_spec_g\n";
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);
        const glm::vec3 cpu = cpuDisney(c, Il, baseColor);
        const glm::vec3 spec = shading::shadeLightDisney(c.N, c.L, c.V, glm::vec3(1.0f), baseColor, c.metallic, c.s,
                                                         c.disney0, c.disney1, false, true, glm::vec3(1.0f));
        const float err = std::max({relativeError(gpu[0], cpu.x), relativeError(gpu[1], cpu.y),
                                    relativeError(gpu[2], cpu.z), relativeError(gpu[3], spec.y)});
        report << i << ',' << c.s << ',' << c.metallic;
        for (int k = 0; k < 4; ++k) report << ',' << c.disney0[k];
        for (int k = 0; k < 4; ++k) report << ',' << c.disney1[k];
        report << ',' << gpu[0] << ',' << cpu.x << ',' << gpu[3] << ',' << spec.y << '\n';
        if (err > worst) {
            worst = err;
            worstIndex = int(i);
        }
        if (err > tol) ++failures;
    }
    RecordProperty("max_rel_error", std::to_string(worst));
    std::printf("shader-unit disney sweep: %zu cases, max |GLSL - C++| / max(1, |C++|) = %.3g (case %d)\n",
                cases.size(), worst, worstIndex);
    EXPECT_EQ(failures, 0) << "max error " << worst << " at case " << worstIndex << "; all values in "
                           << test::outputPath("shader_unit_disney_sweep.csv");
    struct Control {
        const char* what;
        int vec, component;  // -1: the roughness, scaled by 1.1; else disney0 / disney1's component, plus 0.1
    };
    const Control controls[] = {{"roughness", -1, 0},   {"subsurface", 0, 0}, {"anisotropic", 0, 3},
                                {"sheen", 1, 0},        {"clearcoat", 1, 2},  {"clearcoatGloss", 1, 3},
                                {"specularTint", 0, 2}, {"specular", 0, 1}};
    for (const Control& k : controls) {
        int noticed = 0;
        for (size_t i = 0; i < cases.size(); ++i) {
            Case changed = cases[i];
            if (k.vec < 0)
                changed.s *= 1.1f;
            else
                (k.vec == 0 ? changed.disney0 : changed.disney1)[k.component] += 0.1f;
            const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);
            const glm::vec3 cpu = cpuDisney(changed, Il, baseColor);
            if (std::max({relativeError(gpu[0], cpu.x), relativeError(gpu[1], cpu.y), relativeError(gpu[2], cpu.z)}) >
                tol)
                ++noticed;
        }
        EXPECT_GT(noticed, int(cases.size()) / 10) << "0.1 more " << k.what << " went unnoticed";
    }
}

namespace {

constexpr int kCoatedPbr = 8;  // lighting_probe.frag's case for pbr under the clear coat

constexpr int kSpecularLayered = 7;  // lighting_probe.frag's case for pbr with glTF's specular layer

// The specular layer sweep: pbr's roughness and metallic (0, 1 or between), a dielectric F0 from an index in
// [1, 3] tinted by a colour in [0, 2] (clamped to 1), and a weight in [0, 1]; glTF's anisotropy in half the cases.
std::vector<Case> makeSpecularLayerCases() {
    std::mt19937 rng(20261207);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = unit(rng);
        c.model = kSpecularLayered;
        const int kind = (i / 2) % 3;
        c.metallic = kind == 0 ? 0.0f : kind == 1 ? 1.0f : unit(rng);
        const float ior = 1.0f + 2.0f * unit(rng), r = (ior - 1.0f) / (ior + 1.0f);
        glm::vec3 f0;
        for (int k = 0; k < 3; ++k) f0[k] = std::min(r * r * 2.0f * unit(rng), 1.0f);
        c.disney0 = glm::vec4(f0, unit(rng));
        // glTF's anisotropy in half the cases: a strength and a turn of the direction (Anisotropy::packed).
        if ((i / 6) % 2) c.disney1 = glm::vec4(Anisotropy{unit(rng), 6.3f * unit(rng) - 3.15f}.packed(), 0.0f);
        cases.push_back(c);
    }
    return cases;
}

glm::vec3 cpuSpecularLayered(const Case& c, const glm::vec3& Il, const glm::vec3& baseColor) {
    return shading::shadeLightPbrSpecular(
        c.N, c.L, c.V, Il, shading::pbrDiffuseColor(baseColor, c.metallic), baseColor, c.metallic, c.s, c.disney0,
        glm::vec4(shading::anisotropyDirection(c.N, glm::vec4(0.0f), glm::vec3(c.disney1)), c.disney1.x), true, true,
        glm::vec3(1.0f));
}

// The clear coat sweep: pbr's roughness and metallic, the coat's factor and roughness uniform in [0, 1] (the
// factor 0 in an eighth of the cases), the coat's normal the base's in half the cases and tilted off it in the
// others (a base normal map under a smooth coat); half the cases look along the mirror direction.
std::vector<Case> makeCoatCases() {
    std::mt19937 rng(20261206);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = unit(rng);
        c.model = kCoatedPbr;
        c.metallic = (i / 2) % 3 == 0 ? 1.0f : unit(rng);
        c.disney0 = glm::vec4((i / 4) % 8 == 0 ? 0.0f : unit(rng), unit(rng), 0.0f, 0.0f);
        const glm::vec3 tilt = (i / 8) % 2 ? 0.3f * glm::normalize(randomDirection(rng)) : glm::vec3(0.0f);
        c.disney1 = glm::vec4(glm::normalize(c.N) + tilt, 0.0f);
        cases.push_back(c);
    }
    return cases;
}

glm::vec3 cpuCoated(const Case& c, const glm::vec3& Il, const glm::vec3& baseColor) {
    const glm::vec3 base =
        shading::shadeLight(c.N, c.L, c.V, Il, shading::pbrDiffuseColor(baseColor, c.metallic),
                            shading::pbrF0(baseColor, c.metallic), c.s, shading::SL_MODEL_PBR, true, true);
    return shading::clearcoatLight(base, glm::vec3(c.disney1), c.L, c.V, Il, glm::vec2(c.disney0), true);
}

constexpr int kSheenedPbr = 10;  // lighting_probe.frag's case for pbr under glTF's sheen

// The sheen sweep: pbr's roughness and metallic, the sheen's colour in [0, 1]³ (0 in an eighth of the cases) and
// roughness in [0, 1], its albedos at N·V and N·L from the table (as the renderers read them).
std::vector<Case> makeSheenCases() {
    std::mt19937 rng(20261208);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = unit(rng);
        c.model = kSheenedPbr;
        c.metallic = (i / 2) % 3 == 0 ? 1.0f : unit(rng);
        const glm::vec3 color = (i / 4) % 8 == 0 ? glm::vec3(0.0f) : glm::vec3(unit(rng), unit(rng), unit(rng));
        c.disney0 = glm::vec4(color, unit(rng));
        shading::SheenLookup table{&shading::sheenLut()};
        c.disney1 = glm::vec4(table.at(table.sheenCos(c.N, c.V), c.disney0.w),
                              table.at(table.sheenCos(c.N, c.L), c.disney0.w), 0.0f, 0.0f);
        cases.push_back(c);
    }
    return cases;
}

glm::vec3 cpuSheened(const Case& c, const glm::vec3& Il, const glm::vec3& baseColor) {
    const glm::vec3 base =
        shading::shadeLight(c.N, c.L, c.V, Il, shading::pbrDiffuseColor(baseColor, c.metallic),
                            shading::pbrF0(baseColor, c.metallic), c.s, shading::SL_MODEL_PBR, true, true);
    return shading::sheenLight(base, c.N, c.L, c.V, Il, c.disney0, c.disney1.x, c.disney1.y, true);
}

// The GPU's texel for case i (lighting_probe.frag writes case i at column i % kW, row i / kW from the top).
const float* gpuOf(const ImageF& result, size_t i) { return result.pixel(int(i) % kW, kH - 1 - int(i) / kW); }

// A glTF layer's sweep: the GPU's (rgb, w) against `cpu(case)` (rgb) and `cpuW(case)` to 1e-4 relative above 1,
// every value in `csv`; then each control's changed case (`change(case&)`), run through `cpu`, must be noticed
// in more than a tenth of the cases (a twentieth where `rare`).
struct SweepControl {
    const char* what;
    std::function<void(Case&)> change;
    bool rare = false;
};
void checkLayerSweep(const char* name, const std::vector<Case>& cases, const ImageF& result,
                     const std::function<glm::vec3(const Case&)>& cpu, const std::function<float(const Case&)>& cpuW,
                     const std::vector<SweepControl>& controls) {
    const float tol = 1e-4f;
    float worst = 0.0f;
    int worstIndex = -1, failures = 0;
    const std::string csv = test::outputPath(std::string("shader_unit_") + name + "_sweep.csv");
    std::ofstream report(csv);
    report << "index,model,roughness,metallic,p0,p1,p2,p3,gpu_r,cpu_r,gpu_w,cpu_w\n";
    for (size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        const float* gpu = gpuOf(result, i);
        const glm::vec3 rgb = cpu(c);
        const float w = cpuW(c);
        const float err = std::max({relativeError(gpu[0], rgb.x), relativeError(gpu[1], rgb.y),
                                    relativeError(gpu[2], rgb.z), relativeError(gpu[3], w)});
        report << i << ',' << c.model << ',' << c.s << ',' << c.metallic;
        for (int k = 0; k < 4; ++k) report << ',' << c.disney0[k];
        report << ',' << gpu[0] << ',' << rgb.x << ',' << gpu[3] << ',' << w << '\n';
        if (err > worst) {
            worst = err;
            worstIndex = int(i);
        }
        if (err > tol) ++failures;
    }
    ::testing::Test::RecordProperty("max_rel_error", std::to_string(worst));
    std::printf("shader-unit %s sweep: %zu cases, max |GLSL - C++| / max(1, |C++|) = %.3g (case %d)\n", name,
                cases.size(), worst, worstIndex);
    EXPECT_EQ(failures, 0) << "max error " << worst << " at case " << worstIndex << "; all values in " << csv;
    for (const SweepControl& k : controls) {
        int noticed = 0;
        for (size_t i = 0; i < cases.size(); ++i) {
            Case changed = cases[i];
            k.change(changed);
            const float* gpu = gpuOf(result, i);
            const glm::vec3 rgb = cpu(changed);
            if (std::max({relativeError(gpu[0], rgb.x), relativeError(gpu[1], rgb.y), relativeError(gpu[2], rgb.z)}) >
                tol)
                ++noticed;
        }
        EXPECT_GT(noticed, int(cases.size()) / (k.rare ? 20 : 10)) << k.what << " went unnoticed";
    }
}

const glm::vec3 kLayerIl(1.0f, 0.7f, 0.3f), kLayerBase(0.9f, 0.6f, 0.2f);

constexpr int kTransmittingPbr = 11;  // lighting_probe.frag's case for pbr under glTF's transmission

// The transmission sweep: pbr's roughness and metallic, a specular layer as in its own sweep, a factor in [0, 1],
// an index in [1, 3] giving the roughness scale and, in half the cases, the volume's η (else a thin wall), and a
// grey tint in [0, 1]. N and L are independent: about half the lights are behind the surface.
std::vector<Case> makeTransmissionCases() {
    std::mt19937 rng(20261209);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<Case> cases;
    for (int i = 0; i < kW * kH; ++i) {
        Case c = randomGeometry(rng, i);
        c.s = unit(rng);
        c.model = kTransmittingPbr;
        c.metallic = (i / 2) % 4 == 0 ? 0.0f : unit(rng);
        const float ior = 1.0f + 2.0f * unit(rng), r = (ior - 1.0f) / (ior + 1.0f);
        c.disney0 = glm::vec4(glm::vec3(r * r), 0.5f + 0.5f * unit(rng));
        Material m;
        m.ior = ior;
        m.transmission.factor = unit(rng);
        if ((i / 4) % 2) m.volume.thickness = 1.0f;
        c.disney1 = glm::vec4(glm::vec3(transmissionPacked(m)), unit(rng));
        cases.push_back(c);
    }
    return cases;
}

glm::vec3 cpuTransmitting(const Case& c, const glm::vec3& Il, const glm::vec3& baseColor) {
    const glm::vec3 md = shading::pbrDiffuseColor(baseColor, c.metallic), tc = md * c.disney1.x;
    return shading::shadeLightPbrSpecular(c.N, c.L, c.V, Il, md * (1.0f - c.disney1.x), baseColor, c.metallic, c.s,
                                          c.disney0, glm::vec4(0.0f), true, true, glm::vec3(1.0f)) +
           shading::transmissionLight(c.N, c.L, c.V, Il, tc, glm::vec3(c.disney1.w), c.disney0, c.s * c.disney1.y, true,
                                      true);
}

float cpuThrough(const Case& c) {
    const glm::vec3 tc = shading::pbrDiffuseColor(kLayerBase, c.metallic) * c.disney1.x;
    const glm::vec4 packed(c.disney1.x, c.disney1.y, c.disney1.z, 0.0f);
    return shading::transmissionEnvironment(tc, glm::vec3(0.7f), c.disney0, glm::vec2(c.s, c.metallic), true, true).y +
           0.5f * shading::transmissionDirection(c.N, c.V, packed).y;
}

}  // namespace

// pbr under glTF's transmission and volume: the light through (transmissionLight) with the base's share, the
// environment through (transmissionEnvironment) and the direction it comes from (transmissionDirection) agree in
// GLSL and C++ to 1e-4 (relative above 1) over 2,048 cases; 10 % more transmission, a 10 % wider transmitted lobe,
// the tint dropped and the transmission dropped are noticed (negative controls).
TEST_F(ShaderUnitTest, GlslTransmissionEqualsCppOverSweep) {
    const std::vector<Case> cases = makeTransmissionCases();
    ASSERT_GE(cases.size(), 2048u);
    checkLayerSweep("transmission", cases, runProbe(cases, kLayerIl, kLayerBase, glm::vec3(0.0f)),
                    [](const Case& c) { return cpuTransmitting(c, kLayerIl, kLayerBase); }, cpuThrough,
                    {{"10% more transmission", [](Case& c) { c.disney1.x = std::min(c.disney1.x * 1.1f, 1.0f); }},
                     {"10% wider transmitted lobe", [](Case& c) { c.disney1.y *= 1.1f; }},
                     {"the tint dropped", [](Case& c) { c.disney1.w = 1.0f; }},
                     {"the transmission dropped", [](Case& c) { c.disney1.x = 0.0f; }}});
}

// pbr with glTF's specular layer and ior, and its anisotropy: shadeLightPbrSpecular's GLSL and C++ agree to 1e-4
// (relative above 1) over 2,048 cases, and pbrSpecularF0 too; 10 % more F0, 10 % less weight, 10 % more roughness
// and the anisotropy's direction turned by 0.1 rad are noticed.
TEST_F(ShaderUnitTest, GlslSpecularLayerEqualsCppOverSweep) {
    const std::vector<Case> cases = makeSpecularLayerCases();
    ASSERT_GE(cases.size(), 2048u);
    checkLayerSweep(
        "specular_layer", cases, runProbe(cases, kLayerIl, kLayerBase, glm::vec3(0.0f)),
        [](const Case& c) { return cpuSpecularLayered(c, kLayerIl, kLayerBase); },
        [](const Case& c) { return shading::pbrSpecularF0(kLayerBase, c.metallic, c.disney0).y; },
        {{"10% more F0", [](Case& c) { c.disney0 = glm::vec4(glm::vec3(c.disney0) * 1.1f, c.disney0.w); }},
         {"10% less weight", [](Case& c) { c.disney0.w *= 0.9f; }},
         {"10% more roughness", [](Case& c) { c.s *= 1.1f; }},
         {"anisotropy turned by 0.1 rad",
          [](Case& c) {
              const float r = std::atan2(c.disney1.z, c.disney1.y) + 0.1f;
              if (c.disney1.x > 0.0f) c.disney1 = glm::vec4(Anisotropy{c.disney1.x, r}.packed(), 0.0f);
          },
          true}});
}

// pbr under glTF's clear coat: clearcoatLight's GLSL and C++ agree to 1e-4 (relative above 1) over 2,048 cases,
// and the coat's Fresnel weight too; 10 % more coat, 10 % more coat roughness and the base's normal for the coat's
// are noticed (negative controls; the last only where the coat's normal was tilted, half the cases).
TEST_F(ShaderUnitTest, GlslClearcoatEqualsCppOverSweep) {
    const std::vector<Case> cases = makeCoatCases();
    ASSERT_GE(cases.size(), 2048u);
    checkLayerSweep(
        "clearcoat", cases, runProbe(cases, kLayerIl, kLayerBase, glm::vec3(0.0f)),
        [](const Case& c) { return cpuCoated(c, kLayerIl, kLayerBase); },
        [](const Case& c) { return shading::clearcoatWeight(glm::vec3(c.disney1), c.V, c.disney0.x); },
        {{"10% more coat", [](Case& c) { c.disney0.x *= 1.1f; }},
         {"10% more coat roughness", [](Case& c) { c.disney0.y *= 1.1f; }},
         {"the base's normal for the coat's", [](Case& c) { c.disney1 = glm::vec4(c.N, 0.0f); }, true}});
}

// pbr under glTF's sheen: sheenLight's GLSL and C++ agree to 1e-4 (relative above 1) over 2,048 cases, and the
// sheen's lobe too; 10 % more sheen colour, 10 % more sheen roughness and the sheen dropped are noticed (negative
// controls).
TEST_F(ShaderUnitTest, GlslSheenEqualsCppOverSweep) {
    const std::vector<Case> cases = makeSheenCases();
    ASSERT_GE(cases.size(), 2048u);
    checkLayerSweep(
        "sheen", cases, runProbe(cases, kLayerIl, kLayerBase, glm::vec3(0.0f)),
        [](const Case& c) { return cpuSheened(c, kLayerIl, kLayerBase); },
        [](const Case& c) { return shading::sheenLobe(c.N, c.L, c.V, c.disney0.w); },
        {{"10% more sheen", [](Case& c) { c.disney0 = glm::vec4(glm::vec3(c.disney0) * 1.1f, c.disney0.w); }},
         {"10% more sheen roughness", [](Case& c) { c.disney0.w *= 1.1f; }},
         {"the sheen dropped", [](Case& c) { c.disney0 = glm::vec4(0.0f); }}});
}

namespace {

// Runs view_transform_probe.frag over `values` (three per texel) with one display, and reads the results back.
ImageF runViewProbe(const std::vector<glm::vec4>& values, const DisplaySettings& display) {
    gl::Program program = gl::Program::build(gl::ShaderLibrary(), "fullscreen.vert", "view_transform_probe.frag");
    gl::Texture input = floatTexture(values);
    raster::RenderTarget target;
    target.resize(kW, kH, false);
    target.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glUseProgram(program.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, input.id());
    glUniform1i(program.uniform("t_in"), 0);
    glUniform1f(program.uniform("u_exposure"), display.scale());  // as image_view.cpp sets it
    glUniform1i(program.uniform("u_transform"), display.transform == ViewTransform::Filmic ? 1 : 0);
    gl::VertexArray vao = gl::VertexArray::create();
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ImageF result;
    target.readColor(result);
    return result;
}

}  // namespace

// The viewer's exposure and view transform (shaders/view_transform.glsl in view_image.frag) equal the C++ that
// every PNG goes through (displayValue, image/encode.h) within 1e-6, over linear values from 0 to 40 (the
// Cornell lamp's radiance) and several exposures; a display 0.1 stops off, or the other transform, is noticed
// (negative controls).
TEST_F(ShaderUnitTest, GlslViewTransformEqualsCpp) {
    std::mt19937 rng(20261202);
    std::uniform_real_distribution<float> logValue(-4.0f, 1.6f);  // 1e-4 .. 40
    std::vector<glm::vec4> values;
    for (int i = 0; i < kW * kH; ++i)
        values.emplace_back(std::pow(10.0f, logValue(rng)), float(i) / float(kW * kH), 7.0f + float(i % 64) * 0.01f,
                            1.0f);
    values[0] = glm::vec4(0.0f, 1.0f, 8.0f, 1.0f);
    values[1] = glm::vec4(-0.5f, 7.24f, 1e6f, 1.0f);  // below 0, near the fit's crossing of 1, far above it
    const DisplaySettings displays[] = {{0.0, ViewTransform::Filmic},
                                        {1.0, ViewTransform::Filmic},
                                        {-2.5, ViewTransform::Filmic},
                                        {3.7, ViewTransform::Standard},
                                        {0.0, ViewTransform::Standard}};
    const float tol = 1e-6f;
    std::ofstream report(test::outputPath("shader_unit_view_transform.csv"));
    report << "display,index,channel,linear,gpu,cpu\n";
    for (const DisplaySettings& d : displays) {
        const ImageF result = runViewProbe(values, d);
        float worst = 0.0f;
        int failures = 0, offNoticed = 0, otherNoticed = 0;
        const DisplaySettings off{d.exposure + 0.1, d.transform};
        const DisplaySettings other{
            d.exposure, d.transform == ViewTransform::Filmic ? ViewTransform::Standard : ViewTransform::Filmic};
        for (size_t i = 0; i < values.size(); ++i) {
            const float* gpu = result.pixel(int(i) % kW, kH - 1 - int(i) / kW);  // readColor put GL's bottom row last
            for (int c = 0; c < 3; ++c) {
                const float linear = values[i][c], cpu = displayValue(linear, d);
                const float err = std::abs(gpu[c] - cpu) / std::max(1.0f, std::abs(cpu));
                worst = std::max(worst, err);
                if (err > tol) {
                    ++failures;
                    report << describe(d) << ',' << i << ',' << c << ',' << linear << ',' << gpu[c] << ',' << cpu
                           << '\n';
                }
                if (std::abs(gpu[c] - displayValue(linear, off)) > tol) ++offNoticed;
                if (std::abs(gpu[c] - displayValue(linear, other)) > tol) ++otherNoticed;
            }
        }
        const std::string name = describe(d).empty() ? "standard" : describe(d);
        std::printf("view transform %s: max |GLSL - C++| / max(1, |C++|) = %.3g\n", name.c_str(), worst);
        EXPECT_EQ(failures, 0) << name << ": max error " << worst << "; the failures are in "
                               << test::outputPath("shader_unit_view_transform.csv");
        EXPECT_GT(offNoticed, int(values.size())) << name << ": 0.1 stops more went unnoticed";
        EXPECT_GT(otherNoticed, int(values.size()) / 2) << name << ": the other transform went unnoticed";
    }
}
