// ArrowOverlay: builds one shaft quad and one head triangle per arrow (screen-space widths in the vertex
// shader), an outline pass in black and a colour pass on top.
#include "app/arrow_overlay.h"

#include "scene/view.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec4.hpp>

namespace shadelab::app {
namespace {

struct Vertex {
    glm::vec3 base, tip, where, color;
};

void addArrow(std::vector<Vertex>& v, const glm::vec3& base, const glm::vec3& tip, const glm::vec3& color, float width,
              float headLength, float headWidth) {
    const float w = 0.5f * width, hl = headLength, hw = 0.5f * headWidth;
    const glm::vec3 shaft[6] = {{0, 0, -w}, {0, 0, w}, {1, -hl, w}, {0, 0, -w}, {1, -hl, w}, {1, -hl, -w}};
    const glm::vec3 head[3] = {{1, 0, 0}, {1, -hl, hw}, {1, -hl, -hw}};
    for (const glm::vec3& where : shaft) v.push_back({base, tip, where, color});
    for (const glm::vec3& where : head) v.push_back({base, tip, where, color});
}

}  // namespace

std::vector<Arrow> probeArrows(const ProbeResult& p) {
    std::vector<Arrow> arrows;
    if (!p.hit) return arrows;
    arrows.push_back({"N", p.N, glm::vec3(1.0f)});
    arrows.push_back({"V", p.V, glm::vec3(0.3f, 0.85f, 1.0f)});
    const bool numbered = p.lights.size() > 1;
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const std::string n = numbered ? std::to_string(i + 1) : "";
        const ProbeLight& l = p.lights[i];
        arrows.push_back({"L" + n, l.L, glm::vec3(1.0f, 0.75f, 0.1f)});
        arrows.push_back({"R" + n, l.R, glm::vec3(1.0f, 0.35f, 0.8f)});
        arrows.push_back({"H" + n, l.H, glm::vec3(0.35f, 1.0f, 0.4f)});
    }
    return arrows;
}

ArrowOverlay::ArrowOverlay(const gl::ShaderLibrary& shaders) {
    program_ = gl::Program::build(shaders, "view_arrows.vert", "view_arrows.frag");
    vao_ = gl::VertexArray::create();
    vbo_ = gl::Buffer::create();
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vbo_.id());
    for (GLuint a = 0; a < 4; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                              reinterpret_cast<const void*>(size_t(a) * sizeof(glm::vec3)));
    }
    glBindVertexArray(0);
    gl::checkError("ArrowOverlay setup");
}

std::vector<ArrowLabel> ArrowOverlay::draw(const Scene& scene, const ProbeResult& probe, int renderWidth,
                                           int renderHeight, const ImageRect& rect, int windowHeight,
                                           float pixelScale) {
    if (!probe.hit) return {};
    const ViewSetup view = makeViewSetup(scene, renderWidth, renderHeight);
    // About a fifth of the image height for an arrow across the view, whatever the distance.
    const float length = 0.4f * glm::length(probe.P - view.eye) * view.tanHalfFovY;
    std::vector<ArrowSegment> segments;
    for (const Arrow& a : probeArrows(probe))
        segments.push_back({probe.P, probe.P + length * a.direction, a.color, a.label});
    return draw(scene, segments, renderWidth, renderHeight, rect, windowHeight, pixelScale);
}

std::vector<ArrowLabel> ArrowOverlay::draw(const Scene& scene, const std::vector<ArrowSegment>& segments,
                                           int renderWidth, int renderHeight, const ImageRect& rect, int windowHeight,
                                           float pixelScale) {
    std::vector<ArrowLabel> labels;
    if (segments.empty() || rect.width <= 0 || rect.height <= 0) return labels;
    const ViewSetup view = makeViewSetup(scene, renderWidth, renderHeight);
    const glm::vec3 forward = view.forward;
    const float near = view.zNear;
    std::vector<Vertex> outline, fill;
    for (const ArrowSegment& a : segments) {
        // Clip against a plane just in front of the eye: the projection of what lies behind it is meaningless.
        glm::vec3 base = a.base, tip = a.tip;
        const float db = glm::dot(base - view.eye, forward) - near, dt = glm::dot(tip - view.eye, forward) - near;
        if (db <= 0.0f && dt <= 0.0f) continue;
        if (db < 0.0f) base = base + (tip - base) * (db / (db - dt));
        if (dt < 0.0f) tip = tip + (base - tip) * (dt / (dt - db));
        const float w = a.width * pixelScale;
        addArrow(outline, base, tip, glm::vec3(0.0f), 5.0f * w, 16.0f * pixelScale, 14.0f * pixelScale);
        addArrow(fill, base, tip, a.color, 2.5f * w, 14.0f * pixelScale, 10.0f * pixelScale);
        if (a.label.empty()) continue;
        const glm::vec4 clip = view.viewProj * glm::vec4(glm::mix(base, tip, a.labelAt), 1.0f);
        if (clip.w <= 0.0f) continue;
        const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
        const glm::vec2 glPos(float(rect.x) + (ndc.x * 0.5f + 0.5f) * float(rect.width),
                              float(rect.y) + (ndc.y * 0.5f + 0.5f) * float(rect.height));
        labels.push_back({a.label, glm::vec2(glPos.x, float(windowHeight) - glPos.y), a.color});
    }
    std::vector<Vertex> all = outline;
    all.insert(all.end(), fill.begin(), fill.end());

    glViewport(rect.x, rect.y, rect.width, rect.height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glUniformMatrix4fv(program_.uniform("u_viewProj"), 1, GL_FALSE, glm::value_ptr(view.viewProj));
    glUniform2f(program_.uniform("u_viewport"), float(rect.width), float(rect.height));
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vbo_.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(all.size() * sizeof(Vertex)), all.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(all.size()));
    glBindVertexArray(0);
    glUseProgram(0);
    return labels;
}

}  // namespace shadelab::app
