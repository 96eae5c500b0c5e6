// PlaneFootprint: the viewport clipped to the half-plane of window coordinates whose rays point at the plane.
#include "raster/plane_footprint.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace shadelab::raster {

PlaneFootprint planeFootprint(const PlaneCamera& c, int width, int height, const glm::vec3& n, float offset,
                              float marginPixels) {
    PlaneFootprint out;
    const glm::vec2 corners[4] = {{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}};
    const auto whole = [&] {
        out.count = 4;
        for (int k = 0; k < 4; ++k) out.corners[k] = corners[k];
        return out;
    };
    if (width <= 0 || height <= 0) return out;
    // A ray hits where t = s / dot(n, D) > 0 (intersectPlane), D the unnormalised direction
    // forward + x·right + y·up of cameraRayDirection, so where sign(dot(n, D)) = sign(s).
    const double s = double(offset) - glm::dot(glm::dvec3(n), glm::dvec3(c.eye));
    const double scale = std::abs(double(offset)) + std::abs(glm::dot(glm::dvec3(n), glm::dvec3(c.eye)));
    if (!(std::abs(s) > 1e-6 * scale)) return whole();  // on the plane, or not finite: no shortcut
    const double W = c.viewport.x, H = c.viewport.y, t = c.viewport.z, band = c.viewport.w;
    if (!(W > 0.0 && H > 0.0 && t > 0.0)) return whole();
    // dot(n, D) at window coordinates (fx, fy) of this viewport: x = (2 fx / W − 1)·t·W/H and
    // y = (1 − 2 (H − fy − band) / H)·t, so h = a + bx·fx + by·fy, signed so that h > 0 where rays hit.
    const double nf = glm::dot(glm::dvec3(n), glm::dvec3(c.forward)), nr = glm::dot(glm::dvec3(n), glm::dvec3(c.right)),
                 nu = glm::dot(glm::dvec3(n), glm::dvec3(c.up));
    const double sign = s > 0.0 ? 1.0 : -1.0;
    const double aspect = W / H;
    const double bx = sign * 2.0 / W * t * aspect * nr, by = sign * 2.0 / H * t * nu;
    const double a = sign * (nf - t * aspect * nr + (2.0 * band / H - 1.0) * t * nu);
    // The margin: marginPixels of the gradient, and the GPU's rounding of D and of the dot product (a relative
    // 1e-5 of its terms' size is far above single precision's few ulps).
    const double slack = marginPixels * (std::abs(bx) + std::abs(by)) +
                         1e-5 * (std::abs(nf) + t * aspect * std::abs(nr) + t * std::abs(nu));
    const auto h = [&](const glm::vec2& ndc) {
        const double fx = 0.5 * (double(ndc.x) + 1.0) * width, fy = 0.5 * (double(ndc.y) + 1.0) * height;
        return a + bx * fx + by * fy + slack;
    };
    // Sutherland–Hodgman against h >= 0: the rectangle loses at most one corner's side, so at most 5 remain.
    for (int k = 0; k < 4; ++k) {
        const glm::vec2 p = corners[k], q = corners[(k + 1) % 4];
        const double hp = h(p), hq = h(q);
        if (hp >= 0.0) out.corners[out.count++] = p;
        if ((hp >= 0.0) != (hq >= 0.0)) {
            const float u = float(hp / (hp - hq));
            out.corners[out.count++] = p + u * (q - p);
        }
    }
    if (out.count < 3) out.count = 0;
    return out;
}

}  // namespace shadelab::raster
