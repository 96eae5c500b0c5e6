// PlaneFootprint: the viewport clipped to the half-plane of window coordinates whose rays point at the plane,
// the holes spheres in front of it make, and the triangles of what is left.
#include "raster/plane_footprint.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace shadelab::raster {
namespace {

// Twice the signed area of a polygon (positive: counter-clockwise).
double signedArea2(const glm::vec2* p, int count) {
    double a = 0.0;
    for (int k = 0; k < count; ++k) {
        const glm::vec2 u = p[k], v = p[(k + 1) % count];
        a += double(u.x) * v.y - double(v.x) * u.y;
    }
    return a;
}

// Whether q lies inside the counter-clockwise convex polygon, at least `margin` (NDC) from every edge.
bool insideConvex(const glm::vec2* p, int count, glm::dvec2 q, double margin) {
    for (int k = 0; k < count; ++k) {
        const glm::dvec2 a(p[k]), b(p[(k + 1) % count]);
        const glm::dvec2 e = b - a;
        const double len = std::sqrt(e.x * e.x + e.y * e.y);
        if (len == 0.0) continue;
        if ((e.x * (q.y - a.y) - e.y * (q.x - a.x)) / len < margin) return false;
    }
    return true;
}

// The x extent of a convex polygon at height y: false where y misses it. The same arithmetic for the same
// (polygon, y) wherever it is asked, so slabs that meet at y agree on it exactly.
bool spanAt(const glm::vec2* p, int count, float y, float& lo, float& hi) {
    lo = INFINITY;
    hi = -INFINITY;
    for (int k = 0; k < count; ++k) {
        const glm::vec2 a = p[k], b = p[(k + 1) % count];
        if (y < std::min(a.y, b.y) || y > std::max(a.y, b.y)) continue;
        if (a.y == b.y) {
            lo = std::min({lo, a.x, b.x});
            hi = std::max({hi, a.x, b.x});
            continue;
        }
        const float x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    return lo <= hi;
}

void boundsOf(const FootprintHole& h, glm::vec2& lo, glm::vec2& hi) {
    lo = glm::vec2(INFINITY);
    hi = glm::vec2(-INFINITY);
    for (int k = 0; k < h.count; ++k) {
        lo = glm::min(lo, h.corners[k]);
        hi = glm::max(hi, h.corners[k]);
    }
}

void trapezoid(std::vector<glm::vec2>& out, float y0, float a0, float b0, float y1, float a1, float b1) {
    if (b0 - a0 <= 0.0f && b1 - a1 <= 0.0f) return;
    if (b0 > a0) out.insert(out.end(), {{a0, y0}, {b0, y0}, {b1, y1}});
    if (b1 > a1) out.insert(out.end(), {{a0, y0}, {b1, y1}, {a1, y1}});
}

}  // namespace

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

FootprintHole sphereHole(const PlaneCamera& c, int width, int height, const glm::vec3& n, float offset,
                         const glm::vec3& centre, float radius, const PlaneFootprint& footprint, float insetPixels) {
    const FootprintHole none;
    if (footprint.count < 3 || width <= 0 || height <= 0 || !(radius > 0.0f) || !(insetPixels >= 0.0f)) return none;
    const glm::dvec3 eye(c.eye), C(centre), N(n);
    const double r = radius;
    const glm::dvec3 d = C - eye;
    const double D2 = glm::dot(d, d), D = std::sqrt(D2);
    if (!(D2 > 1.21 * r * r)) return none;                                       // the eye near or inside the sphere
    const double pixel = 2.0 * double(c.viewport.z) * D / double(c.viewport.y);  // a pixel's size at the sphere
    // On the eye's side of the plane, touching it at most: a ray that meets the sphere meets it before the plane
    // (a ray reaching the plane inside the sphere has entered the sphere first). A sphere sunk by a hair (its
    // centre rounded) hides less than a pixel behind the plane, which the inset covers.
    const double sEye = glm::dot(N, eye) - offset, sC = glm::dot(N, C) - offset;
    if (!(sEye * sC > 0.0) || !(std::abs(sC) >= r - 0.25 * pixel * pixel / r)) return none;
    const glm::dmat4 viewProj(c.viewProj);
    const auto clipOf = [&](const glm::dvec3& p) { return viewProj * glm::dvec4(p, 1.0); };
    const auto inRange = [](const glm::dvec4& q) { return q.w > 0.0 && q.z >= -q.w && q.z <= q.w; };
    const auto depthOf = [](const glm::dvec4& q) { return std::min(0.5 * q.z / q.w + 0.5, 1.0); };
    // The depth a plane hit behind the sphere keeps above the sphere's: along the ray through its centre, a
    // gap of the shortest chord inside the inset silhouette, beyond the sphere's back. Far from the near plane
    // the depth flattens, and two hits a short way apart can round to one depth, where GL_LEQUAL lets the plane
    // win: there, no hole.
    const glm::dvec3 dir = d / D;
    const double q = std::max(r - 0.5 * insetPixels * pixel, 0.0);
    const double chord = 2.0 * std::sqrt(std::max(r * r - q * q, 0.0));
    const glm::dvec4 front = clipOf(C - r * dir), back = clipOf(C + r * dir), behind = clipOf(C + (r + chord) * dir);
    if (!inRange(front) || !inRange(back) || !(behind.w > 0.0)) return none;
    if (!(depthOf(behind) - depthOf(back) > 1e-5)) return none;
    // The octagon inscribed in the silhouette: the tangent circle (as sphere.vert builds it), eight points on it.
    const glm::dvec3 cc = eye + (1.0 - r * r / D2) * d;
    const double rho = r * std::sqrt(1.0 - r * r / D2);
    const glm::dvec3 a = glm::normalize(std::abs(dir.x) < 0.9 ? glm::cross(dir, glm::dvec3(1.0, 0.0, 0.0))
                                                              : glm::cross(dir, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 b = glm::cross(dir, a);
    glm::dvec2 p[8], g(0.0);
    for (int k = 0; k < 8; ++k) {
        const double angle = 0.78539816339744831 * k;
        const glm::dvec4 q4 = clipOf(cc + rho * (std::cos(angle) * a + std::sin(angle) * b));
        if (!inRange(q4)) return none;
        p[k] = glm::dvec2(q4.x / q4.w, q4.y / q4.w);
        g += p[k] / 8.0;
    }
    // Each corner `insetPixels` toward the centre (its edges move at least cos(22.5°) of that).
    FootprintHole out;
    out.count = 8;
    const glm::dvec2 toPixels(0.5 * width, 0.5 * height);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec2 e = (p[k] - g) * toPixels;
        const double len = std::sqrt(e.x * e.x + e.y * e.y);
        if (!(len > insetPixels + 4.0)) return none;  // too small to be worth a hole
        out.corners[k] = glm::vec2(g + (p[k] - g) * (1.0 - insetPixels / len));
    }
    if (signedArea2(out.corners, 8) < 0.0) std::reverse(out.corners, out.corners + 8);
    // Inside the footprint (a pixel clear of its edges), so that the pieces around it never cross it.
    const double margin = 2.0 / std::max(width, height);
    for (int k = 0; k < 8; ++k)
        if (!insideConvex(footprint.corners, footprint.count, glm::dvec2(out.corners[k]), margin)) return none;
    return out;
}

std::vector<glm::vec2> footprintTriangles(const PlaneFootprint& f, std::vector<FootprintHole> holes) {
    std::vector<glm::vec2> out;
    if (f.count < 3) return out;
    // Holes in the order of their size; one whose box meets a kept one's is dropped, so kept holes are disjoint
    // and their spans keep their order through every slab.
    holes.erase(std::remove_if(holes.begin(), holes.end(), [](const FootprintHole& h) { return h.count < 3; }),
                holes.end());
    std::stable_sort(holes.begin(), holes.end(), [](const FootprintHole& x, const FootprintHole& y) {
        return signedArea2(x.corners, x.count) > signedArea2(y.corners, y.count);
    });
    std::vector<FootprintHole> kept;
    std::vector<glm::vec4> boxes;
    for (const FootprintHole& h : holes) {
        if (kept.size() == kMaxFootprintHoles) break;  // the largest; more would cost the CPU what they save
        glm::vec2 lo, hi;
        boundsOf(h, lo, hi);
        bool overlaps = false;
        for (const glm::vec4& b : boxes)
            overlaps = overlaps || (lo.x <= b.z && b.x <= hi.x && lo.y <= b.w && b.y <= hi.y);
        if (overlaps) continue;
        kept.push_back(h);
        boxes.emplace_back(lo.x, lo.y, hi.x, hi.y);
    }
    if (kept.empty()) {
        for (int k = 1; k + 1 < f.count; ++k) out.insert(out.end(), {f.corners[0], f.corners[k], f.corners[k + 1]});
        return out;
    }
    // Horizontal slabs between consecutive corners' heights: inside one, every boundary is one straight edge, so
    // each piece between the footprint's sides and the holes is a trapezoid. Neighbouring slabs meet on the same
    // line with the same spans, so no pixel falls between them.
    std::vector<float> ys;
    for (int k = 0; k < f.count; ++k) ys.push_back(f.corners[k].y);
    for (const FootprintHole& h : kept)
        for (int k = 0; k < h.count; ++k) ys.push_back(h.corners[k].y);
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    struct Span {
        float lo0, hi0, lo1, hi1;
    };
    std::vector<Span> inside;
    for (size_t s = 0; s + 1 < ys.size(); ++s) {
        const float y0 = ys[s], y1 = ys[s + 1];
        float l0, r0, l1, r1;
        if (!spanAt(f.corners, f.count, y0, l0, r0) || !spanAt(f.corners, f.count, y1, l1, r1)) continue;
        inside.clear();
        for (size_t i = 0; i < kept.size(); ++i) {
            if (boxes[i].y > y0 || boxes[i].w < y1) continue;  // the hole does not span the slab
            Span sp{};
            if (spanAt(kept[i].corners, kept[i].count, y0, sp.lo0, sp.hi0) &&
                spanAt(kept[i].corners, kept[i].count, y1, sp.lo1, sp.hi1))
                inside.push_back(sp);
        }
        std::sort(inside.begin(), inside.end(),
                  [](const Span& x, const Span& y) { return x.lo0 + x.lo1 < y.lo0 + y.lo1; });
        float a0 = l0, a1 = l1;
        for (const Span& sp : inside) {
            trapezoid(out, y0, a0, sp.lo0, y1, a1, sp.lo1);
            a0 = sp.hi0;
            a1 = sp.hi1;
        }
        trapezoid(out, y0, a0, r0, y1, a1, r1);
    }
    return out;
}

}  // namespace shadelab::raster
