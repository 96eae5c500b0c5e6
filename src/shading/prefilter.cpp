// prefilterEnvironment: equirect → source cube and its box mips → GGX-prefiltered atlas levels + SH9.
// Work is split by atlas rows over std::thread workers; each texel's result depends only on its own
// direction, so the output is the same for any thread count.
#include "shading/prefilter.h"

#include "shading/dfg_lut.h"
#include "shading/ibl_lookup.h"
#include "util/parallel_for.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace shadelab::shading {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr int kCoarsestMipSkipped = 4;  // mips of 8², 4², 2², 1² per face are never read (see lobeSamples)
constexpr float kMipBias = 1.0f;  // GPU Gems 3 ch. 20: one mip coarser than the sample's footprint, against fireflies

// One face-set of a source mip: 6 faces of n×n RGB texels, no border.
struct SourceLevel {
    int n = 0;
    std::vector<float> rgb;  // face-major: ((face·n + y)·n + x)·3
    const float* texel(int face, int x, int y) const {
        return &rgb[((size_t(face) * size_t(n) + size_t(y)) * size_t(n) + size_t(x)) * 3];
    }
};

glm::vec3 sampleEquirect(const EquirectMap& m, glm::vec3 d) {
    float u, v;
    equirectCoords(d, u, v);
    const float fx = u * float(m.width) - 0.5f;
    const float fy = std::clamp(v * float(m.height) - 0.5f, 0.0f, float(m.height - 1));
    const int x0 = int(std::floor(fx)), y0 = std::min(int(std::floor(fy)), std::max(m.height - 2, 0));
    const float tx = fx - float(x0), ty = std::clamp(fy - float(y0), 0.0f, 1.0f);
    const auto at = [&](int x, int y) {
        x = ((x % m.width) + m.width) % m.width;  // wraps in longitude
        y = std::clamp(y, 0, m.height - 1);
        const float* t = &m.rgb[(size_t(y) * size_t(m.width) + size_t(x)) * 3];
        return glm::vec3(t[0], t[1], t[2]);
    };
    const glm::vec3 a = glm::mix(at(x0, y0), at(x0 + 1, y0), tx);
    const glm::vec3 b = glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx);
    return glm::mix(a, b, ty);
}

// Bilinear inside one face of a source level, clamped at its edges. The face and its coordinates are
// cube_face.glsl's (cubeFace, cubeFaceCoords), written out with one reciprocal: this is the prefilter's
// innermost loop (the lookups at render time use ibl.glsl's own).
glm::vec3 sampleSource(const SourceLevel& s, glm::vec3 d) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    int face;
    float u, v, ma;
    if (ax >= ay && ax >= az) {
        face = d.x > 0.0f ? 0 : 1;
        ma = ax;
        u = d.x > 0.0f ? d.z : -d.z;
        v = d.y;
    } else if (ay >= az) {
        face = d.y > 0.0f ? 2 : 3;
        ma = ay;
        u = d.y > 0.0f ? d.x : -d.x;
        v = d.z;
    } else {
        face = d.z > 0.0f ? 4 : 5;
        ma = az;
        u = d.z > 0.0f ? -d.x : d.x;
        v = d.y;
    }
    const float half = 0.5f * float(s.n) / ma;
    const float fx = std::clamp(u * half + 0.5f * float(s.n) - 0.5f, 0.0f, float(s.n - 1));
    const float fy = std::clamp(v * half + 0.5f * float(s.n) - 0.5f, 0.0f, float(s.n - 1));
    const int x0 = std::min(int(fx), std::max(s.n - 2, 0)), y0 = std::min(int(fy), std::max(s.n - 2, 0));
    const int x1 = std::min(x0 + 1, s.n - 1), y1 = std::min(y0 + 1, s.n - 1);
    const float tx = fx - float(x0), ty = fy - float(y0);
    const float *a = s.texel(face, x0, y0), *b = s.texel(face, x1, y0), *c = s.texel(face, x0, y1),
                *e = s.texel(face, x1, y1);
    glm::vec3 r;
    for (int k = 0; k < 3; ++k) {
        const float top = a[k] + (b[k] - a[k]) * tx, bottom = c[k] + (e[k] - c[k]) * tx;
        r[k] = top + (bottom - top) * ty;
    }
    return r;
}

// A GGX sample of one rough level in the frame N = V = R = +z: L, its N·L weight and its source mip.
struct LobeSample {
    glm::vec3 L;
    float weight;
    int mip;
};

