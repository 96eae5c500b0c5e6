// probePixel: primary ray, nearest hit over spheres, planes and mesh triangles, then the lighting terms.
#include "app/probe.h"

#include "scene/coverage.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "shading/local_illumination.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>

namespace shadelab::app {
namespace {

struct Hit {
    float t;
    uint32_t id;
    glm::vec3 N;        // raw normal as the rasterizer hands it to shadeLight (not yet unit length)
    glm::vec3 md;       // diffuse coefficient at the hit (checker applied)
    Material material;
};

// Möller & Trumbore 1997, "Fast, Minimum Storage Ray/Triangle Intersection", in double precision.
// Returns t and the barycentrics of v1 and v2.
std::optional<glm::dvec3> intersectTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& v0,
                                            const glm::dvec3& v1, const glm::dvec3& v2) {
    const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-300) return std::nullopt;
    const double inv = 1.0 / det;
    const glm::dvec3 s = o - v0;
    const double u = glm::dot(s, p) * inv;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) * inv;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) * inv;
    if (!(t > 0.0)) return std::nullopt;
    return glm::dvec3(t, u, v);
}

void nearestMeshHit(const Scene& scene, const glm::vec3& eye, const glm::vec3& dir, std::optional<Hit>& best) {
    const glm::dvec3 o(eye), d(dir);
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi)
        for (const MeshPart& part : scene.meshes[mi].parts)
            for (size_t k = 0; k + 2 < part.indices.size(); k += 3) {
                const uint32_t i0 = part.indices[k], i1 = part.indices[k + 1], i2 = part.indices[k + 2];
                if (i0 >= part.positions.size() || i1 >= part.positions.size() || i2 >= part.positions.size())
                    continue;
                const glm::vec3 &a = part.positions[i0], &b = part.positions[i1], &c = part.positions[i2];
                auto h = intersectTriangle(o, d, glm::dvec3(a), glm::dvec3(b), glm::dvec3(c));
                if (!h || (best && float(h->x) >= best->t)) continue;
                const float u = float(h->y), v = float(h->z);
                glm::vec3 n = (1.0f - u - v) * part.normals[i0] + u * part.normals[i1] + v * part.normals[i2];
                // gl_FrontFacing: counter-clockwise on screen is the front, i.e. the geometric normal of
                // the winding faces the eye.
                if (glm::dot(glm::cross(b - a, c - a), -dir) < 0.0f) n = -n;
                best = Hit{float(h->x), meshCoverageId(scene, mi), n, part.material.md, part.material};
            }
}

// True when the segment from `o` along unit `d` up to tMax hits any triangle (brute force, as above).
bool meshBlocks(const Scene& scene, const glm::vec3& o, const glm::vec3& d, float tMax) {
    const glm::dvec3 od(o), dd(d);
    for (const Mesh& mesh : scene.meshes)
        for (const MeshPart& part : mesh.parts)
            for (size_t k = 0; k + 2 < part.indices.size(); k += 3) {
                const uint32_t i0 = part.indices[k], i1 = part.indices[k + 1], i2 = part.indices[k + 2];
                if (i0 >= part.positions.size() || i1 >= part.positions.size() || i2 >= part.positions.size())
                    continue;
                auto h = intersectTriangle(od, dd, glm::dvec3(part.positions[i0]), glm::dvec3(part.positions[i1]),
                                           glm::dvec3(part.positions[i2]));
                if (h && h->x < double(tMax)) return true;
            }
    return false;
}

// The tracer's shadow-ray offset: scaled by the box of the bounded geometry and the eye.
float shadowEpsilon(const Scene& scene) {
    Bounds b = sceneBounds(scene);
    const glm::vec3 eye = scene.camera.position;
    b.lo = b.empty() ? eye : glm::min(b.lo, eye);
    b.hi = b.empty() ? eye : glm::max(b.hi, eye);
    const float radius = 0.5f * glm::length(b.hi - b.lo);
    const glm::vec3 mag = glm::max(glm::abs(b.lo), glm::abs(b.hi));
    const float e = std::max({1e-4f * radius, 1e-6f * std::max({mag.x, mag.y, mag.z}), 1e-7f});
    return std::isfinite(e) ? e : 1e-4f;
}

// vis_l by one shadow ray from P + ε·N toward the light, as the tracer casts it.
float shadowRayVisibility(const Scene& scene, const glm::vec3& P, const glm::vec3& N, const Light& light) {
    const glm::vec3 origin = P + shadowEpsilon(scene) * N;
    const bool isPoint = light.type == LightType::Point;
    const glm::vec3 toLight = isPoint ? light.position - origin : -light.direction;
    const float tMax = isPoint ? glm::length(toLight) : std::numeric_limits<float>::infinity();
    const glm::vec3 d = glm::normalize(toLight);
    for (const Sphere& s : scene.spheres) {
        const float t = shading::intersectSphere(origin, d, s.center, s.radius, 0.0f);
        if (t > 0.0f && t < tMax) return 0.0f;
    }
    for (const Plane& p : scene.planes) {
        const float t = shading::intersectPlane(origin, d, p.normal, p.offset, 0.0f);
        if (t > 0.0f && t < tMax) return 0.0f;
    }
    return meshBlocks(scene, origin, d, tMax) ? 0.0f : 1.0f;
}

}  // namespace

