// RasterRenderer: uploads, per-frame uniform block, and the three passes (meshes, spheres, planes), run once
// per mirror plane into its own target (planar_reflection.h) and then for the image itself.
#include "raster/raster_renderer.h"

#include "raster/frame_block.h"
#include "raster/planar_reflection.h"
#include "scene/coverage.h"
#include "scene/ray_epsilon.h"
#include "scene/view.h"
#include "shading/lighting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <optional>
#include <set>
#include <string>

namespace shadelab::raster {
namespace {

// 36 vertices of the cube [-1,1]^3, every triangle wound counter-clockwise seen from outside.
std::array<glm::vec3, 36> unitCube() {
    std::array<glm::vec3, 36> v{};
    size_t n = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            int a = (axis + 1) % 3, b = (axis + 2) % 3;
            glm::vec3 q[4];
            const float us[4] = {-1, 1, 1, -1}, vs[4] = {-1, -1, 1, 1};
            for (int k = 0; k < 4; ++k) {
                q[k][axis] = sign;
                q[k][a] = us[k];
                q[k][b] = vs[k];
            }
            glm::vec3 outward(0.0f);
            outward[axis] = sign;
            bool ccw = glm::dot(glm::cross(q[1] - q[0], q[2] - q[0]), outward) > 0.0f;
            const int order[6] = {0, 1, 2, 0, 2, 3};
            for (int k = 0; k < 6; ++k) v[n++] = q[ccw ? order[k] : order[5 - k]];
        }
    }
    return v;
}

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

FrameBlock makeFrameBlock(const Scene& scene, const ViewSetup& v, Band band, glm::vec2 jitter = glm::vec2(0.0f)) {
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
        bool point = l.type == LightType::Point;
        f.lightPos[i] = glm::vec4(point ? l.position : l.direction, point ? 1.0f : 0.0f);
        f.lightColor[i] = glm::vec4(l.color, 0.0f);
        f.lightAtten[i] = glm::vec4(l.attenuation, 0.0f);
    }
    // The environment, as src/trace/environment_light.cpp reads it.
    f.iblInfo.w = model == shading::SL_MODEL_PBR && scene.energyCompensation ? 1 : 0;
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
        }
    }
    return f;
}

// What rays that leave the scene see where nothing is drawn: the background, times the intensity of a
// uniform environment. A map environment is drawn over it by the backdrop pass.
std::array<float, 4> clearColour(const Scene& scene) {
    const glm::vec3 c = scene.environment ? scene.background * scene.environment->intensity : scene.background;
    return {c.r, c.g, c.b, 1.0f};
}

// Everything an environment cube's pixels depend on except the camera: the frame's shading flags, ambient
// and lights, the background, and every object's geometry and material.
std::vector<float> environmentKey(const Scene& scene, const FrameBlock& frame) {
    std::vector<float> key;
    auto push = [&key](const glm::vec3& v) { key.insert(key.end(), {v.x, v.y, v.z}); };
    auto material = [&](const Material& m) {
        push(m.ma);
        push(m.md);
        push(m.ms);
        push(m.kr);
        key.push_back(m.s);
        push(m.baseColor);
        key.insert(key.end(), {m.metallic, m.roughness});
    };
    key.insert(key.end(), {float(frame.flags.x), float(frame.flags.y), float(frame.flags.z), float(frame.flags.w)});
    push(scene.ambient);
    push(scene.background);
    key.push_back(scene.normalized ? 1.0f : 0.0f);
    key.insert(key.end(), {frame.iblParams.x, frame.iblParams.y, frame.iblParams.z, float(frame.iblInfo.x),
                           float(frame.iblInfo.y), float(frame.iblInfo.w), frame.iblRadiance.x, frame.iblRadiance.y,
                           frame.iblRadiance.z, frame.iblSH[0].x});
    for (int i = 0; i < frame.flags.z; ++i)
        for (const glm::vec4& v : {frame.lightPos[i], frame.lightColor[i], frame.lightAtten[i]})
            key.insert(key.end(), {v.x, v.y, v.z, v.w});
    for (const Sphere& sp : scene.spheres) {
        push(sp.center);
        key.push_back(sp.radius);
        material(sp.material);
    }
    for (const Plane& p : scene.planes) {
        push(p.normal);
        key.push_back(p.offset);
        material(p.material);
        const Checker c = p.checker.value_or(Checker{glm::vec3(-1.0f), -1.0f});
        push(c.md2);
        key.push_back(c.size);
    }
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& part : m.parts) material(part.material);
    return key;
}

}  // namespace