std::vector<LobeSample> lobeSamples(float roughness, int samples, int sourceSize, int sourceLevels) {
    std::vector<LobeSample> out;
    const float a = pbrAlpha(roughness);
    const float texelSolidAngle = 4.0f * kPi / (6.0f * float(sourceSize) * float(sourceSize));
    for (int k = 0; k < samples; ++k) {
        float u, v;
        hammersley(unsigned(k), unsigned(samples), u, v);
        const glm::vec3 H = importanceSampleGGX(u, v, a);
        const glm::vec3 L = 2.0f * H.z * H - glm::vec3(0.0f, 0.0f, 1.0f);
        if (L.z <= 0.0f) continue;
        // pdf(L) = D·N·H / (4 V·H) = D/4 for N = V; the sample stands for a solid angle 1/(samples·pdf),
        // read from the mip whose texels cover about that much (+1: GPU Gems 3 ch. 20's bias).
        const float NoH = H.z;
        const float D = D_GGX(NoH, H.x * H.x + H.y * H.y, a);
        const float sampleSolidAngle = 1.0f / (float(samples) * D * 0.25f + 1e-6f);
        // Never a mip with faces under 16² texels: bilinear reads clamped at the edges of a 4² or
        // 2² face weight its texels unevenly, which shifts a small bright source's energy by up to 10 %.
        const float coarsest = float(std::max(sourceLevels - 1 - kCoarsestMipSkipped, 0));
        const float mip = std::clamp(0.5f * std::log2(sampleSolidAngle / texelSolidAngle) + kMipBias, 0.0f, coarsest);
        out.push_back({L, L.z, int(std::lround(mip))});
    }
    return out;
}

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": tangents of unit n.
void basis(glm::vec3 n, glm::vec3& t, glm::vec3& b) {
    const float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sgn + n.z), c = n.x * n.y * a;
    t = glm::vec3(1.0f + sgn * n.x * n.x * a, sgn * c, -sgn * n.x);
    b = glm::vec3(c, sgn + n.y * n.y * a, -n.y);
}

void projectSH(const SourceLevel& s, std::array<glm::vec3, 9>& sh) {
    std::array<double, 27> acc{};
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < s.n; ++y)
            for (int x = 0; x < s.n; ++x) {
                const float fx = 2.0f * (float(x) + 0.5f) / float(s.n) - 1.0f;
                const float fy = 2.0f * (float(y) + 0.5f) / float(s.n) - 1.0f;
                const glm::vec3 d = cubeDirection(face, fx, fy);
                const float r2 = 1.0f + fx * fx + fy * fy;
                const float dw = (2.0f / float(s.n)) * (2.0f / float(s.n)) / (r2 * std::sqrt(r2));
                const float Y[9] = {0.282095f,
                                    0.488603f * d.y,
                                    0.488603f * d.z,
                                    0.488603f * d.x,
                                    1.092548f * d.x * d.y,
                                    1.092548f * d.y * d.z,
                                    0.315392f * (3.0f * d.z * d.z - 1.0f),
                                    1.092548f * d.x * d.z,
                                    0.546274f * (d.x * d.x - d.y * d.y)};
                const float* c = s.texel(face, x, y);
                for (int i = 0; i < 9; ++i)
                    for (int k = 0; k < 3; ++k) acc[size_t(i * 3 + k)] += double(c[k] * Y[i] * dw);
            }
    // Ramamoorthi & Hanrahan 2001: the clamped cosine's bands are π, 2π/3, π/4; divided by π.
    const float band[9] = {1.0f, 2.0f / 3.0f, 2.0f / 3.0f, 2.0f / 3.0f, 0.25f, 0.25f, 0.25f, 0.25f, 0.25f};
    for (int i = 0; i < 9; ++i)
        sh[size_t(i)] = band[i] * glm::vec3(float(acc[size_t(i * 3)]), float(acc[size_t(i * 3 + 1)]),
                                            float(acc[size_t(i * 3 + 2)]));
}

PrefilteredEnvironment emptyAtlas(int size) {
    PrefilteredEnvironment env;
    env.size = size;
    env.levels = prefilterLevels(size);
    env.atlasWidth = 6 * (size + 2);
    env.atlasHeight = IblLookup{}.iblLevelRow(size, env.levels);
    env.atlas.assign(size_t(env.atlasWidth) * size_t(env.atlasHeight) * 3, 0.0f);
    return env;
}

}  // namespace

int prefilterLevels(int) { return kPrefilterLevels; }

