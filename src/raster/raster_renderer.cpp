// RasterRenderer: set-up, the shadow maps and environment cubes a frame needs, and the order of a render: the
// uploads (raster_uploads.cpp), then the three colour passes (meshes, spheres, planes; raster_passes.cpp), run
// once per mirror plane into its own target (planar_reflection.h) and then for the image itself.
#include "raster/raster_renderer.h"

#include "raster/frame_block.h"
#include "raster/planar_reflection.h"
#include "scene/coverage.h"
#include "scene/ray_epsilon.h"
#include "scene/scene_models.h"
#include "scene/view.h"
#include "shading/lighting.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
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

// What rays that leave the scene see where nothing is drawn: the background, times the intensity of a
// uniform environment. A map environment is drawn over it by the backdrop pass.
std::array<float, 4> clearColour(const Scene& scene) {
    const glm::vec3 c = scene.environment ? scene.background * scene.environment->intensity : scene.background;
    return {c.r, c.g, c.b, 1.0f};
}

// Everything an environment cube's pixels depend on except the camera and the materials (which the caller
// keys per object): the frame's shading flags, ambient and lights, the background, and the objects' geometry.
KeyBytes environmentSharedKey(const Scene& scene, const FrameBlock& frame) {
    KeyBytes key;
    key.add(frame.flags).add(scene.ambient).add(scene.background).add(scene.normalized);
    key.add(frame.iblParams).add(frame.iblInfo).add(frame.iblRadiance).add(frame.iblSH);
    for (int i = 0; i < frame.flags.z; ++i)
        key.add(frame.lightPos[i])
            .add(frame.lightColor[i])
            .add(frame.lightAtten[i])
            .add(frame.lightSpot[i])
            .add(frame.lightCone[i]);
    for (const Sphere& sp : scene.spheres) key.add(sp.center).add(sp.radius);
    for (const Plane& p : scene.planes) key.add(p.normal).add(p.offset);
    return key;
}

}  // namespace

RasterRenderer::RasterRenderer(const gl::ShaderLibrary& shaders, ProgramCheck check)
    : shaders_(shaders.withDialect(gl::currentContextDialect())),
      programs_(shaders_),
      shadows_(shaders_, check == ProgramCheck::AtStart),
      partial_(shaders_) {
    if (check == ProgramCheck::AtStart) {
        // Compile errors surface here, not at a later draw: every variant is the same source with different
        // constants, so these two (without shadows; with every optional block) check all of it. llvmpipe
        // generates code lazily at the first draw, but keeps each linked program's IR.
        ShaderVariant local;
        ShaderVariant full;
        full.shadows = full.pcf = full.moreLights = true;
        full.lights = 3;
        full.shadowKind = {kShadowOrtho, kShadowPerspective, kShadowCube};
        full.planes = 1;
        full.planeMask = {1, 1, 1};
        for (const ShaderVariant* v : {&local, &full}) {
            const ColorPrograms& set = programs_.get(*v);
            for (int k = 0; k < ColorPrograms::kKinds; ++k) set.get(ColorPrograms::Kind(k));
        }
        glUseProgram(0);
    }
    // Environment cubes are sampled bilinearly across face edges: desktop core profiles leave this off, ES 3.0
    // and WebGL2 always filter across edges and have no such switch.
    if (shaders_.dialect() == gl::ShaderDialect::Glsl330) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

    frameUbo_ = gl::Buffer::create();
    glBindBuffer(GL_UNIFORM_BUFFER, frameUbo_.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameBlock), nullptr, GL_DYNAMIC_DRAW);

    const std::array<glm::vec3, 36> cube = unitCube();
    geometry_.cubeVao = gl::VertexArray::create();
    geometry_.cubeVbo = gl::Buffer::create();
    glBindVertexArray(geometry_.cubeVao.id());
    glBindBuffer(GL_ARRAY_BUFFER, geometry_.cubeVbo.id());
    glBufferData(GL_ARRAY_BUFFER, sizeof(cube), cube.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    geometry_.planeVao = gl::VertexArray::create();
    geometry_.planeVbo = gl::Buffer::create();
    glBindVertexArray(geometry_.planeVao.id());
    glBindBuffer(GL_ARRAY_BUFFER, geometry_.planeVbo.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), nullptr);
    geometry_.emptyVao = gl::VertexArray::create();
    glBindVertexArray(0);
    gl::checkError("RasterRenderer setup");
}

