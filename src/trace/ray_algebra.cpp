// The intersection algebra in the lecture's form. Built with -ffp-contract=off (CMakeLists.txt), as the
// sphere tests are, so that nothing is fused and every expression rounds as intersectSphere's does.
#include "trace/ray_algebra.h"

#include "scene/objects.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <glm/geometric.hpp>

namespace shadelab::trace {
namespace {

std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char* fmt, ...) {
    char buf[256];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    return buf;
}

std::string vec(const glm::vec3& v) { return format("(%.4g, %.4g, %.4g)", v.x, v.y, v.z); }

void rayLines(std::vector<std::string>& out, const Ray& ray) {
    out.push_back("r(t) = o + t·d");
    out.push_back("o = " + vec(ray.origin));
    out.push_back("d = " + vec(ray.dir) + format("  (|d| = %.6g)", double(glm::length(ray.dir))));
}

}  // namespace

SphereAlgebra sphereAlgebra(const Ray& ray, const glm::vec3& center, float radius, float tMin) {
    SphereAlgebra s;
    s.center = center;
    s.radius = radius;
    // intersectSphere (lighting.glsl), step by step.
    const glm::vec3 oc = ray.origin - center;
    const float bHalf = glm::dot(oc, ray.dir);
    const glm::vec3 perp = oc - bHalf * ray.dir;
    const float discQuarter = radius * radius - glm::dot(perp, perp);
    const float c = glm::dot(oc, oc) - radius * radius;
    s.a = glm::dot(ray.dir, ray.dir);
    s.b = 2.0f * bHalf;
    s.c = c;
    s.discriminant = 4.0f * discQuarter;  // a power of two: exact
    s.real = !(discQuarter < 0.0f);
    if (!s.real) return s;
    const float sq = std::sqrt(discQuarter);
    const float q = bHalf > 0.0f ? -bHalf - sq : -bHalf + sq;
    const float t0 = q != 0.0f ? c / q : 0.0f;
    const float t1 = q;
    s.tNear = std::min(t0, t1);
    s.tFar = std::max(t0, t1);
    if (s.tNear > tMin) {
        s.taken = 1;
        s.t = s.tNear;
    } else if (s.tFar > tMin) {
        s.taken = 2;
        s.t = s.tFar;
    }
    return s;
}

PlaneAlgebra planeAlgebra(const Ray& ray, const glm::vec3& normal, float offset, float tMin) {
    PlaneAlgebra p;
    p.normal = normal;
    p.offset = offset;
    // intersectPlane (lighting.glsl).
    p.nDotD = glm::dot(normal, ray.dir);
    p.nDotO = glm::dot(normal, ray.origin);
    p.parallel = std::fabs(p.nDotD) < 1e-12f;
    if (p.parallel) return p;
    const float t = (offset - p.nDotO) / p.nDotD;
    p.t = t > tMin ? t : -1.0f;
    return p;
}

TriangleAlgebra triangleAlgebra(const Ray& ray, const glm::vec3& A, const glm::vec3& B, const glm::vec3& C) {
    TriangleAlgebra r;
    r.A = A, r.B = B, r.C = C;
    const glm::dvec3 o(ray.origin), d(ray.dir), a(A), e1 = glm::dvec3(B) - a, e2 = glm::dvec3(C) - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    r.parallel = std::fabs(det) < 1e-300;
    if (r.parallel) return r;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    r.t = glm::dot(e2, q) / det;
    r.b0 = 1.0 - u - v;
    r.b1 = u;
    r.b2 = v;
    return r;
}

std::vector<std::string> rayAlgebraLines(const TraceScene& scene, const Ray& ray, const Hit& hit) {
    std::vector<std::string> out;
    rayLines(out, ray);
    const Scene& sc = scene.scene();
    switch (hit.kind) {
        case HitKind::Sphere: {
            const Sphere& sp = sc.spheres[hit.index];
            const SphereAlgebra s = sphereAlgebra(ray, sp.center, sp.radius);
            out.push_back(
                format("sphere: |r(t) - c|² - r² = 0, c = %s, r = %.4g", vec(sp.center).c_str(), double(sp.radius)));
            out.push_back(format("a·t² + b·t + c = 0:  a = d·d = %.6g, b = 2d·(o - c) = %.6g, c = |o - c|² - r² = %.6g",
                                 double(s.a), double(s.b), double(s.c)));
            out.push_back(format("Δ = b² - 4ac = %.6g%s", double(s.discriminant), s.real ? "" : " < 0: no hit"));
            if (s.real) {
                out.push_back(format("roots t = (-b ± √Δ)/2a:  %.6g and %.6g", double(s.tNear), double(s.tFar)));
                out.push_back(s.taken == 1   ? format("t = %.7g: the nearer root, in front of o", double(s.t))
                              : s.taken == 2 ? format("t = %.7g: the nearer root is behind o (o is inside), so the "
                                                      "farther",
                                                      double(s.t))
                                             : std::string("both roots behind o: no hit"));
            }
            break;
        }
        case HitKind::Plane: {
            const Plane& pl = sc.planes[hit.index];
            const PlaneAlgebra p = planeAlgebra(ray, pl.normal, pl.offset);
            out.push_back(format("plane: nᵀx - δ = 0, n = %s, δ = %.4g", vec(pl.normal).c_str(), double(pl.offset)));
            out.push_back(format("t = (δ - nᵀo)/(nᵀd):  nᵀo = %.6g, nᵀd = %.6g", double(p.nDotO), double(p.nDotD)));
            out.push_back(p.parallel   ? std::string("nᵀd = 0: the ray runs parallel to the plane, no hit")
                          : p.t > 0.0f ? format("t = %.7g", double(p.t))
                                       : format("t = %.7g <= 0: the plane is behind o, no hit",
                                                double((pl.offset - p.nDotO) / p.nDotD)));
            break;
        }
        case HitKind::Triangle: {
            const MeshGeometry& g = *scene.meshPart(hit).geometry;
            const size_t tri = 3 * size_t(scene.triangleInPart(hit));
            const glm::vec3 A = g.positions[g.indices[tri]], B = g.positions[g.indices[tri + 1]],
                            C = g.positions[g.indices[tri + 2]];
            const TriangleAlgebra t = triangleAlgebra(ray, A, B, C);
            out.push_back("triangle: o + t·d = b0·A + b1·B + b2·C, b0 + b1 + b2 = 1");
            out.push_back("A = " + vec(A) + ", B = " + vec(B) + ", C = " + vec(C));
            out.push_back(t.parallel ? std::string("the ray lies in the triangle's plane: no hit")
                                     : format("t = %.7g, (b0, b1, b2) = (%.4g, %.4g, %.4g): all >= 0, inside", t.t,
                                              t.b0, t.b1, t.b2));
            break;
        }
    }
    return out;
}

}  // namespace shadelab::trace
