// SurfacePasses: what the camera sees first at each pixel, beside the colour: the surface's albedo, its
// shading normal and its depth. The denoiser keeps apart what they tell apart (image/denoise.h), and
// `render --passes` writes them as image layers. Traced at pixel centres (trace/first_hit_passes.h); the
// background has albedo 0, normal 0 and depth 0. Plain data, row 0 at the top.
#pragma once

#include <cstddef>
#include <vector>

namespace shadelab {

struct SurfacePasses {
    int width = 0, height = 0;
    std::vector<float> albedo;  // 3 per pixel, linear RGB: the diffuse plus specular colour, or the base colour
    std::vector<float> normal;  // 3 per pixel, unit, world space, toward the camera
    std::vector<float> depth;   // 1 per pixel: distance along the camera's forward axis, world units

    SurfacePasses() = default;
    SurfacePasses(int w, int h)
        : width(w),
          height(h),
          albedo(size_t(w) * size_t(h) * 3, 0.0f),
          normal(size_t(w) * size_t(h) * 3, 0.0f),
          depth(size_t(w) * size_t(h), 0.0f) {}
};

}  // namespace shadelab