glm::vec3 equirectDirection(float u, float v) {
    const float phi = (u - 0.5f) * 2.0f * kPi, theta = v * kPi;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

void equirectCoords(glm::vec3 d, float& u, float& v) {
    d = glm::normalize(d);
    u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
    v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
}

glm::vec3 cubeDirection(int face, float x, float y) {
    const int axis = face / 2;
    const float sgn = face % 2 == 0 ? 1.0f : -1.0f;
    glm::vec3 d = axis == 0   ? glm::vec3(sgn, y, sgn * x)
                  : axis == 1 ? glm::vec3(sgn * x, sgn, y)
                              : glm::vec3(-sgn * x, y, sgn);
    return glm::normalize(d);
}

PrefilteredEnvironment prefilterEnvironment(const EquirectMap& map, const PrefilterSettings& settings) {
    const int size = settings.size;
    const int threads = settings.threads > 0 ? settings.threads : std::max(1, int(std::thread::hardware_concurrency()));
    PrefilteredEnvironment env = emptyAtlas(size);

    // Source cube (size² per face) and its box-filtered mips down to 1².
    std::vector<SourceLevel> source(1);
    source[0].n = size;
    source[0].rgb.assign(size_t(6) * size_t(size) * size_t(size) * 3, 0.0f);
    parallelFor(6 * size, threads, [&](int task) {
        const int face = task / size, y = task % size;
        for (int x = 0; x < size; ++x) {
            const glm::vec3 c = sampleEquirect(map, cubeDirection(face, 2.0f * (float(x) + 0.5f) / float(size) - 1.0f,
                                                                  2.0f * (float(y) + 0.5f) / float(size) - 1.0f));
            float* t = &source[0].rgb[((size_t(face) * size_t(size) + size_t(y)) * size_t(size) + size_t(x)) * 3];
            t[0] = c.x, t[1] = c.y, t[2] = c.z;
        }
    });
    while (source.back().n > 1) {
        const SourceLevel& up = source.back();
        SourceLevel down;
        down.n = up.n / 2;
        down.rgb.resize(size_t(6) * size_t(down.n) * size_t(down.n) * 3);
        for (int face = 0; face < 6; ++face)
            for (int y = 0; y < down.n; ++y)
                for (int x = 0; x < down.n; ++x)
                    for (int k = 0; k < 3; ++k)
                        down.rgb[((size_t(face) * size_t(down.n) + size_t(y)) * size_t(down.n) + size_t(x)) * 3 +
                                 size_t(k)] =
                            0.25f * (up.texel(face, 2 * x, 2 * y)[k] + up.texel(face, 2 * x + 1, 2 * y)[k] +
                                     up.texel(face, 2 * x, 2 * y + 1)[k] + up.texel(face, 2 * x + 1, 2 * y + 1)[k]);
        source.push_back(std::move(down));
    }

    std::vector<std::vector<LobeSample>> lobes(size_t(env.levels));
    // Wider lobes take more samples (doubling per level, on ever fewer texels): each sample then covers a
    // solid angle small enough to read a mip of 16² or finer, and a small bright source (a sun) spreads
    // smoothly instead of showing as one blob per sample.
    for (int l = 1; l < env.levels; ++l)
        lobes[size_t(l)] =
            lobeSamples(float(l) / float(env.levels - 1), settings.samples << (l - 1), size, int(source.size()));

    // One task per atlas row of every level.
    parallelFor(env.atlasHeight, threads, [&](int row) {
        int level = 0;
        while (level + 1 < env.levels && IblLookup{}.iblLevelRow(size, level + 1) <= row) ++level;
        const int n = IblLookup{}.iblFaceSize(size, level);
        const int j = row - IblLookup{}.iblLevelRow(size, level) - 1;  // -1 .. n: border rows included
        const float y = 2.0f * (float(j) + 0.5f) / float(n) - 1.0f;
        for (int face = 0; face < 6; ++face)
            for (int i = -1; i <= n; ++i) {
                const float x = 2.0f * (float(i) + 0.5f) / float(n) - 1.0f;
                const glm::vec3 N = cubeDirection(face, x, y);
                glm::vec3 c(0.0f);
                if (level == 0 && i >= 0 && i < n && j >= 0 && j < n) {
                    const float* t = source[0].texel(face, i, j);  // the same direction, already sampled
                    c = glm::vec3(t[0], t[1], t[2]);
                } else if (level == 0) {
                    c = sampleEquirect(map, N);  // border texels: the neighbouring face's radiance
                } else {
                    glm::vec3 T, B;
                    basis(N, T, B);
                    float total = 0.0f;
                    for (const LobeSample& s : lobes[size_t(level)]) {
                        const glm::vec3 L = s.L.x * T + s.L.y * B + s.L.z * N;
                        c += s.weight * sampleSource(source[size_t(s.mip)], L);
                        total += s.weight;
                    }
                    c /= std::max(total, 1e-20f);
                }
                float* t = &env.atlas[(size_t(row) * size_t(env.atlasWidth) + size_t(face * (n + 2) + i + 1)) * 3];
                t[0] = c.x, t[1] = c.y, t[2] = c.z;
            }
    });

    // Irradiance from the 32² (or smaller) source level: SH9 needs no finer detail.
    size_t shLevel = 0;
    while (shLevel + 1 < source.size() && source[shLevel].n > 32) ++shLevel;
    projectSH(source[shLevel], env.sh);
    return env;
}

PrefilteredEnvironment uniformEnvironment(glm::vec3 radiance, int size) {
    PrefilteredEnvironment env = emptyAtlas(size);
    for (size_t i = 0; i < env.atlas.size(); i += 3) {
        env.atlas[i] = radiance.x;
        env.atlas[i + 1] = radiance.y;
        env.atlas[i + 2] = radiance.z;
    }
    env.sh[0] = radiance / 0.282095f;
    return env;
}

}  // namespace shadelab::shading
