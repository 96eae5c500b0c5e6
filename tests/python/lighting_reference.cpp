// lighting_reference: the C++ shading functions (src/shading/lighting.h) evaluated row by row on a file of inputs,
// for test_lighting.py, which checks the vectorised shadelab.lighting against them. No Python, no numpy: plain
// scalar calls, so that the package's broadcasting and argument order are checked, not assumed.
//
// Input: rows of 27 float32: N L V (3 each), s, Il md ms base_color (3 each), metallic, roughness, model (0 phong,
// 1 blinn-phong, 2 pbr), diffuse, specular (0 or 1). Output: rows of 8 float32: specularPhong, specularBlinnPhong,
// the pbr specular BRDF (3, 0 where N·L <= 0), shadeLight (3).
#include "shading/lighting.h"

#include <cstdio>
#include <vector>

namespace {

using shadelab::shading::vec3;

vec3 at(const float* p) { return vec3(p[0], p[1], p[2]); }

}  // namespace

int main(int argc, char** argv) {
    namespace sh = shadelab::shading;
    if (argc != 3) {
        std::fprintf(stderr, "usage: lighting_reference IN OUT\n");
        return 2;
    }
    std::FILE* in = std::fopen(argv[1], "rb");
    std::FILE* out = std::fopen(argv[2], "wb");
    if (!in || !out) {
        std::fprintf(stderr, "lighting_reference: cannot open %s or %s\n", argv[1], argv[2]);
        return 1;
    }
    float row[27];
    while (std::fread(row, sizeof(float), 27, in) == 27) {
        const vec3 N = at(row), L = at(row + 3), V = at(row + 6);
        const float s = row[9];
        const vec3 Il = at(row + 10), md = at(row + 13), ms = at(row + 16), base = at(row + 19);
        const float metallic = row[22], roughness = row[23];
        const int model = int(row[24]);
        const bool diffuse = row[25] != 0.0f, specular = row[26] != 0.0f;
        const vec3 ggx =
            sh::dot(N, L) > 0.0f ? sh::specularGGX(N, L, V, sh::pbrF0(base, metallic), roughness) : vec3(0.0f);
        const vec3 shaded = sh::shadeLight(N, L, V, Il, md, ms, s, model, diffuse, specular);
        const float result[8] = {sh::specularPhong(N, L, V, s),
                                 sh::specularBlinnPhong(N, L, V, s),
                                 ggx.x,
                                 ggx.y,
                                 ggx.z,
                                 shaded.x,
                                 shaded.y,
                                 shaded.z};
        std::fwrite(result, sizeof(float), 8, out);
    }
    std::fclose(in);
    return std::fclose(out) == 0 ? 0 : 1;
}
