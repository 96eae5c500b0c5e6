// IblTextures: the rasterizer's copy of the split-sum data: the prefiltered atlas of a scene's environment
// map (RGB32F), the DFG table (RG32F) and the sheen's albedo table (R32F), uploaded as the exact floats the tracer
// reads (shading/environment_map.h) and read with texelFetch, so the shaders filter them by hand as the tracer does
// (shaders/ibl.glsl). Uploads only when the map changes. Not the lookups, not the prefilter.
#pragma once

#include "gl/objects.h"
#include "shading/environment_map.h"

#include <cstdint>
#include <memory>

namespace shadelab::raster {

class IblTextures {
public:
    // Makes `map` (may be null: nothing to upload) current, the DFG table when `needDfg` and the sheen's albedo
    // table (shading/sheen_lut.h) when `needSheen` (each costs tens of milliseconds to compute the first time);
    // cheap when unchanged.
    void prepare(const std::shared_ptr<const shading::PrefilteredEnvironment>& map, bool needDfg, bool needSheen);
    // Binds the atlas to texture unit `cubeUnit`, the DFG table to `dfgUnit` and the sheen's table to `sheenUnit`.
    void bind(unsigned cubeUnit, unsigned dfgUnit, unsigned sheenUnit) const;
    // Bumped by every upload of a new map (part of what the reflection cubes depend on).
    uint64_t generation() const { return generation_; }

private:
    gl::Texture atlas_, dfg_, sheen_;
    // Held, so that a new map can never reuse the address of the one uploaded and be mistaken for it.
    std::shared_ptr<const shading::PrefilteredEnvironment> uploaded_;
    uint64_t generation_ = 0;
};

}  // namespace shadelab::raster