RasterRenderer::RasterRenderer(const gl::ShaderLibrary& shaders) : shaders_(shaders), shadows_(shaders) {
    // Compile errors surface here, not at a later draw: every variant is the same source with different
    // constants, so these two (without shadows; with every optional block) check all of it. llvmpipe
    // generates code lazily at the first draw, so variants a scene never uses cost little.
    ShaderVariant local;
    ShaderVariant full;
    full.shadows = full.pcf = full.moreLights = true;
    full.lights = 3;
    full.shadowKind = {kShadowOrtho, kShadowPerspective, kShadowCube};
    full.planes = 1;
    full.planeMask = {1, 1, 1};
    programsFor(local);
    programsFor(full);
    glUseProgram(0);
    // Environment cubes are sampled bilinearly across face edges (core profile leaves this off).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

    frameUbo_ = gl::Buffer::create();
    glBindBuffer(GL_UNIFORM_BUFFER, frameUbo_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameBlock), nullptr, GL_DYNAMIC_DRAW);

    const std::array<glm::vec3, 36> cube = unitCube();
    cubeVao_ = gl::VertexArray::create();
    cubeVbo_ = gl::Buffer::create();
    glBindVertexArray(cubeVao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, cubeVbo_.id());
    glBufferData(GL_ARRAY_BUFFER, sizeof(cube), cube.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    emptyVao_ = gl::VertexArray::create();
    glBindVertexArray(0);
    gl::checkError("RasterRenderer setup");
}

