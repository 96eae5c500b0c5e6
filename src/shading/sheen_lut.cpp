// computeSheenLut: the sheen's albedo by importance sampling its fibre normals (D_Charlie·N·H), with
// gltf_layers.glsl's own lobe terms, so the table matches the BRDF the renderers evaluate.
#include "shading/sheen_lut.h"

#include "shading/dfg_lut.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab::shading {

glm::vec3 importanceSampleCharlie(float u, float v, float alpha) {
    const float sinTheta = std::pow(u, alpha / (2.0f * alpha + 1.0f));
    const float cosTheta = std::sqrt(std::max(0.0f, 1.0f - sinTheta * sinTheta));
    const float phi = 2.0f * SL_PI * v;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

SheenLut computeSheenLut(int size, int samples) {
    SheenLut lut;
    lut.size = size;
    lut.e.assign(size_t(size) * size_t(size), 0.0f);
    std::vector<glm::vec3> normals(static_cast<size_t>(samples));
    for (int j = 0; j < size; ++j) {
        const float roughness = float(j) / float(size - 1);
        const float a = sheenAlpha(roughness);
        // The fibre normals depend on the row's α alone: drawn once for its texels.
        for (int k = 0; k < samples; ++k) {
            float u, v;
            hammersley(unsigned(k), unsigned(samples), u, v);
            normals[size_t(k)] = importanceSampleCharlie(u, v, a);
        }
        for (int i = 0; i < size; ++i) {
            const float NoV = std::max(float(i) / float(size - 1), 1e-3f);  // N·V = 0 has no view direction
            const glm::vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
            const float lambdaV = 1.0f + sheenLambda(NoV, a);
            double E = 0.0;
            for (const glm::vec3& H : normals) {
                const float VoH = glm::dot(V, H);
                if (VoH <= 0.0f || H.z <= 0.0f) continue;
                const float NoL = 2.0f * VoH * H.z - V.z;  // L = 2 (V·H) H − V
                if (NoL <= 0.0f) continue;
                // f·N·L / pdf(L) with pdf(L) = D·N·H / (4 V·H) and f·N·L = sheenLobe/π = D / (4 N·V (1 + Λ(N·V) +
                // Λ(N·L))): the D cancels.
                E += double(VoH / (NoV * H.z * (lambdaV + sheenLambda(NoL, a))));
            }
            lut.e[size_t(j) * size_t(size) + size_t(i)] = float(E / samples);
        }
    }
    return lut;
}

const SheenLut& sheenLut() {
    static const SheenLut lut = computeSheenLut();
    return lut;
}

}  // namespace shadelab::shading
