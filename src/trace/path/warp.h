// Warps: uniform numbers in [0, 1)² to directions and points with known densities, the sampling routines
// the path tracer's BSDFs, emitters and environment share (pbrt-v4 §A.5, Heitz 2018). Each sample routine
// has its pdf beside it; tests/.. path_sampling_test checks every pair with a χ² test. Local frames have
// the lobe axis along +z.
#pragma once

#include "shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace shadelab::trace {

inline constexpr float kPi = 3.14159265358979f;

// An orthonormal basis around unit n (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
struct Frame {
    glm::vec3 t, b, n;

    explicit Frame(const glm::vec3& normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float c = n.x * n.y * a;
        t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
        b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
    }
    glm::vec3 toWorld(const glm::vec3& v) const { return v.x * t + v.y * b + v.z * n; }
    glm::vec3 toLocal(const glm::vec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
};

// A direction around +z with cos θ = c and azimuth 2π·u.
inline glm::vec3 sphericalDirection(float cosTheta, float u) {
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Cosine-weighted hemisphere (Lambert): pdf = cos θ / π.
inline glm::vec3 sampleCosineHemisphere(glm::vec2 u) { return sphericalDirection(std::sqrt(1.0f - u.x), u.y); }
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta / kPi : 0.0f; }

// Uniform sphere: pdf = 1 / 4π.
inline glm::vec3 sampleUniformSphere(glm::vec2 u) { return sphericalDirection(1.0f - 2.0f * u.x, u.y); }
inline constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPi);

// Uniform cone of directions with cos θ >= cosMax: pdf = 1 / (2π (1 − cosMax)).
inline glm::vec3 sampleUniformCone(glm::vec2 u, float cosMax) {
    return sphericalDirection(1.0f - u.x * (1.0f - cosMax), u.y);
}
inline float uniformConePdf(float cosMax) { return 1.0f / (2.0f * kPi * (1.0f - cosMax)); }

// A cos^s lobe around +z (Lafortune & Willems 1994, the Phong lobe): cos θ = u^(1/(s+1)),
// pdf = (s + 1) / 2π · cos^s θ over the hemisphere around the axis.
inline glm::vec3 samplePowerCosine(glm::vec2 u, float s) {
    return sphericalDirection(std::pow(1.0f - u.x, 1.0f / (s + 1.0f)), u.y);
}
inline float powerCosinePdf(float cosTheta, float s) {
    if (cosTheta <= 0.0f) return 0.0f;
    return (s + 1.0f) / (2.0f * kPi) * (s > 0.0f ? std::pow(cosTheta, s) : 1.0f);
}

// GGX (Trowbridge-Reitz) with roughness α: the normal distribution D(h) (cos θh = h.z, local frame).
inline float ggxD(float cosThetaH, float alpha) {
    if (cosThetaH <= 0.0f) return 0.0f;
    const float a2 = alpha * alpha, c2 = cosThetaH * cosThetaH;
    const float d = c2 * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}