void RasterRenderer::uploadMeshes(const Scene& scene) {
    ranges_.clear();
    ++meshGeneration_;
    size_t vertexCount = 0, indexCount = 0;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& p : m.parts) {
            vertexCount += p.geometry->positions.size();
            indexCount += p.geometry->indices.size();
        }
    if (!meshVao_) {
        meshVao_ = gl::VertexArray::create();
        meshVbo_ = gl::Buffer::create();
        meshIbo_ = gl::Buffer::create();
    }
    glBindVertexArray(meshVao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, meshVbo_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, meshIbo_.id());
    if (vertexCount == 0) {
        glBindVertexArray(0);
        return;
    }
    // Positions, normals, TEXCOORD_0, TEXCOORD_1 and tangents (five planar arrays; zeros for parts without
    // texture coordinates or tangents), and one index buffer rebased per part.
    const size_t uvOffset = vertexCount * 2 * sizeof(glm::vec3);
    const size_t uv1Offset = uvOffset + vertexCount * sizeof(glm::vec2);
    const size_t tangentOffset = uv1Offset + vertexCount * sizeof(glm::vec2);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(tangentOffset + vertexCount * sizeof(glm::vec4)), nullptr, GL_STATIC_DRAW);
    std::vector<glm::vec2> zeros;
    std::vector<glm::vec4> zeros4;
    std::set<const Texture*> textures;
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indexCount * sizeof(uint32_t)), nullptr, GL_STATIC_DRAW);
    size_t vBase = 0, iBase = 0;
    std::vector<uint32_t> rebased;
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const Mesh& m = scene.meshes[mi];
        for (size_t pi = 0; pi < m.parts.size(); ++pi) {
            const MeshGeometry& g = *m.parts[pi].geometry;
            const size_t n = g.positions.size();
            size_t bytes = n * sizeof(glm::vec3);
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr(vBase * sizeof(glm::vec3)), GLsizeiptr(bytes),
                            g.positions.data());
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr((vertexCount + vBase) * sizeof(glm::vec3)), GLsizeiptr(bytes),
                            g.normals.data());
            auto uvs = [&](const std::vector<glm::vec2>& uv, size_t offset) {
                const bool has = uv.size() == n;
                if (!has) zeros.assign(n, glm::vec2(0.0f));
                glBufferSubData(GL_ARRAY_BUFFER, GLintptr(offset + vBase * sizeof(glm::vec2)),
                                GLsizeiptr(n * sizeof(glm::vec2)), has ? uv.data() : zeros.data());
            };
            uvs(g.texcoords0, uvOffset);
            uvs(g.texcoords1, uv1Offset);
            const bool hasTangents = g.tangents.size() == n;
            if (!hasTangents) zeros4.assign(n, glm::vec4(0.0f));
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr(tangentOffset + vBase * sizeof(glm::vec4)),
                            GLsizeiptr(n * sizeof(glm::vec4)), hasTangents ? g.tangents.data() : zeros4.data());
            const Material& mat = m.parts[pi].material;
            for (const TextureBinding* b : {&mat.baseColorTexture, &mat.metallicRoughnessTexture, &mat.normalTexture,
                                            &mat.occlusionTexture, &mat.emissiveTexture})
                if (b->texture) textures.insert(b->texture.get());
            rebased.resize(g.indices.size());
            for (size_t k = 0; k < g.indices.size(); ++k) rebased[k] = g.indices[k] + uint32_t(vBase);
            glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, GLintptr(iBase * sizeof(uint32_t)),
                            GLsizeiptr(rebased.size() * sizeof(uint32_t)), rebased.data());
            ranges_.push_back({mi, pi, iBase, g.indices.size(), g.bounds.lo, g.bounds.hi});
            vBase += g.positions.size();
            iBase += g.indices.size();
        }
    }
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3),
                          reinterpret_cast<const void*>(vertexCount * sizeof(glm::vec3)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), reinterpret_cast<const void*>(uvOffset));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), reinterpret_cast<const void*>(uv1Offset));
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), reinterpret_cast<const void*>(tangentOffset));
    glBindVertexArray(0);
    textures_.prune(textures);
    gl::checkError("RasterRenderer::uploadMeshes");
}

void RasterRenderer::uploadFrame(const FrameBlock& frame) const {
    glBindBuffer(GL_UNIFORM_BUFFER, frameUbo_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameBlock), &frame);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frameUbo_.id());
}

// Shadow maps depend on lights, casters and settings only, not on the camera or the band: re-render them
// when that key changes, so a banded image renders them once and a material edit or an orbit not at all.
void RasterRenderer::prepareShadows(const Scene& scene, int width, int height) {
    RasterSettings settings = scene.raster;
    settings.shadowMapSize = shadowMapSizeFor(scene.raster, width, height);
    std::vector<float> key = {float(settings.shadowMapSize), settings.depthBias,     settings.normalBias,
                              float(settings.pcf),           float(meshGeneration_), float(scene.meshes.size())};
    auto push = [&key](const glm::vec3& v) { key.insert(key.end(), {v.x, v.y, v.z}); };
    for (const Light& l : scene.lights) {
        key.push_back(float(l.type));
        push(l.position);
        push(l.direction);
    }
    for (const Sphere& sp : scene.spheres) {
        push(sp.center);
        key.push_back(sp.radius);
    }
    for (const Plane& p : scene.planes) {
        push(p.normal);
        key.push_back(p.offset);
    }
    if (key != shadowKey_) {
        shadows_.render(scene, settings, ranges_, meshVao_ ? meshVao_.id() : emptyVao_.id(), cubeVao_.id());
        shadowKey_ = std::move(key);
    }
    // Scaled by the box of casters and eye, so it follows the camera (a uniform, not a new map).
    shadows_.setEpsilon(secondaryRayEpsilon(scene, scene.camera.position));
}

