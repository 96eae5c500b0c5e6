// EnvironmentSampler: the texel distribution over level 0 of the prefiltered cube (environment_map.h).
#include "trace/path/environment_sampler.h"

#include "shading/environment_map.h"
#include "shading/ibl_lookup.h"
#include "trace/path/warp.h"

#include <cmath>
#include <glm/trigonometric.hpp>

namespace shadelab::trace {
namespace {

float luminance(const float* rgb) { return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2]; }

}  // namespace

glm::vec3 EnvironmentSampler::faceDirection(int face, float x, float y) {
    switch (face) {
        case 0: return {1.0f, y, x};
        case 1: return {-1.0f, y, -x};
        case 2: return {x, 1.0f, y};
        case 3: return {-x, -1.0f, y};
        case 4: return {-x, y, 1.0f};
        default: return {x, y, -1.0f};
    }
}

EnvironmentSampler::EnvironmentSampler(const Scene& scene) {
    const bool background = scene.background.x > 0.0f || scene.background.y > 0.0f || scene.background.z > 0.0f;
    if (!scene.environment) {
        emits_ = background;
        return;
    }
    const Environment& e = *scene.environment;
    cosRot_ = std::cos(glm::radians(e.rotation));
    sinRot_ = std::sin(glm::radians(e.rotation));
    map_ = e.map.get();
    if (!map_) {
        emits_ = background && e.intensity > 0.0f;
        return;
    }
    emits_ = e.intensity > 0.0f;
    n_ = shading::IblLookup{}.iblFaceSize(map_->size, 0);
    std::vector<double> lumSolid(size_t(6) * size_t(n_) * size_t(n_)), solid(lumSolid.size());
    double lumTotal = 0.0, solidTotal = 0.0;
    const float delta = 2.0f / float(n_);
    for (int f = 0; f < 6; ++f)
        for (int j = 0; j < n_; ++j)
            for (int i = 0; i < n_; ++i) {
                const float x = -1.0f + (float(i) + 0.5f) * delta, y = -1.0f + (float(j) + 0.5f) * delta;
                const float r2 = 1.0f + x * x + y * y;
                const double omega = double(delta) * delta / (double(r2) * std::sqrt(double(r2)));
                const size_t col = size_t(f) * size_t(n_ + 2) + size_t(i) + 1, row = size_t(j) + 1;
                const float* t = &map_->atlas[3 * (row * size_t(map_->atlasWidth) + col)];
                const size_t k = (size_t(f) * size_t(n_) + size_t(j)) * size_t(n_) + size_t(i);
                lumSolid[k] = std::max(0.0, double(luminance(t))) * omega;
                solid[k] = omega;
                lumTotal += lumSolid[k];
                solidTotal += omega;
            }
    std::vector<double> weights(lumSolid.size());
    for (size_t k = 0; k < weights.size(); ++k)
        weights[k] =
            (lumTotal > 0.0 ? 0.9 * lumSolid[k] / lumTotal : 0.9 * solid[k] / solidTotal) + 0.1 * solid[k] / solidTotal;
    texels_ = Distribution1D(weights);
}

EnvironmentDirection EnvironmentSampler::sample(glm::vec3 u) const {
    if (!map_) return {sampleUniformSphere(glm::vec2(u.y, u.z)), kUniformSpherePdf};
    const size_t k = texels_.sample(u.x);
    const int f = int(k / (size_t(n_) * size_t(n_)));
    const int j = int((k / size_t(n_)) % size_t(n_)), i = int(k % size_t(n_));
    const float delta = 2.0f / float(n_);
    const float x = -1.0f + (float(i) + u.y) * delta, y = -1.0f + (float(j) + u.z) * delta;
    const glm::vec3 m = faceDirection(f, x, y);
    const float r2 = glm::dot(m, m);
    const glm::vec3 map = m / std::sqrt(r2);
    // World direction: the map turned back (iblRotate with −rotation).
    const glm::vec3 world(cosRot_ * map.x + sinRot_ * map.z, map.y, -sinRot_ * map.x + cosRot_ * map.z);
    return {world, texels_.probability(k) / (delta * delta) * r2 * std::sqrt(r2)};
}

float EnvironmentSampler::pdf(const glm::vec3& dir) const {
    if (!map_) return kUniformSpherePdf;
    shading::IblLookup l;
    const glm::vec3 m = l.iblRotate(dir, cosRot_, sinRot_);
    const int f = l.cubeFace(m);
    const glm::vec3 fc = l.cubeFaceCoords(m, f);
    const float delta = 2.0f / float(n_);
    const int i = std::clamp(int((fc.x + 1.0f) / delta), 0, n_ - 1),
              j = std::clamp(int((fc.y + 1.0f) / delta), 0, n_ - 1);
    const size_t k = (size_t(f) * size_t(n_) + size_t(j)) * size_t(n_) + size_t(i);
    const float r2 = 1.0f + fc.x * fc.x + fc.y * fc.y;
    return texels_.probability(k) / (delta * delta) * r2 * std::sqrt(r2);
}

}  // namespace shadelab::trace
