// Emitters: power-weighted picking, cone sampling of spheres (pbrt-v3 §14.2.2), area sampling of triangles.
#include "trace/path/emitters.h"

#include "scene/mesh_geometry.h"
#include "shading/lighting.h"
#include "trace/luminance.h"
#include "trace/path/warp.h"

#include <cmath>
#include <limits>

namespace shadelab::trace {
namespace {

bool emits(const Material& m) { return m.emission.x > 0.0f || m.emission.y > 0.0f || m.emission.z > 0.0f; }

// Light sampling draws emitters of uniform radiance only: an emissive texture varies over the triangle (and
// alpha may cut it away), so such parts are left to BSDF sampling, which reads the texture where it hits.
bool sampledDirectly(const Material& m) { return emits(m) && !m.emissiveTexture && m.alphaMode == AlphaMode::Opaque; }

// 1 + this: how far outside a sphere (in radii squared) P must be for the cone to be used.
constexpr float kOutsideMargin = 1e-4f;

}  // namespace

Emitters::Emitters(const TraceScene& scene, const EnvironmentSampler& environment)
    : scene_(&scene), environment_(&environment) {
    const Scene& sc = scene.scene();
    std::vector<double> power;
    for (size_t i = 0; i < sc.spheres.size(); ++i) {
        const Sphere& s = sc.spheres[i];
        if (!sampledDirectly(s.material)) continue;
        Entry e;
        e.sphere = true;
        e.sphereIndex = uint32_t(i);
        e.Le = s.material.emission;
        entries_.push_back(e);
        power.push_back(double(luminance(e.Le)) * 4.0 * double(kPi) * double(s.radius) * s.radius);
    }
    for (const Mesh& mesh : sc.meshes)
        for (const MeshPart& part : mesh.parts) {
            if (!sampledDirectly(part.material) || !part.geometry) continue;
            const MeshGeometry& g = *part.geometry;
            for (size_t t = 0; t + 2 < g.indices.size(); t += 3) {
                Entry e;
                e.p0 = g.positions[g.indices[t]];
                e.e1 = g.positions[g.indices[t + 1]] - e.p0;
                e.e2 = g.positions[g.indices[t + 2]] - e.p0;
                e.Le = part.material.emission;
                const double area = 0.5 * double(glm::length(glm::cross(e.e1, e.e2)));
                if (!(area > 0.0) || !std::isfinite(area)) continue;
                entries_.push_back(e);
                power.push_back(double(luminance(e.Le)) * area);
            }
        }
    pick_ = Distribution1D(power);
}

float Emitters::sphereDensity(const Sphere& s, const glm::vec3& P, const glm::vec3& q) {
    const glm::vec3 toCentre = s.center - P;
    const float d2 = glm::dot(toCentre, toCentre), r2 = s.radius * s.radius;
    if (d2 > r2 * (1.0f + kOutsideMargin)) {
        const float cosMax = std::sqrt(std::max(0.0f, 1.0f - r2 / d2));
        return uniformConePdf(cosMax);
    }
    // Inside: uniform over the area, converted to solid angle at P.
    const glm::vec3 w = q - P;
    const float dist2 = glm::dot(w, w);
    const float cosL = std::abs(glm::dot((q - s.center) / s.radius, w)) / std::sqrt(dist2);
    if (!(cosL > 0.0f)) return 0.0f;
    return dist2 / (cosL * 4.0f * kPi * r2);
}

std::optional<EmitterSample> Emitters::sample(const glm::vec3& P, const glm::vec4& u) const {
    float pick = u.x;
    const float objects = pick_.empty() ? 0.0f : objectShare();
    if (pick >= objects) {
        if (!environment_->sampled()) return std::nullopt;
        const EnvironmentDirection d = environment_->sample(glm::vec3((pick - objects) / (1.0f - objects), u.y, u.z));
        EmitterSample out;
        out.wi = d.dir;
        out.distance = std::numeric_limits<float>::infinity();
        out.pdf = d.pdf * (1.0f - objects);
        out.environment = true;
        return out;
    }
    const size_t k = pick_.sample(pick / objects);
    const Entry& e = entries_[k];
    const float pickPdf = objects * pick_.probability(k);
    EmitterSample out;
    out.Le = e.Le;
    if (e.sphere) {
        const Sphere& s = scene_->scene().spheres[e.sphereIndex];
        const glm::vec3 toCentre = s.center - P;
        const float d2 = glm::dot(toCentre, toCentre), r2 = s.radius * s.radius;
        glm::vec3 q;
        if (d2 > r2 * (1.0f + kOutsideMargin)) {
            const float d = std::sqrt(d2);
            const float cosMax = std::sqrt(std::max(0.0f, 1.0f - r2 / d2));
            out.wi = glm::normalize(Frame(toCentre / d).toWorld(sampleUniformCone(glm::vec2(u.y, u.z), cosMax)));
            // The nearer crossing of the sphere (the closest approach when rounding misses it).
            const float b = glm::dot(out.wi, toCentre), disc = b * b - (d2 - r2);
            out.distance = disc > 0.0f ? b - std::sqrt(disc) : b;
            out.pdf = pickPdf * uniformConePdf(cosMax);
            return out.pdf > 0.0f && std::isfinite(out.pdf) ? std::optional<EmitterSample>(out) : std::nullopt;
        }
        q = s.center + s.radius * sampleUniformSphere(glm::vec2(u.y, u.z));
        const glm::vec3 w = q - P;
        out.distance = glm::length(w);
        if (!(out.distance > 0.0f)) return std::nullopt;
        out.wi = w / out.distance;
        out.pdf = pickPdf * sphereDensity(s, P, q);
    } else {
        const glm::vec2 b = sampleTriangleBarycentrics(glm::vec2(u.y, u.z));
        const glm::vec3 q = e.p0 + b.y * e.e1 + (1.0f - b.x - b.y) * e.e2;
        const glm::vec3 w = q - P;
        const float dist2 = glm::dot(w, w);
        out.distance = std::sqrt(dist2);
        if (!(out.distance > 0.0f)) return std::nullopt;
        out.wi = w / out.distance;
        const glm::vec3 n = glm::cross(e.e1, e.e2);
        const float area2 = glm::length(n);  // twice the area
        const float cosL = std::abs(glm::dot(n, out.wi)) / area2;
        if (!(cosL > 0.0f)) return std::nullopt;
        out.pdf = pickPdf * dist2 / (cosL * 0.5f * area2);
    }
    return out.pdf > 0.0f && std::isfinite(out.pdf) ? std::optional<EmitterSample>(out) : std::nullopt;
}

float Emitters::pdfHit(const Ray& ray, const Hit& hit) const {
    if (pick_.empty() || hit.kind == HitKind::Plane) return 0.0f;
    const Material& m = scene_->material(hit);
    if (!sampledDirectly(m)) return 0.0f;
    const float share = objectShare() / float(pick_.total());
    const glm::vec3 q = ray.origin + hit.t * ray.dir;
    if (hit.kind == HitKind::Sphere) {
        const Sphere& s = scene_->scene().spheres[hit.index];
        const float pickPdf = share * luminance(m.emission) * 4.0f * kPi * s.radius * s.radius;
        return pickPdf * sphereDensity(s, ray.origin, q);
    }
    // A triangle's pick is luminance·area / total power; the area density is 1/area: the area cancels.
    const MeshGeometry& g = *scene_->meshPart(hit).geometry;
    const size_t t = 3 * size_t(scene_->triangleInPart(hit));
    const glm::vec3 n = glm::cross(g.positions[g.indices[t + 1]] - g.positions[g.indices[t]],
                                   g.positions[g.indices[t + 2]] - g.positions[g.indices[t]]);
    const float len = glm::length(n);
    const float cosL = len > 0.0f ? std::abs(glm::dot(n, ray.dir)) / len : 0.0f;
    if (!(cosL > 0.0f)) return 0.0f;
    return share * luminance(m.emission) * hit.t * hit.t / cosL;
}

float Emitters::pdfEnvironment(const glm::vec3& dir) const {
    if (!environment_->sampled()) return 0.0f;
    const float objects = pick_.empty() ? 0.0f : objectShare();
    return (1.0f - objects) * environment_->pdf(dir);
}

}  // namespace shadelab::trace
