// makeFrameBlock (frame_block.h): the frame uniform block from the scene and the view, for one band and one
// jitter offset of the image.
#include "raster/frame_block.h"

#include "scene/light_at.h"
#include "scene/scene_models.h"
#include "shading/lighting.h"
#include "shading/prefilter.h"

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>

namespace shadelab::raster {
namespace {

// Maps the full image's clip space onto one band's: y' = a·y + b·w, so the band's rows fill its viewport.
glm::mat4 bandMatrix(int height, Band band) {
    glm::mat4 m(1.0f);
    if (band.rows <= 0 || band.rows == height) return m;
    const float h = float(height), rows = float(band.rows);
    const float glBottom = float(height - band.top - band.rows);
    m[1][1] = h / rows;
    m[3][1] = (h - 2.0f * glBottom) / rows - 1.0f;
    return m;
}

// Moves every sample by `jitter` pixels (x right, y down) off the pixel centre: the clip-space shift for
// rasterized meshes, and for the ray-cast impostors a forward vector moved by as much, since the camera ray
// normalize(forward + x·right + y·up) is linear in the pixel position before it is normalised.
glm::mat4 jitterMatrix(const ViewSetup& v, glm::vec2 jitter) {
    glm::mat4 m(1.0f);
    m[3][0] = -2.0f * jitter.x / float(v.width);
    m[3][1] = 2.0f * jitter.y / float(v.height);
    return m;
}

}  // namespace

FrameBlock makeFrameBlock(const Scene& scene, const ViewSetup& v, Band band, glm::vec2 jitter) {
    FrameBlock f{};
    f.viewProj = bandMatrix(v.height, band) * jitterMatrix(v, jitter) * v.viewProj;
    f.eye = glm::vec4(v.eye, 1.0f);
    const float aspect = float(v.width) / float(v.height);
    const glm::vec3 forward = v.forward + (2.0f * jitter.x / float(v.width)) * v.tanHalfFovY * aspect * v.right -
                              (2.0f * jitter.y / float(v.height)) * v.tanHalfFovY * v.up;
    f.forward = glm::vec4(forward, 0.0f);
    f.right = glm::vec4(v.right, 0.0f);
    f.up = glm::vec4(v.up, 0.0f);
    const float bandBottom = band.rows > 0 ? float(v.height - band.top - band.rows) : 0.0f;
    f.viewport = glm::vec4(float(v.width), float(v.height), v.tanHalfFovY, bandBottom);
    f.ambient = glm::vec4(scene.ambient, 0.0f);
    int terms = (scene.terms.ambient ? kTermAmbient : 0) | (scene.terms.diffuse ? kTermDiffuse : 0) |
                (scene.terms.specular ? kTermSpecular : 0);
    int model = modelIndex(scene.model);
    int count = int(std::min(scene.lights.size(), size_t(kMaxLights)));
    const bool lit = scene.terms.diffuse || scene.terms.specular;
    const int passes =
        (scene.terms.shadows && lit && count > 0 ? kPassShadows : 0) | (scene.terms.reflections ? kPassMirrors : 0);
    f.flags = glm::ivec4(model, terms, count, passes);
    for (int i = 0; i < count; ++i) {
        const Light& l = scene.lights[size_t(i)];
        f.lightPos[i] = glm::vec4(lightPosOrDir(l), l.positional() ? 1.0f : 0.0f);
        f.lightColor[i] = glm::vec4(l.color, 0.0f);
        f.lightAtten[i] = glm::vec4(l.attenuation, 0.0f);
        f.lightSpot[i] = glm::vec4(l.direction, 0.0f);
        f.lightCone[i] = lightCone(l);
    }
    // The environment, as src/trace/environment_light.cpp reads it.
    // (for the pbr and disney surfaces: the scene's model, or any material's own)
    f.iblInfo.w = scene.energyCompensation && usesPhysicallyBased(scene) ? 1 : 0;
    if (scene.environment) {
        const Environment& e = *scene.environment;
        f.iblParams =
            glm::vec4(e.intensity, std::cos(glm::radians(e.rotation)), std::sin(glm::radians(e.rotation)), 0.0f);
        f.iblRadiance = glm::vec4(scene.background * e.intensity, 0.0f);
        if (e.map) {
            f.iblInfo = glm::ivec4(kIblMap, e.map->size, e.map->levels, f.iblInfo.w);
            for (int i = 0; i < 9; ++i) f.iblSH[i] = glm::vec4(e.map->sh[size_t(i)], 0.0f);
        } else {
            f.iblInfo.x = kIblUniform;
            f.iblInfo.z = shading::prefilterLevels(256);  // the levels EnvironmentLight::mirrorWeight reads
        }
    }
    return f;
}

}  // namespace shadelab::raster
