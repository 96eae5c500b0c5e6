// PrefilteredEnvironment and DfgLut: the split-sum image-based lighting data (Karis 2013) as plain arrays,
// computed once on the CPU (prefilter.h, dfg_lut.h) and read identically by both renderers: the tracer
// through ibl_lookup.h, the rasterizer by uploading the same floats (src/raster/ibl_textures.h). No GL.
#pragma once

#include <array>
#include <glm/vec3.hpp>
#include <vector>

namespace shadelab::shading {

// The prefiltered specular cube, every level in one RGB float atlas. Level l has faces of
// n = iblFaceSize(size, l) texels per side (size, then size/4, size/8, ..., at least 8) plus a one-texel
// border holding the neighbouring faces' radiance (filtered for the border texel's own direction), so
// bilinear lookups never cross a face. Level l occupies atlas rows [iblLevelRow(size, l), + n + 2) and face
// f the columns [f·(n + 2), (f + 1)·(n + 2)); faces are +X −X +Y −Y +Z −Z with cube_face.glsl's coordinates
// (shaders/ibl.glsl). Level l is GGX-prefiltered at roughness l / (levels − 1); level 0 is the environment.
struct PrefilteredEnvironment {
    int size = 0;                   // texels per face side at level 0, a power of two
    int levels = 0;                 // prefiltered roughness levels, >= 2
    int atlasWidth = 0;             // 6·(size + 2)
    int atlasHeight = 0;            // iblLevelRow(size, levels)
    std::vector<float> atlas;       // atlasWidth·atlasHeight RGB texels, row-major
    std::array<glm::vec3, 9> sh{};  // irradiance SH9, convolved with the cosine and divided by π
};

// The split-sum DFG table: (A, B) with ∫ f·N·L dω = F0·A + B for the GGX lobe with Schlick Fresnel (F = 1:
// A + B), at N·V = i/(size − 1) (at least 0.001) and roughness j/(size − 1).
struct DfgLut {
    int size = 0;
    std::vector<float> ab;  // size·size (A, B) pairs, row j = roughness
};

}  // namespace shadelab::shading
