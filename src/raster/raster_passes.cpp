// RasterRenderer's colour passes (meshes, sphere impostors, planes) with one frame block: run once per
// mirror plane into its target and once for the image. Not the set-up, the uploads or the shadow maps.
#include "raster/raster_renderer.h"

#include "raster/frame_block.h"
#include "raster/plane_footprint.h"
#include "scene/coverage.h"
#include "shading/local_illumination.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace shadelab::raster {
namespace {

// texture_sample.glsl's wrap-mode numbers.
int wrapIndex(TextureWrap w) {
    switch (w) {
        case TextureWrap::MirroredRepeat: return 1;
        case TextureWrap::ClampToEdge: return 2;
        case TextureWrap::Repeat: break;
    }
    return 0;
}

}  // namespace

void RasterRenderer::setMaterial(const gl::Program& p, const Material& m, uint32_t objectId, int model,
                                 bool normalized) const {
    // The coefficients shadeLight reads under this model, derived on the CPU exactly as the tracer does.
    const shading::SurfaceParams c =
        shading::surfaceParams(model, m.ma, m.md, m.ms, m.s, m.baseColor, m.metallic, m.roughness, normalized,
                               m.disney.lobes0(), m.disney.lobes1());
    p.set("u_ma", c.ma);
    p.set("u_md", c.md);
    p.set("u_ms", c.ms);
    p.set("u_s", c.s);
    p.set("u_baseColor", m.baseColor);  // pbr's unlit colour, and mesh.frag's metallic-roughness map
    p.set("u_emission", m.emission);
    p.set("u_metallic", m.metallic);  // disney's (shadeLightDisney), with its own parameters
    p.set("u_disney0", c.disney0);
    p.set("u_disney1", c.disney1);
    p.set("u_coat", m.clearcoat.packed());           // pbr's clear coat, in the programs that have one (SL_CLEARCOAT)
    p.set("u_specLayer", m.specular.packed(m.ior));  // glTF's specular layer and ior (SL_SPECULAR_LAYER)
    p.set("u_sheen", m.sheen.packed());              // glTF's sheen (SL_SHEEN)
    p.set("u_aniso", m.anisotropy.packed());         // glTF's anisotropy (SL_SPECULAR_LAYER)
    p.set("u_transmission", transmissionPacked(m));  // glTF's transmission and volume (SL_SPECULAR_LAYER)
    p.set("u_transmitTint", transmissionTint(m));
    p.set("u_objectId", objectId);
    p.set("u_kr", m.kr);  // planes' mirrors and objects' cubes
    // Base-colour texture (mesh.frag): F0 = u_ms + u_msTex·(tex − 1) under pbr, as the tracer's local().
    const glm::vec3 msTex = shading::physicallyBased(model) ? m.metallic * m.baseColor : glm::vec3(0.0f);
    p.set("u_msTex", msTex);
    // The material maps (mesh.frag's u_tex arrays; spheres and planes have none of these uniforms).
    if (p.uniform("u_tex") < 0) return;
    constexpr int kMaps = 8;
    const TextureBinding* maps[kMaps] = {&m.baseColorTexture,          &m.metallicRoughnessTexture, &m.normalTexture,
                                         &m.occlusionTexture,          &m.emissiveTexture,          &m.clearcoatTexture,
                                         &m.clearcoatRoughnessTexture, &m.clearcoatNormalTexture};
    const GLuint units[kMaps] = {kBaseColorUnit, kMetalRoughUnit, kNormalMapUnit,          kOcclusionUnit,
                                 kEmissiveUnit,  kClearcoatUnit,  kClearcoatRoughnessUnit, kClearcoatNormalUnit};
    glm::ivec4 info[kMaps];
    glm::vec4 matrix[kMaps], offset[kMaps];
    for (int k = 0; k < kMaps; ++k) {
        const TextureBinding& t = *maps[k];
        info[k] = glm::ivec4(0);
        matrix[k] = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
        offset[k] = glm::vec4(0.0f);
        if (!t || t.texture->levels.empty()) continue;
        info[k] = glm::ivec4(int(t.texture->levels.size()), wrapIndex(t.sampler.wrapS), wrapIndex(t.sampler.wrapT),
                             (t.sampler.magLinear ? 1 : 0) | (t.sampler.minLinear ? 2 : 0) |
                                 (t.sampler.mipmaps ? 4 : 0) | (t.sampler.mipLinear ? 8 : 0));
        matrix[k] = t.uvMatrix();
        offset[k] = glm::vec4(t.offset, t.texCoord == 1 ? 1.0f : 0.0f, t.strength);
        glActiveTexture(GL_TEXTURE0 + units[k]);
        glBindTexture(GL_TEXTURE_2D, textures_.texture(t.texture));
    }
    glActiveTexture(GL_TEXTURE0);
    p.set("u_tex", info, kMaps, gl::Program::Uniform::Required);
    p.set("u_texMatrix", matrix, kMaps);
    p.set("u_texOffset", offset, kMaps);
    const glm::vec4 factors(m.metallic, m.roughness, normalized ? 1.0f : 0.0f, 0.0f);
    const glm::vec4 alpha(m.alpha, m.alphaCutoff, float(int(m.alphaMode)), 0.0f);
    p.set("u_mapFactors", factors);
    p.set("u_alpha", alpha);
}

