// Lines by coverage: each pixel near a projected segment is blended toward the line's colour by how much
// of a pixel-wide band of the given width covers its centre (a one-pixel linear ramp at the edge).
#include "probe/ray_tree_picture.h"

#include "scene/view.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace shadelab {
namespace {

void blendPixel(Image8& img, int x, int y, const glm::vec3& c, float a) {
    if (x < 0 || y < 0 || x >= img.width || y >= img.height || a <= 0.0f) return;
    uint8_t* p = &img.data[(size_t(y) * size_t(img.width) + size_t(x)) * size_t(img.channels)];
    for (int k = 0; k < 3; ++k) {
        const float v = float(p[k]) + (255.0f * std::clamp(c[k], 0.0f, 1.0f) - float(p[k])) * std::min(a, 1.0f);
        p[k] = uint8_t(std::lround(std::clamp(v, 0.0f, 255.0f)));
    }
}

// A line from a to b (pixel coordinates, y down) of `width` pixels.
void line(Image8& img, glm::vec2 a, glm::vec2 b, const glm::vec3& c, float width) {
    const float r = 0.5f * width;
    const int x0 = int(std::floor(std::min(a.x, b.x) - r - 1.0f)), x1 = int(std::ceil(std::max(a.x, b.x) + r + 1.0f));
    const int y0 = int(std::floor(std::min(a.y, b.y) - r - 1.0f)), y1 = int(std::ceil(std::max(a.y, b.y) + r + 1.0f));
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    for (int y = std::max(y0, 0); y <= std::min(y1, img.height - 1); ++y)
        for (int x = std::max(x0, 0); x <= std::min(x1, img.width - 1); ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
            const float d = glm::length(p - (a + t * ab));
            blendPixel(img, x, y, c, r + 0.5f - d);
        }
}

void ring(Image8& img, glm::vec2 centre, float radius, const glm::vec3& c, float width) {
    const int n = 48;
    for (int k = 0; k < n; ++k) {
        const float a0 = 6.2831853f * float(k) / float(n), a1 = 6.2831853f * float(k + 1) / float(n);
        line(img, centre + radius * glm::vec2(std::cos(a0), std::sin(a0)),
             centre + radius * glm::vec2(std::cos(a1), std::sin(a1)), c, width);
    }
}

}  // namespace

void drawRayTreePicture(Image8& image, const Scene& scene, const RayTreeView& tree) {
    if (image.width <= 0 || image.height <= 0 || tree.record.rays.empty()) return;
    const ViewSetup view = makeViewSetup(scene, image.width, image.height);
    const trace::TreeRay& primary = tree.record.rays[0];
    const float escape = primary.hit ? primary.hit->t : 10.0f;
    const float px = float(std::min(image.width, image.height)) / 360.0f;  // 1 at 640x360
    auto project = [&](const glm::vec3& p) {
        const glm::vec4 clip = view.viewProj * glm::vec4(p, 1.0f);
        return glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * float(image.width),
                         (0.5f - clip.y / clip.w * 0.5f) * float(image.height));
    };
    const std::vector<RayTreeSegment> segments = rayTreeSegments(scene, tree.record, escape);
    for (int pass = 0; pass < 2; ++pass)  // the outlines under every line
        for (const RayTreeSegment& s : segments) {
            glm::vec3 a = s.from, b = s.to;
            const float da = glm::dot(a - view.eye, view.forward) - view.zNear;
            const float db = glm::dot(b - view.eye, view.forward) - view.zNear;
            if (da <= 0.0f && db <= 0.0f) continue;
            if (da < 0.0f) a = a + (b - a) * (da / (da - db));
            if (db < 0.0f) b = b + (a - b) * (db / (db - da));
            if (pass == 0)
                line(image, project(a), project(b), glm::vec3(0.0f), 4.5f * px);
            else
                line(image, project(a), project(b), s.color, 2.0f * px);
        }
    const glm::vec2 at(float(tree.x) + 0.5f, float(tree.y) + 0.5f);
    ring(image, at, 7.0f * px, glm::vec3(0.0f), 3.5f * px);
    ring(image, at, 7.0f * px, glm::vec3(1.0f), 1.5f * px);
}

}  // namespace shadelab
