// prefilterEnvironment: an equirectangular radiance map → the split-sum PrefilteredEnvironment (Karis 2013),
// on the CPU, once, on every core, so that both renderers read the same data. No GL, no scene types.
#pragma once

#include "shading/environment_map.h"

#include <glm/vec3.hpp>
#include <vector>

namespace shadelab::shading {

// An equirectangular (latitude-longitude) radiance map: row 0 looks up (+y), the centre column looks
// along −z, u grows toward +x (equirectDirection).
struct EquirectMap {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width·height RGB, linear radiance
};

struct PrefilterSettings {
    int size = 256;    // texels per face side at level 0: a power of two in [16, 1024]
    int samples = 64;  // GGX samples per texel of each rough level
    int threads = 0;   // 0: std::thread::hardware_concurrency()
};

// Roughness levels 0, 0.2, ..., 1 (faces of size, size/4, size/8, ..., at least 8 texels: iblFaceSize).
inline constexpr int kPrefilterLevels = 6;

// kPrefilterLevels for every size (kept as a function for callers that ask per cube).
int prefilterLevels(int size);

// The direction of equirect pixel coordinates (u, v) in [0, 1]² and back.
glm::vec3 equirectDirection(float u, float v);
void equirectCoords(glm::vec3 d, float& u, float& v);

// The unit direction through face coordinates (x, y) of `face` (the inverse of cube_face.glsl's
// cubeFaceCoords; |x|, |y| may exceed 1 for border texels).
glm::vec3 cubeDirection(int face, float x, float y);

// Level l is the environment convolved with the GGX lobe of roughness l / (levels − 1) for N = V = R,
// weighted by N·L (Karis 2013), each sample read from a box-filtered mip of the source chosen by its pdf
// (Colbert & Křivánek 2007, GPU Gems 3 ch. 20) to avoid fireflies; the SH9 irradiance comes from the
// source cube (Ramamoorthi & Hanrahan 2001). The map must be non-empty; values are used as given.
PrefilteredEnvironment prefilterEnvironment(const EquirectMap& map, const PrefilterSettings& settings = {});

// The same data for a uniform environment of radiance `radiance` (every texel and the SH's DC term).
PrefilteredEnvironment uniformEnvironment(glm::vec3 radiance, int size = 16);

}  // namespace shadelab::shading
