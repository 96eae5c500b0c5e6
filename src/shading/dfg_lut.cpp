// computeDfgLut: the split-sum table by importance sampling (Karis 2013, "Real Shading in Unreal Engine 4",
// IntegrateBRDF), with lighting.glsl's own visibility term and α so the table matches the BRDF.
#include "shading/dfg_lut.h"

#include "shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace shadelab::shading {

void hammersley(unsigned i, unsigned n, float& u, float& v) {
    uint32_t bits = i;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    u = (float(i) + 0.5f) / float(n);
    v = float(bits) * 2.3283064365386963e-10f;
}

glm::vec3 importanceSampleGGX(float u, float v, float alpha) {
    const float phi = 2.0f * SL_PI * v;
    const float cosTheta = std::sqrt((1.0f - u) / (1.0f + (alpha * alpha - 1.0f) * u));
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

DfgLut computeDfgLut(int size, int samples) {
    DfgLut lut;
    lut.size = size;
    lut.ab.assign(size_t(size) * size_t(size) * 2, 0.0f);
    for (int j = 0; j < size; ++j) {
        const float roughness = float(j) / float(size - 1);
        const float a = pbrAlpha(roughness);
        for (int i = 0; i < size; ++i) {
            const float NoV = std::max(float(i) / float(size - 1), 1e-3f);  // N·V = 0 has no view direction
            const glm::vec3 V(std::sqrt(1.0f - NoV * NoV), 0.0f, NoV);
            double A = 0.0, B = 0.0;
            for (int k = 0; k < samples; ++k) {
                float u, v;
                hammersley(unsigned(k), unsigned(samples), u, v);
                const glm::vec3 H = importanceSampleGGX(u, v, a);
                const float VoH = glm::dot(V, H);
                const glm::vec3 L = 2.0f * VoH * H - V;
                const float NoL = L.z, NoH = H.z;
                if (NoL <= 0.0f || VoH <= 0.0f) continue;
                // f·N·L / pdf(L) with pdf(L) = D·N·H / (4 V·H): the D cancels.
                const float gVis = V_SmithGGXCorrelated(NoV, NoL, a) * 4.0f * NoL * VoH / NoH;
                const float x = 1.0f - VoH, x2 = x * x, Fc = x2 * x2 * x;
                A += double((1.0f - Fc) * gVis);
                B += double(Fc * gVis);
            }
            float* t = &lut.ab[(size_t(j) * size_t(size) + size_t(i)) * 2];
            t[0] = float(A / samples);
            t[1] = float(B / samples);
        }
    }
    return lut;
}

const DfgLut& dfgLut() {
    static const DfgLut lut = computeDfgLut();
    return lut;
}

}  // namespace shadelab::shading
