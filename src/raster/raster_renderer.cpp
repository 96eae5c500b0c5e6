// RasterRenderer: uploads, per-frame uniform block, and the three passes (meshes, spheres, planes).
#include "raster/raster_renderer.h"

#include "raster/frame_block.h"
#include "scene/coverage.h"
#include "scene/view.h"
#include "shading/lighting.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>

namespace shadelab::raster {
namespace {

constexpr GLuint kFrameBinding = 0;

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

std::string programDefines() {
    return "#define SL_MAX_LIGHTS " + std::to_string(kMaxLights) + "\n";
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

// Conservative test: true when the box lies wholly outside one side of the clip volume (far is infinite).
bool outsideClip(const glm::mat4& viewProj, const glm::vec3& lo, const glm::vec3& hi) {
    int outside[5] = {0, 0, 0, 0, 0};
    for (int c = 0; c < 8; ++c) {
        glm::vec4 p = viewProj * glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f);
        outside[0] += p.x < -p.w;
        outside[1] += p.x > p.w;
        outside[2] += p.y < -p.w;
        outside[3] += p.y > p.w;
        outside[4] += p.z < -p.w;
    }
    for (int n : outside)
        if (n == 8) return true;
    return false;
}

FrameBlock makeFrameBlock(const Scene& scene, const ViewSetup& v, Band band) {
    FrameBlock f{};
    f.viewProj = bandMatrix(v.height, band) * v.viewProj;
    f.eye = glm::vec4(v.eye, 1.0f);
    f.forward = glm::vec4(v.forward, 0.0f);
    f.right = glm::vec4(v.right, 0.0f);
    f.up = glm::vec4(v.up, 0.0f);
    const float bandBottom = band.rows > 0 ? float(v.height - band.top - band.rows) : 0.0f;
    f.viewport = glm::vec4(float(v.width), float(v.height), v.tanHalfFovY, bandBottom);
    f.ambient = glm::vec4(scene.ambient, 0.0f);
    int terms = (scene.terms.ambient ? kTermAmbient : 0) | (scene.terms.diffuse ? kTermDiffuse : 0) |
                (scene.terms.specular ? kTermSpecular : 0);
    int model = scene.model == ShadingModel::Phong ? shading::SL_MODEL_PHONG : shading::SL_MODEL_BLINN_PHONG;
    int count = int(std::min(scene.lights.size(), size_t(kMaxLights)));
    f.flags = glm::ivec4(model, terms, count, 0);
    for (int i = 0; i < count; ++i) {
        const Light& l = scene.lights[size_t(i)];
        bool point = l.type == LightType::Point;
        f.lightPos[i] = glm::vec4(point ? l.position : l.direction, point ? 1.0f : 0.0f);
        f.lightColor[i] = glm::vec4(l.color, 0.0f);
        f.lightAtten[i] = glm::vec4(l.attenuation, 0.0f);
    }
    return f;
}

}  // namespace

RasterRenderer::RasterRenderer(const gl::ShaderLibrary& shaders) {
    const std::string defines = programDefines();
    meshProgram_ = gl::Program::build(shaders, "mesh.vert", "mesh.frag", defines);
    sphereProgram_ = gl::Program::build(shaders, "sphere.vert", "sphere.frag", defines);
    planeProgram_ = gl::Program::build(shaders, "plane.vert", "plane.frag", defines);
    for (const gl::Program* p : {&meshProgram_, &sphereProgram_, &planeProgram_}) p->bindBlock("Frame", kFrameBinding);

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
    size_t vertexCount = 0, indexCount = 0;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& p : m.parts) {
            vertexCount += p.positions.size();
            indexCount += p.indices.size();
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
    // Positions then normals (two planar arrays), and one index buffer rebased per part.
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertexCount * 2 * sizeof(glm::vec3)), nullptr, GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indexCount * sizeof(uint32_t)), nullptr, GL_STATIC_DRAW);
    size_t vBase = 0, iBase = 0;
    std::vector<uint32_t> rebased;
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const Mesh& m = scene.meshes[mi];
        for (size_t pi = 0; pi < m.parts.size(); ++pi) {
            const MeshPart& p = m.parts[pi];
            size_t bytes = p.positions.size() * sizeof(glm::vec3);
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr(vBase * sizeof(glm::vec3)), GLsizeiptr(bytes), p.positions.data());
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr((vertexCount + vBase) * sizeof(glm::vec3)), GLsizeiptr(bytes),
                            p.normals.data());
            rebased.resize(p.indices.size());
            for (size_t k = 0; k < p.indices.size(); ++k) rebased[k] = p.indices[k] + uint32_t(vBase);
            glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, GLintptr(iBase * sizeof(uint32_t)),
                            GLsizeiptr(rebased.size() * sizeof(uint32_t)), rebased.data());
            glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
            for (const glm::vec3& q : p.positions) {
                lo = glm::min(lo, q);
                hi = glm::max(hi, q);
            }
            ranges_.push_back({mi, pi, iBase, p.indices.size(), lo, hi});
            vBase += p.positions.size();
            iBase += p.indices.size();
        }
    }
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3),
                          reinterpret_cast<const void*>(vertexCount * sizeof(glm::vec3)));
    glBindVertexArray(0);
    gl::checkError("RasterRenderer::uploadMeshes");
}

