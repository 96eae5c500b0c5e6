// The fixed k×k sample grid the rasterizer and the Whitted tracer both put in every pixel (spp = k²), so that
// their supersampled images agree sample for sample. This is the one rule for the sample counts it takes;
// the path tracer's random samples are not on it.
#pragma once

namespace shadelab {

inline constexpr int kMaxGridSamplesPerSide = 8;
inline constexpr int kMaxGridSamples = kMaxGridSamplesPerSide * kMaxGridSamplesPerSide;  // 64

// k for spp = k² with 1 <= k <= kMaxGridSamplesPerSide. Otherwise throws SettingError (util/input_error.h)
// for the field "spp", naming the nearest counts the grid takes.
int gridSamplesPerSide(int spp);

}  // namespace shadelab