// The program for one object: with its environment cube when it has one and this pass looks them up.
const gl::Program& RasterRenderer::objectProgram(const ColorPrograms& programs, int plainKind, int environmentKind,
                                                 int sphere, int range, const PassOptions& options) const {
    const gl::Program& plain = programs.get(ColorPrograms::Kind(plainKind));
    if (!options.reflections) {
        glUseProgram(plain.id());
        return plain;
    }
    for (size_t cube = 0; cube < probes_.size(); ++cube) {
        const EnvironmentProbe& probe = probes_[cube];
        if ((sphere >= 0 && probe.sphere == sphere) || (range >= 0 && probe.range == range)) {
            const gl::Program& environment = programs.get(ColorPrograms::Kind(environmentKind));
            glUseProgram(environment.id());
            glActiveTexture(GL_TEXTURE0 + kEnvironmentUnit);
            glBindTexture(GL_TEXTURE_CUBE_MAP, environments_.texture(int(cube)));
            glActiveTexture(GL_TEXTURE0);
            return environment;
        }
    }
    glUseProgram(plain.id());
    return plain;
}

void RasterRenderer::drawPasses(const Scene& scene, const FrameBlock& frame, const PassOptions& options) const {
    const auto skipped = [&options](uint32_t id) {
        return options.only && std::find(options.only->begin(), options.only->end(), id) == options.only->end();
    };
    // A mirror reverses winding: front faces (for culling and gl_FrontFacing) become clockwise.
    glFrontFace(options.mirrored ? GL_CW : GL_CCW);

    // Meshes first: they keep early depth testing, and the impostors behind them are rejected cheaply.
    std::vector<size_t> blended;  // alphaMode BLEND parts, drawn last
    glDisable(GL_CULL_FACE);      // two-sided lighting: back faces are lit with the flipped normal
    glBindVertexArray(geometry_.meshVao.id());
    TriangleBatches batches(batchTriangles_);
    for (size_t k = 0; k < geometry_.ranges.size(); ++k) {
        const DrawRange& r = geometry_.ranges[k];
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        if (int(k) == options.skipRange || skipped(meshCoverageId(scene, r.mesh)) ||
            outsideClip(frame.viewProj, r.lo, r.hi))
            continue;
        const Material& m = scene.meshes[r.mesh].parts[r.part].material;
        if (m.alphaMode == AlphaMode::Blend) {
            blended.push_back(k);
            continue;
        }
        drawRange(scene, options, k, batches);
    }

    // Spheres: back faces of the bounding cube cover the footprint from outside and inside.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glBindVertexArray(geometry_.cubeVao.id());
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        if (int(i) == options.skipSphere || skipped(sphereCoverageId(scene, i))) continue;
        const Sphere& s = scene.spheres[i];
        const gl::Program& p = objectProgram(programs_.of(s.material), ColorPrograms::Sphere,
                                             ColorPrograms::SphereEnvironment, int(i), -1, options);
        setMaterial(p, s.material, sphereCoverageId(scene, i), programs_.modelOf(s.material), scene.normalized);
        p.set("u_center", s.center, gl::Program::Uniform::Required);
        p.set("u_radius", s.radius, gl::Program::Uniform::Required);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    glDisable(GL_CULL_FACE);

    // Planes last, over the part of the viewport where rays can hit them and no sphere drawn above stands in
    // front (plane_footprint.h): plane.frag casts the ray and writes the exact hit's depth, as the spheres' shader
    // does, so its fragments are depth-tested only after they are shaded.
    glBindVertexArray(geometry_.planeVao.id());
    glBindBuffer(GL_ARRAY_BUFFER, geometry_.planeVbo.id());
    const glm::vec3 eye(frame.eye);
    GLint viewport[4] = {0, 0, 0, 0};
    if (!scene.planes.empty()) glGetIntegerv(GL_VIEWPORT, viewport);
    const PlaneCamera camera{
        eye, glm::vec3(frame.forward), glm::vec3(frame.right), glm::vec3(frame.up), frame.viewport, frame.viewProj};
    std::vector<FootprintHole> holes;
    for (size_t i = 0; i < scene.planes.size(); ++i) {
        if (int(i) == options.skipPlane || skipped(planeCoverageId(scene, i))) continue;  // a mirror: not itself
        const Plane& p = scene.planes[i];
        const PlaneFootprint footprint = planeFootprint(camera, viewport[2], viewport[3], p.normal, p.offset);
        if (footprint.count == 0) continue;  // every ray misses it
        // Spheres drawn above, whole: in a mirrored pass they are cut at the mirror, so none makes a hole there.
        holes.clear();
        for (size_t s = 0; s < scene.spheres.size() && !options.mirrored; ++s)
            if (int(s) != options.skipSphere && !skipped(sphereCoverageId(scene, s)))
                holes.push_back(sphereHole(camera, viewport[2], viewport[3], p.normal, p.offset,
                                           scene.spheres[s].center, scene.spheres[s].radius, footprint));
        const std::vector<glm::vec2> triangles = footprintTriangles(footprint, holes);
        if (triangles.empty()) continue;
        const int mirror = options.reflections && i < mirrorOfPlane_.size() ? mirrorOfPlane_[i] : -1;
        const gl::Program& planeProgram =
            programs_.of(p.material).get(mirror >= 0 ? ColorPrograms::PlaneMirror : ColorPrograms::Plane);
        const int model = programs_.modelOf(p.material);
        glUseProgram(planeProgram.id());
        if (mirror >= 0) {
            glActiveTexture(GL_TEXTURE0 + kReflectionUnit);
            glBindTexture(GL_TEXTURE_2D, mirrorTargets_[size_t(mirror)].colorTexture());
            glActiveTexture(GL_TEXTURE0);
        }
        setMaterial(planeProgram, p.material, planeCoverageId(scene, i), model, scene.normalized);
        const glm::vec3 t = shading::planeTangent(p.normal), b = shading::planeBitangent(p.normal);
        // The tangent basis picks the checker's tiles only: where the shaded colour does not depend on the tile
        // (a variant that ignores md and the base colour), the compiler removes both, so they are optional.
        planeProgram.set("u_planeT", t);
        planeProgram.set("u_planeB", b);
        planeProgram.set("u_planeNormal", p.normal, gl::Program::Uniform::Required);
        planeProgram.set("u_planeOffset", p.offset, gl::Program::Uniform::Required);
        planeProgram.set("u_checker", p.checker ? 1 : 0);
        const Checker c = p.checker.value_or(Checker{});
        // pbr: the second tiles' md2 is their base colour (F0 stays the plane's), as in the tracer.
        const glm::vec3 md2 =
            shading::physicallyBased(model) ? shading::pbrDiffuseColor(c.md2, p.material.metallic) : c.md2;
        planeProgram.set("u_md2", md2);
        planeProgram.set("u_baseColor2", c.md2);
        planeProgram.set("u_checkerSize", c.size);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles.size() * sizeof(glm::vec2)), triangles.data(),
                     GL_STREAM_DRAW);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles.size()));  // the footprint; plane.frag finds the hit
    }

    glBindBuffer(GL_ARRAY_BUFFER, 0);

    // alphaMode BLEND (docs/gltf-import.md): over everything opaque, farthest part first by its bounds'
    // centre, composited with the fragment's alpha and without depth writes; the coverage id is the part's.
    if (!blended.empty()) {
        std::stable_sort(blended.begin(), blended.end(), [&](size_t a, size_t b) {
            const glm::vec3 ca = 0.5f * (geometry_.ranges[a].lo + geometry_.ranges[a].hi),
                            cb = 0.5f * (geometry_.ranges[b].lo + geometry_.ranges[b].hi);
            return glm::dot(ca - eye, ca - eye) > glm::dot(cb - eye, cb - eye);
        });
        glBindVertexArray(geometry_.meshVao.id());
        glEnable(GL_BLEND);  // the coverage attachment is integer: blending leaves it alone
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        for (size_t k : blended) drawRange(scene, options, k, batches);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glFrontFace(GL_CCW);
    glBindVertexArray(0);
    glUseProgram(0);
}

void RasterRenderer::drawRange(const Scene& scene, const PassOptions& options, size_t k,
                               TriangleBatches& batches) const {
    const DrawRange& r = geometry_.ranges[k];
    const Material& m = scene.meshes[r.mesh].parts[r.part].material;
    const gl::Program& p = objectProgram(programs_.of(m, true), ColorPrograms::Mesh, ColorPrograms::MeshEnvironment, -1,
                                         int(k), options);  // prepared by render()
    setMaterial(p, m, meshCoverageId(scene, r.mesh), programs_.modelOf(m), scene.normalized);
    batches.draw(r.firstIndex, r.indexCount);
}

}  // namespace shadelab::raster
