// C++ mirror of the std140 `Frame` uniform block in shaders/frame.glsl, with its layout pinned by
// static_asserts (Filament's UibStructs.h does the same).
#pragma once

#include "gl/gl_api.h"
#include "raster/band.h"
#include "scene/scene.h"
#include "scene/view.h"

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace shadelab::raster {

struct FrameBlock {
    glm::mat4 viewProj;
    glm::vec4 eye;
    glm::vec4 forward;
    glm::vec4 right;
    glm::vec4 up;
    glm::vec4 viewport;  // full width, height, tan(fovY/2), GL row of the band's bottom
    glm::vec4 ambient;   // Ia
    glm::ivec4 flags;    // model, term bits, light count, pass bits
    glm::vec4 lightPos[kMaxLights];
    glm::vec4 lightColor[kMaxLights];
    glm::vec4 lightAtten[kMaxLights];
    glm::vec4 lightSpot[kMaxLights];              // a spot's direction of travel (xyz)
    glm::vec4 lightCone[kMaxLights];              // lightCone(): spot scale, offset, range, spot flag
    glm::vec4 clipPlane{0.0f, 0.0f, 0.0f, 1.0f};  // mirror passes: keep dot(xyz, P) + w >= 0
    // The environment (shaders/ibl.glsl): Scene::environment and energyCompensation.
    glm::vec4 iblParams{1.0f, 1.0f, 0.0f, 0.0f};  // intensity, cos(rotation), sin(rotation), unused
    glm::ivec4 iblInfo{0};                        // IblMode, cube size, levels, pbr energy compensation (0/1)
    glm::vec4 iblRadiance{0.0f};                  // a uniform environment's radiance: background·intensity
    glm::vec4 iblSH[9] = {};                      // a map's SH9 irradiance (xyz), shading::PrefilteredEnvironment
};

static_assert(offsetof(FrameBlock, eye) == 64);
static_assert(offsetof(FrameBlock, viewport) == 128);
static_assert(offsetof(FrameBlock, flags) == 160);
static_assert(offsetof(FrameBlock, lightPos) == 176);
static_assert(offsetof(FrameBlock, lightColor) == 176 + 16 * kMaxLights);
static_assert(offsetof(FrameBlock, lightAtten) == 176 + 32 * kMaxLights);
static_assert(offsetof(FrameBlock, lightSpot) == 176 + 48 * kMaxLights);
static_assert(offsetof(FrameBlock, lightCone) == 176 + 64 * kMaxLights);
static_assert(offsetof(FrameBlock, clipPlane) == 176 + 80 * kMaxLights);
static_assert(offsetof(FrameBlock, iblParams) == 192 + 80 * kMaxLights);
static_assert(offsetof(FrameBlock, iblSH) == 240 + 80 * kMaxLights);
static_assert(sizeof(FrameBlock) == 384 + 80 * kMaxLights);

// FrameBlock::iblInfo.x: what surrounds the scene.
enum IblMode : int { kIblNone = 0, kIblUniform = 1, kIblMap = 2 };

enum TermBits : int { kTermAmbient = 1, kTermDiffuse = 2, kTermSpecular = 4 };
enum PassBits : int { kPassShadows = 1, kPassMirrors = 2 };

// Uniform-block bindings and texture units of the colour passes; unit 0 is left to callers (the viewer).
inline constexpr GLuint kFrameBinding = 0;
inline constexpr GLuint kShadowBinding = 1;
inline constexpr GLuint kShadowUnit = 1;
inline constexpr GLuint kReflectionUnit = 2;
inline constexpr GLuint kEnvironmentUnit = 3;
inline constexpr GLuint kIblCubeUnit = 4;              // the prefiltered atlas (IblTextures)
inline constexpr GLuint kIblDfgUnit = 5;               // the DFG table
inline constexpr GLuint kBaseColorUnit = 6;            // a mesh part's material maps (MeshTextures): base colour,
inline constexpr GLuint kMetalRoughUnit = 7;           // metallic-roughness,
inline constexpr GLuint kNormalMapUnit = 8;            // normal
inline constexpr GLuint kOcclusionUnit = 9;            // occlusion
inline constexpr GLuint kEmissiveUnit = 10;            // emissive
inline constexpr GLuint kClearcoatUnit = 11;           // and the clear coat's factor,
inline constexpr GLuint kClearcoatRoughnessUnit = 12;  // roughness
inline constexpr GLuint kClearcoatNormalUnit = 13;     // and normal (units 0–15 exist everywhere: GL 3.3, WebGL2)
inline constexpr GLuint kSheenLutUnit = 14;            // the sheen's albedo table (IblTextures)

// The block for drawing `band` of the image `v` describes, every sample moved by `jitter` pixels (x right, y
// down) off the pixel centre: the lights, terms, model and environment of `scene` in the layout above.
FrameBlock makeFrameBlock(const Scene& scene, const ViewSetup& v, Band band, glm::vec2 jitter = glm::vec2(0.0f));

}  // namespace shadelab::raster