// Smith's masking G1 for GGX: 2 cos θ / (cos θ + sqrt(α² + (1 − α²) cos² θ)).
inline float ggxG1(float cosTheta, float alpha) {
    if (cosTheta <= 0.0f) return 0.0f;
    const float a2 = alpha * alpha;
    return 2.0f * cosTheta / (cosTheta + std::sqrt(a2 + (1.0f - a2) * cosTheta * cosTheta));
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals" (JCGT 7(4)): sampleGgxVisibleNormal (below)
// draws a micro-normal h seen from local direction v (v.z > 0) with density D_v(h) = G1(v) max(0, v·h) D(h) / v.z.
inline float ggxVisibleNormalPdf(const glm::vec3& v, const glm::vec3& h, float alpha) {
    if (v.z <= 0.0f) return 0.0f;
    return ggxG1(v.z, alpha) * std::max(0.0f, glm::dot(v, h)) * ggxD(h.z, alpha) / v.z;
}

// Anisotropic GGX with widths (ax, ay) along the local x and y axes: lighting.glsl's D_GTR2Aniso (Burley 2012,
// eq. 13) and Smith's G1 = 2 cos θ · smithGGXAniso (Heitz 2014, eq. 86), in the local frame.
inline float ggxAnisoD(const glm::vec3& h, float ax, float ay) {
    return h.z > 0.0f ? shading::D_GTR2Aniso(h.z, h.x, h.y, ax, ay) : 0.0f;
}
inline float ggxAnisoG1(const glm::vec3& v, float ax, float ay) {
    return v.z > 0.0f ? 2.0f * v.z * shading::smithGGXAniso(v.z, v.x, v.y, ax, ay) : 0.0f;
}

// Heitz 2018 with two widths: the hemisphere configuration stretches x by ax and y by ay, and the sampled normal
// is stretched back. Density D_v(h) = G1(v) max(0, v·h) D(h) / v.z, as the isotropic sampler.
inline glm::vec3 sampleGgxAnisoVisibleNormal(const glm::vec3& v, float ax, float ay, glm::vec2 u) {
    const glm::vec3 vh = glm::normalize(glm::vec3(ax * v.x, ay * v.y, v.z));
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lensq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1.0f + vh.z);
    p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * p2;
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(glm::vec3(ax * nh.x, ay * nh.y, std::max(1e-6f, nh.z)));
}
// The isotropic sampler is the anisotropic one with equal widths: the same operations, the same bits.
inline glm::vec3 sampleGgxVisibleNormal(const glm::vec3& v, float alpha, glm::vec2 u) {
    return sampleGgxAnisoVisibleNormal(v, alpha, alpha, u);
}
inline float ggxAnisoVisibleNormalPdf(const glm::vec3& v, const glm::vec3& h, float ax, float ay) {
    if (v.z <= 0.0f) return 0.0f;
    return ggxAnisoG1(v, ax, ay) * std::max(0.0f, glm::dot(v, h)) * ggxAnisoD(h, ax, ay) / v.z;
}

// Burley 2012, Appendix B: GTR1 (the clearcoat's distribution, γ = 1) by its cos θh,
// cos² θh = (1 − α^(2(1 − u))) / (1 − α²); density D(h)·cos θh (lighting.glsl's D_GTR1) over the micro-normal's
// solid angle.
inline float gtr1D(float cosThetaH, float alpha) {
    return cosThetaH > 0.0f ? shading::D_GTR1(cosThetaH, 1.0f - cosThetaH * cosThetaH, alpha) : 0.0f;
}
inline glm::vec3 sampleGtr1Normal(glm::vec2 u, float alpha) {
    const float a2 = std::min(alpha * alpha, 0.9999f);
    const float cos2 = (1.0f - std::pow(a2, 1.0f - u.x)) / (1.0f - a2);
    return sphericalDirection(std::sqrt(std::clamp(cos2, 0.0f, 1.0f)), u.y);
}
inline float gtr1NormalPdf(float cosThetaH, float alpha) { return gtr1D(cosThetaH, alpha) * std::max(cosThetaH, 0.0f); }

// A uniform point on a triangle as barycentrics (b1, b2) (Heitz 2019's low-distortion map is not needed:
// the square-root map, pbrt-v3 §13.6.5).
inline glm::vec2 sampleTriangleBarycentrics(glm::vec2 u) {
    const float su = std::sqrt(u.x);
    return {1.0f - su, u.y * su};
}

// Mirror of v about unit n.
inline glm::vec3 reflectAbout(const glm::vec3& v, const glm::vec3& n) { return 2.0f * glm::dot(n, v) * n - v; }

// Veach 1997's power heuristic (β = 2) for a sample from strategy f against strategy g.
inline float powerHeuristic(float pdfF, float pdfG) {
    const float f = pdfF * pdfF, g = pdfG * pdfG;
    return f + g > 0.0f ? f / (f + g) : 0.0f;
}

}  // namespace shadelab::trace