// Reflective spheres and mesh parts (kr > 0, reflections on): one environment cube each, rendered from its
// centre with the image's programs, re-rendered only when something but the camera changes.
void RasterRenderer::prepareEnvironments(const Scene& scene, const FrameBlock& frame, const ColorPrograms& programs) {
    probes_.clear();
    if (!(frame.flags.w & kPassMirrors)) return;
    const auto reflective = [](const Material& m) { return m.kr.x > 0.0f || m.kr.y > 0.0f || m.kr.z > 0.0f; };
    for (size_t i = 0; i < scene.spheres.size() && probes_.size() < size_t(kMaxEnvironmentCubes); ++i) {
        const Sphere& s = scene.spheres[i];
        if (reflective(s.material)) probes_.push_back({int(i), -1, s.center, 0.5f * s.radius});
    }
    for (size_t k = 0; k < ranges_.size() && probes_.size() < size_t(kMaxEnvironmentCubes); ++k) {
        const DrawRange& r = ranges_[k];
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        if (!reflective(scene.meshes[r.mesh].parts[r.part].material)) continue;
        probes_.push_back({-1, int(k), 0.5f * (r.lo + r.hi), std::max(1e-3f * glm::length(r.hi - r.lo), 1e-5f)});
    }
    if (probes_.empty()) return;

    const int size = std::clamp(scene.raster.reflectionCubeSize, kMinReflectionCubeSize, kMaxReflectionCubeSize);
    std::vector<float> key = environmentKey(scene, frame);
    key.insert(key.end(), shadowKey_.begin(), shadowKey_.end());
    key.insert(key.end(), {float(size), float(meshGeneration_), float(probes_.size()), float(ibl_.generation())});
    if (key == environmentKey_) return;

    environments_.resize(int(probes_.size()), size);
    const std::array<float, 4> background = clearColour(scene);
    const float farDepth = 1.0f;
    for (size_t cube = 0; cube < probes_.size(); ++cube) {
        const EnvironmentProbe& probe = probes_[cube];
        // The faces' shadow rays start at the cube's centre, not the camera: ε from there keeps the cubes
        // independent of the camera they were first rendered for.
        shadows_.setEpsilon(secondaryRayEpsilon(scene, probe.centre));
        for (int face = 0; face < 6; ++face) {
            environments_.bindFace(int(cube), face);
            glClearBufferfv(GL_COLOR, 0, background.data());
            glClearBufferfv(GL_DEPTH, 0, &farDepth);
            const FrameBlock faceFrame = cubeFaceFrame(frame, probe.centre, probe.zNear, face, size);
            uploadFrame(faceFrame);
            drawBackdrop(faceFrame);
            drawPasses(scene, faceFrame, programs, PassOptions{-1, probe.sphere, probe.range, false, false});
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    shadows_.setEpsilon(secondaryRayEpsilon(scene, scene.camera.position));
    environmentKey_ = std::move(key);
}

void RasterRenderer::draw(const Scene& scene, int width, int height, bool withCoverage, Band band, glm::vec2 jitter) {
    if (band.rows <= 0) band = Band{0, height};
    const ViewSetup view = makeViewSetup(scene, width, height);
    const FrameBlock frame = makeFrameBlock(scene, view, band, jitter);
    if (frame.flags.w & kPassShadows) prepareShadows(scene, width, height);
    shadows_.bind(kShadowBinding, kShadowUnit);  // always bound: the programs declare the block
    int maps = 0;  // mesh.frag's SL_MATERIAL_MAPS: bit k for map k some part has (emissive 32), 16 for alpha
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& p : m.parts) {
            const Material& mat = p.material;
            maps |= (mat.baseColorTexture ? 1 : 0) | (mat.metallicRoughnessTexture ? 2 : 0) |
                    (mat.normalTexture ? 4 : 0) | (mat.occlusionTexture ? 8 : 0) |
                    (mat.alphaMode != AlphaMode::Opaque ? 16 : 0) | (mat.emissiveTexture ? 32 : 0);
        }
    const ColorPrograms& programs = programsFor(makeShaderVariant(frame, &shadows_.block()), maps);

    // Every pass sets the state it needs (style.md "GL resources").
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // impostors far away may round to depth 1.0, the clear value
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const std::array<float, 4> backgroundColour = clearColour(scene);
    const float* background = backgroundColour.data();
    const GLuint noObject[4] = {kBackgroundId, 0, 0, 0};
    const float farDepth = 1.0f;
    const bool pbr = frame.flags.x == shading::SL_MODEL_PBR;
    ibl_.prepare(scene.environment ? scene.environment->map : nullptr,
                 pbr && (frame.iblInfo.x != kIblNone || frame.iblInfo.w != 0));
    ibl_.bind(kIblCubeUnit, kIblDfgUnit);
    if (frame.iblInfo.x == kIblMap && !backdrop_) {
        // Compiled on first use: scenes without an environment map never pay for it.
        backdrop_ =
            gl::Program::build(shaders_, "fullscreen.vert", "environment_backdrop.frag", ShaderVariant().defines());
        backdrop_.bindBlock("Frame", kFrameBinding);
        glUseProgram(backdrop_.id());
        glUniform1i(backdrop_.uniform("t_iblCube"), GLint(kIblCubeUnit));
        glUseProgram(0);
    }

    prepareEnvironments(scene, frame, programs);

    // Mirror passes first, each into its own float target of the band's size (one bounce, local shading).
    mirrorOfPlane_.assign(scene.planes.size(), -1);
    glActiveTexture(GL_TEXTURE0 + kReflectionUnit);
    glBindTexture(GL_TEXTURE_2D, 0);  // no feedback loop with a mirror target being drawn
    glActiveTexture(GL_TEXTURE0);
    size_t mirrors = 0;
    for (size_t i = 0; i < scene.planes.size() && mirrors < size_t(kMaxMirrorPlanes); ++i) {
        if (!isMirror(scene, scene.planes[i])) continue;
        const std::optional<FrameBlock> mirrored = mirroredFrame(frame, scene.planes[i]);
        if (!mirrored) continue;
        if (mirrorTargets_.size() <= mirrors) mirrorTargets_.emplace_back();
        RenderTarget& t = mirrorTargets_[mirrors];
        t.resize(width, band.rows, false);
        t.bind();
        glClearBufferfv(GL_COLOR, 0, background);
        glClearBufferfv(GL_DEPTH, 0, &farDepth);
        uploadFrame(*mirrored);
        drawBackdrop(*mirrored);
        glEnable(GL_CLIP_DISTANCE0);
        drawPasses(scene, *mirrored, programs, PassOptions{int(i), -1, -1, true, false});
        glDisable(GL_CLIP_DISTANCE0);
        mirrorOfPlane_[i] = int(mirrors++);
    }

    target_.resize(width, band.rows, withCoverage);
    target_.bind();
    glClearBufferfv(GL_COLOR, 0, background);
    if (target_.hasCoverage()) glClearBufferuiv(GL_COLOR, 1, noObject);
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    uploadFrame(frame);
    drawBackdrop(frame);
    drawPasses(scene, frame, programs, PassOptions{});
    gl::checkError("RasterRenderer::draw");
}

// An environment map seen where no object is: each pixel's ray (of the uploaded frame: the image's, a
// mirror's or a cube face's) reads the map's level 0, as the tracer's escaping rays do. Depth untouched.
void RasterRenderer::drawBackdrop(const FrameBlock& frame) const {
    if (frame.iblInfo.x != kIblMap) return;
    glUseProgram(backdrop_.id());
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glBindVertexArray(emptyVao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(0);
}

int bandCount(int width, int height, size_t maxTargetBytes) {
    const size_t bytes = size_t(width) * size_t(height) * 4 * sizeof(float);
    return int(std::min<size_t>(size_t(height), std::max<size_t>(1, (bytes + maxTargetBytes - 1) / maxTargetBytes)));
}

RasterOutput renderRaster(RasterRenderer& r, const Scene& scene, int width, int height, bool withCoverage) {
    r.draw(scene, width, height, withCoverage);
    RasterOutput out;
    r.target().readColor(out.color);
    if (withCoverage) r.target().readCoverage(out.coverage);
    return out;
}

}  // namespace shadelab::raster