void RasterRenderer::setMaterial(const gl::Program& p, const Material& m, uint32_t objectId) const {
    glUniform3fv(p.uniform("u_ma"), 1, glm::value_ptr(m.ma));
    glUniform3fv(p.uniform("u_md"), 1, glm::value_ptr(m.md));
    glUniform3fv(p.uniform("u_ms"), 1, glm::value_ptr(m.ms));
    glUniform1f(p.uniform("u_s"), m.s);
    glUniform1ui(p.uniform("u_objectId"), objectId);
}

void RasterRenderer::draw(const Scene& scene, int width, int height, bool withCoverage, Band band) {
    if (band.rows <= 0) band = Band{0, height};
    target_.resize(width, band.rows, withCoverage);
    target_.bind();

    // Every pass sets the state it needs (style.md "GL resources").
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);  // impostors far away may round to depth 1.0, the clear value
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const float background[4] = {scene.background.r, scene.background.g, scene.background.b, 1.0f};
    const GLuint noObject[4] = {kBackgroundId, 0, 0, 0};
    const float farDepth = 1.0f;
    glClearBufferfv(GL_COLOR, 0, background);
    if (target_.hasCoverage()) glClearBufferuiv(GL_COLOR, 1, noObject);
    glClearBufferfv(GL_DEPTH, 0, &farDepth);

    const ViewSetup view = makeViewSetup(scene, width, height);
    const FrameBlock frame = makeFrameBlock(scene, view, band);
    glBindBuffer(GL_UNIFORM_BUFFER, frameUbo_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameBlock), &frame);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frameUbo_.id());

    // Meshes first: they keep early depth testing, and the impostors behind them are rejected cheaply.
    glDisable(GL_CULL_FACE);  // two-sided lighting: back faces are lit with the flipped normal
    glUseProgram(meshProgram_.id());
    glBindVertexArray(meshVao_.id());
    for (const DrawRange& r : ranges_) {
        if (r.mesh >= scene.meshes.size() || r.part >= scene.meshes[r.mesh].parts.size()) continue;
        if (outsideClip(frame.viewProj, r.lo, r.hi)) continue;
        setMaterial(meshProgram_, scene.meshes[r.mesh].parts[r.part].material, meshCoverageId(scene, r.mesh));
        glDrawElements(GL_TRIANGLES, GLsizei(r.indexCount), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(r.firstIndex * sizeof(uint32_t)));
    }

    // Spheres: back faces of the bounding cube cover the footprint from outside and inside.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CCW);
    glUseProgram(sphereProgram_.id());
    glBindVertexArray(cubeVao_.id());
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        setMaterial(sphereProgram_, s.material, sphereCoverageId(scene, i));
        glUniform3fv(sphereProgram_.uniform("u_center"), 1, glm::value_ptr(s.center));
        glUniform1f(sphereProgram_.uniform("u_radius"), s.radius);
        glDrawArrays(GL_TRIANGLES, 0, 36);
    }
    glDisable(GL_CULL_FACE);

    // Planes last, drawn to infinity with ordinary depth: what meshes and spheres cover is rejected early.
    glUseProgram(planeProgram_.id());
    glBindVertexArray(emptyVao_.id());
    for (size_t i = 0; i < scene.planes.size(); ++i) {
        const Plane& p = scene.planes[i];
        setMaterial(planeProgram_, p.material, planeCoverageId(scene, i));
        const float eyeHeight = glm::dot(p.normal, view.eye) - p.offset;
        const glm::vec3 centre = view.eye - eyeHeight * p.normal;
        const glm::vec3 t = shading::planeTangent(p.normal), b = shading::planeBitangent(p.normal);
        glUniform3fv(planeProgram_.uniform("u_planeCenter"), 1, glm::value_ptr(centre));
        glUniform3fv(planeProgram_.uniform("u_planeT"), 1, glm::value_ptr(t));
        glUniform3fv(planeProgram_.uniform("u_planeB"), 1, glm::value_ptr(b));
        glUniform3fv(planeProgram_.uniform("u_planeNormal"), 1, glm::value_ptr(p.normal));
        glUniform1f(planeProgram_.uniform("u_planeOffset"), p.offset);
        glUniform1i(planeProgram_.uniform("u_checker"), p.checker ? 1 : 0);
        const Checker c = p.checker.value_or(Checker{});
        glUniform3fv(planeProgram_.uniform("u_md2"), 1, glm::value_ptr(c.md2));
        glUniform1f(planeProgram_.uniform("u_checkerSize"), c.size);
        glDrawArrays(GL_TRIANGLES, 0, 12);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    gl::checkError("RasterRenderer::draw");
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