// Shadow maps depend on lights, casters and settings only, not on the camera or the band: re-render them
// when that key changes, so a banded image renders them once and a material edit or an orbit not at all.
void RasterRenderer::prepareShadows(const Scene& scene, int width, int height) {
    RasterSettings settings = scene.raster;
    settings.shadowMapSize = shadowMapSizeFor(scene.raster, width, height);
    std::vector<float> key = {float(settings.shadowMapSize), settings.depthBias,          settings.normalBias,
                              float(settings.pcf),           float(geometry_.generation), float(scene.meshes.size())};
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
        shadows_.render(scene, settings, geometry_.ranges,
                        geometry_.meshVao ? geometry_.meshVao.id() : geometry_.emptyVao.id(), geometry_.cubeVao.id(),
                        batchTriangles_);
        shadowKey_ = std::move(key);
        report_.shadowMaps = true;
    }
    // Scaled by the box of casters and eye, so it follows the camera (a uniform, not a new map).
    shadows_.setEpsilon(secondaryRayEpsilon(scene, scene.camera.position));
}

// Reflective spheres and mesh parts (kr > 0, reflections on), and in an environment those glTF's transmission lets
// the light through under pbr: one environment cube each, rendered from its centre with the image's programs,
// re-rendered only when something but the camera changes.
void RasterRenderer::prepareEnvironments(const Scene& scene, const FrameBlock& frame) {
    probes_.clear();
    if (!(frame.flags.w & kPassMirrors)) return;
    const bool lit = scene.environment.has_value();  // the light through reads a cube only in an environment
    const auto reflective = [&](const Material& m) {
        return m.kr.x > 0.0f || m.kr.y > 0.0f || m.kr.z > 0.0f ||
               (lit && m.transmission.on() && modelOf(m, scene.model) == ShadingModel::Pbr);
    };
    for (size_t i = 0; i < scene.spheres.size() && probes_.size() < size_t(kMaxEnvironmentCubes); ++i) {
        const Sphere& s = scene.spheres[i];
        if (reflective(s.material)) probes_.push_back({int(i), -1, s.center, 0.5f * s.radius});
    }
    for (size_t k = 0; k < geometry_.ranges.size() && probes_.size() < size_t(kMaxEnvironmentCubes); ++k) {
        const DrawRange& r = geometry_.ranges[k];
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        if (!reflective(scene.meshes[r.mesh].parts[r.part].material)) continue;
        probes_.push_back({-1, int(k), 0.5f * (r.lo + r.hi), std::max(1e-3f * glm::length(r.hi - r.lo), 1e-5f)});
    }
    if (probes_.empty()) return;

    const int size = std::clamp(scene.raster.reflectionCubeSize, kMinReflectionCubeSize, kMaxReflectionCubeSize);
    DrawKey key = drawKey(scene);  // for its objects' ids and materials
    key.shared = environmentSharedKey(scene, frame);
    for (float v : shadowKey_) key.shared.add(v);
    key.shared.add(size).add(geometry_.generation).add(ibl_.generation()).add(probes_.size());
    for (const EnvironmentProbe& probe : probes_) key.shared.add(probe.sphere).add(probe.range);
    // When only materials changed, a face is re-rendered only inside the rectangle where a changed object
    // can appear (every object drawn there again): no other pixel of it can change (one bounce, no mirrors).
    const RedrawPlan plan = planRedraw(environmentKey_ ? &*environmentKey_ : nullptr, key, kMaxPartialIds);
    if (!plan.full && plan.ids.empty()) return;
    const auto listed = [&plan](uint32_t id) {
        return plan.full || std::find(plan.ids.begin(), plan.ids.end(), id) != plan.ids.end();
    };

    environments_.resize(int(probes_.size()), size);
    const std::array<float, 4> background = clearColour(scene);
    const float farDepth = 1.0f;
    for (size_t cube = 0; cube < probes_.size(); ++cube) {
        const EnvironmentProbe& probe = probes_[cube];
        // The faces' shadow rays start at the cube's centre, not the camera: ε from there keeps the cubes
        // independent of the camera they were first rendered for.
        shadows_.setEpsilon(secondaryRayEpsilon(scene, probe.centre));
        for (int face = 0; face < 6; ++face) {
            const FrameBlock faceFrame = cubeFaceFrame(frame, probe.centre, probe.zNear, face, size);
            PixelRect rect{0, 0, size, size};
            if (!plan.full) {
                rect = PixelRect{};
                for (size_t k = 0; k < geometry_.ranges.size(); ++k)
                    if (int(k) != probe.range && geometry_.ranges[k].mesh < scene.meshes.size() &&
                        listed(meshCoverageId(scene, geometry_.ranges[k].mesh)))
                        rect = unite(rect, boxPixelRect(faceFrame.viewProj, geometry_.ranges[k].lo,
                                                        geometry_.ranges[k].hi, size, size));
                for (size_t i = 0; i < scene.spheres.size(); ++i)
                    if (int(i) != probe.sphere && listed(sphereCoverageId(scene, i))) {
                        const Sphere& sp = scene.spheres[i];
                        rect = unite(rect, boxPixelRect(faceFrame.viewProj, sp.center - glm::vec3(sp.radius),
                                                        sp.center + glm::vec3(sp.radius), size, size));
                    }
                for (size_t i = 0; i < scene.planes.size(); ++i)
                    if (listed(planeCoverageId(scene, i))) rect = PixelRect{0, 0, size, size};
                if (rect.empty()) continue;
            }
            environments_.bindFace(int(cube), face);
            glEnable(GL_SCISSOR_TEST);
            glScissor(rect.x0, rect.y0, rect.x1 - rect.x0, rect.y1 - rect.y0);
            glClearBufferfv(GL_COLOR, 0, background.data());
            glClearBufferfv(GL_DEPTH, 0, &farDepth);
            uploadFrame(faceFrame);
            drawBackdrop(faceFrame);
            drawPasses(scene, faceFrame, PassOptions{-1, probe.sphere, probe.range, false, false});
            glDisable(GL_SCISSOR_TEST);
            report_.environments = true;
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    shadows_.setEpsilon(secondaryRayEpsilon(scene, scene.camera.position));
    environmentKey_ = std::move(key);
}

void RasterRenderer::draw(const Scene& scene, int width, int height, bool withCoverage, Band band, glm::vec2 jitter) {
    const bool whole = band.rows <= 0 || (band.top == 0 && band.rows == height);
    render(target_, scene, width, height, withCoverage, band, jitter,
           partial_.enabled() && whole && withCoverage && jitter == glm::vec2(0.0f));
}

const RenderTarget& RasterRenderer::drawSample(const Scene& scene, int width, int height, glm::vec2 jitter) {
    render(sampleTarget_, scene, width, height, false, Band{}, jitter, false);
    return sampleTarget_;
}

// `reusable`: the image may be the start of a partial redraw, or be one (target_ only).
void RasterRenderer::render(RenderTarget& out, const Scene& scene, int width, int height, bool withCoverage, Band band,
                            glm::vec2 jitter, bool reusable) {
    report_ = DrawReport{};
    if (band.rows <= 0) band = Band{0, height};
    const ViewSetup view = makeViewSetup(scene, width, height);
    const FrameBlock frame = makeFrameBlock(scene, view, band, jitter);
    if (frame.flags.w & kPassShadows) prepareShadows(scene, width, height);
    shadows_.bind(kShadowBinding, kShadowUnit);  // always bound: the programs declare the block
    const ShaderVariant variant = makeShaderVariant(frame, &shadows_.block());
    int maps = 0;  // every part's SL_MATERIAL_MAPS bits together (the partial-redraw key)
    programs_.prepare(frame, &shadows_.block(), scene, maps);

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
    const bool pbr = usesPhysicallyBased(scene);  // the scene's model, or any material's own
    ibl_.prepare(scene.environment ? scene.environment->map : nullptr,
                 pbr && (frame.iblInfo.x != kIblNone || frame.iblInfo.w != 0), usesSheen(scene));
    ibl_.bind(kIblCubeUnit, kIblDfgUnit, kSheenLutUnit);
    if (frame.iblInfo.x == kIblMap && !backdrop_) {
        // Compiled on first use: scenes without an environment map never pay for it.
        backdrop_ =
            gl::Program::build(shaders_, "fullscreen.vert", "environment_backdrop.frag", ShaderVariant().defines());
        backdrop_.bindBlock("Frame", kFrameBinding);
        glUseProgram(backdrop_.id());
        backdrop_.setSampler("t_iblCube", kIblCubeUnit);
        glUseProgram(0);
    }

    prepareEnvironments(scene, frame);

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
        t.resize(width, band.rows, false, false);  // plane.frag reads its colour only
        t.bind();
        glClearBufferfv(GL_COLOR, 0, background);
        glClearBufferfv(GL_DEPTH, 0, &farDepth);
        uploadFrame(*mirrored);
        drawBackdrop(*mirrored);
        // Meshes are clipped at the mirror plane by gl_ClipDistance where the dialect has it, else by a discard
        // in mesh.frag (SL_CLIP_DISTANCE); impostors test their own hit.
        const bool clipDistance = shaders_.dialect() == gl::ShaderDialect::Glsl330;
        if (clipDistance) glEnable(GL_CLIP_DISTANCE0);
        drawPasses(scene, *mirrored, PassOptions{int(i), -1, -1, true, false});
        if (clipDistance) glDisable(GL_CLIP_DISTANCE0);
        mirrorOfPlane_[i] = int(mirrors++);
    }

    std::optional<DrawKey> key;
    if (&out == &target_) {
        if (band.top == 0 && band.rows == height)
            targetViewProj_ = frame.viewProj;
        else
            targetViewProj_.reset();
        if (reusable && mirrors == 0) {
            // Everything the colour pass reads besides the materials (redraw_plan.h): the scene's part, and
            // what this renderer derives from it or holds.
            key = drawKey(scene);
            key->shared.add(frame)
                .addString(variant.defines())
                .add(maps)
                .add(geometry_.generation)
                .add(ibl_.generation());
            key->shared.add(width).add(height).add(shadowKey_.size());
            for (float v : shadowKey_) key->shared.add(v);
            RedrawPlan plan = planRedraw(partial_.last(), *key, kMaxPartialIds);
            // A re-rendered environment cube changes the pixels of the object that looks it up.
            for (size_t cube = 0; cube < probes_.size() && !plan.full && report_.environments; ++cube) {
                const EnvironmentProbe& probe = probes_[cube];
                addToPlan(plan,
                          probe.sphere >= 0 ? sphereCoverageId(scene, size_t(probe.sphere))
                                            : meshCoverageId(scene, geometry_.ranges[size_t(probe.range)].mesh),
                          kMaxPartialIds);
            }
            if (!plan.full && target_.width() == width && target_.height() == height && target_.hasCoverage()) {
                if (!plan.ids.empty()) redrawPart(scene, frame, plan.ids);
                report_.partial = true;
                report_.partialIds = int(plan.ids.size());
                partial_.remember(std::move(*key));
                gl::checkError("RasterRenderer::draw (partial)");
                return;
            }
        }
        partial_.forget();
    }

    out.resize(width, band.rows, withCoverage, &out == &target_ ? targetAlpha_ : true);
    out.bind();
    glClearBufferfv(GL_COLOR, 0, background);
    if (out.hasCoverage()) glClearBufferuiv(GL_COLOR, 1, noObject);
    glClearBufferfv(GL_DEPTH, 0, &farDepth);
    uploadFrame(frame);
    drawBackdrop(frame);
    drawPasses(scene, frame, PassOptions{});
    if (key) partial_.remember(std::move(*key));
    gl::checkError("RasterRenderer::draw");
}

PixelRect RasterRenderer::objectRect(const Scene& scene, uint32_t id) const {
    if (!targetViewProj_) return PixelRect{0, 0, target_.width(), target_.height()};
    return PartialRedraw::objectsRect(scene, geometry_.ranges, *targetViewProj_, {id}, target_.width(),
                                      target_.height());
}

// The partial redraw (partial_redraw.h): the listed objects drawn again over a copy of the image's depth, only
// where their bounds can reach, then merged into the image.
void RasterRenderer::redrawPart(const Scene& scene, const FrameBlock& frame, const std::vector<uint32_t>& ids) {
    const PixelRect rect =
        PartialRedraw::objectsRect(scene, geometry_.ranges, frame.viewProj, ids, target_.width(), target_.height());
    if (rect.empty()) return;
    partial_.begin(target_, rect);
    uploadFrame(frame);
    PassOptions options;
    options.only = &ids;
    drawPasses(scene, frame, options);
    partial_.merge(target_, ids);
}

// An environment map seen where no object is: each pixel's ray (of the uploaded frame: the image's, a
// mirror's or a cube face's) reads the map's level 0, as the tracer's escaping rays do. Depth untouched.
void RasterRenderer::drawBackdrop(const FrameBlock& frame) const {
    if (frame.iblInfo.x != kIblMap) return;
    glUseProgram(backdrop_.id());
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glBindVertexArray(geometry_.emptyVao.id());
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