ProbeResult probePixel(const Scene& scene, int width, int height, int x, int y) {
    ProbeResult r;
    r.x = x;
    r.y = y;
    r.width = width;
    r.height = height;
    if (width <= 0 || height <= 0) return r;
    const ViewSetup view = makeViewSetup(scene, width, height);
    const glm::vec3 eye = view.eye;
    const glm::vec3 dir = shading::cameraRayDirection(view.forward, view.right, view.up, view.tanHalfFovY,
                                                      float(width), float(height), float(x) + 0.5f,
                                                      float(y) + 0.5f);
    const glm::vec3 V = -dir;

    std::optional<Hit> best;
    nearestMeshHit(scene, eye, dir, best);
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const float t = shading::intersectSphere(eye, dir, s.center, s.radius, 0.0f);
        if (t < 0.0f || (best && t >= best->t)) continue;
        const glm::vec3 P = eye + t * dir;
        best = Hit{t, sphereCoverageId(scene, i), shading::faceForward((P - s.center) / s.radius, V),
                   s.material.md, s.material};
    }
    for (size_t i = 0; i < scene.planes.size(); ++i) {
        const Plane& p = scene.planes[i];
        const float t = shading::intersectPlane(eye, dir, p.normal, p.offset, 0.0f);
        if (t < 0.0f || (best && t >= best->t)) continue;
        const glm::vec3 P = eye + t * dir;
        const bool second = p.checker && shading::checkerParity(P, p.normal, p.checker->size) == 1;
        best = Hit{t, planeCoverageId(scene, i), shading::faceForward(p.normal, V),
                   second ? p.checker->md2 : p.material.md, p.material};
    }
    if (!best) return r;

    r.hit = true;
    r.objectId = best->id;
    r.kind = objectRef(scene, best->id).kind;
    r.label = objectLabel(scene, best->id);
    r.t = best->t;
    r.P = eye + best->t * dir;
    r.N = glm::normalize(best->N);
    r.V = glm::normalize(V);
    r.material = best->material;
    r.material.md = best->md;
    const Material& m = r.material;
    r.ambient = shading::shadeAmbient(scene.ambient, m.ma, true);

    // Each light: the same raw vectors the fragment shaders pass (surface.glsl), then shadeLight.
    std::vector<shading::LightSample> samples;
    for (const Light& light : scene.lights) {
        const bool isPoint = light.type == LightType::Point;
        const glm::vec3 Lraw = shading::lightVector(isPoint ? light.position : light.direction, isPoint, r.P);
        const glm::vec3 Il = shading::lightIntensityAt(light.color, isPoint, light.attenuation, Lraw);
        const bool lit = glm::dot(r.N, Lraw) > 0.0f;   // the terms are 0 on the unlit side: no ray needed
        const float vis = scene.terms.shadows && lit ? shadowRayVisibility(scene, r.P, r.N, light) : 1.0f;
        samples.push_back({Lraw, Il, vis});
        ProbeLight pl;
        pl.name = light.name;
        pl.L = glm::normalize(Lraw);
        pl.R = shading::reflectLight(r.N, pl.L);
        pl.H = glm::normalize(pl.L + r.V);
        pl.NoL = glm::dot(r.N, pl.L);
        pl.RoV = glm::dot(pl.R, r.V);
        pl.NoH = glm::dot(r.N, pl.H);
        pl.Il = Il;
        pl.visibility = vis;
        pl.specPhong = shading::specularPhong(r.N, pl.L, r.V, m.s);
        pl.specBlinn = shading::specularBlinnPhong(r.N, pl.L, r.V, m.s);
        const int phong = shading::SL_MODEL_PHONG, blinn = shading::SL_MODEL_BLINN_PHONG;
        pl.diffuse = vis * shading::shadeLight(best->N, Lraw, V, Il, m.md, m.ms, m.s, phong, true, false);
        pl.specularPhong = vis * shading::shadeLight(best->N, Lraw, V, Il, m.md, m.ms, m.s, phong, false, true);
        pl.specularBlinn = vis * shading::shadeLight(best->N, Lraw, V, Il, m.md, m.ms, m.s, blinn, false, true);
        r.lights.push_back(pl);
    }
    const shading::SurfaceParams params{m.ma, m.md, m.ms, m.s};
    const shading::TermFlags flags{scene.terms.ambient, scene.terms.diffuse, scene.terms.specular};
    r.totalPhong = shading::shadeLocal(best->N, V, samples.data(), samples.size(), params, scene.ambient,
                                       shading::SL_MODEL_PHONG, flags);
    r.totalBlinn = shading::shadeLocal(best->N, V, samples.data(), samples.size(), params, scene.ambient,
                                       shading::SL_MODEL_BLINN_PHONG, flags);
    return r;
}

}  // namespace shadelab::app
