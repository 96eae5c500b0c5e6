// IblTextures: the rasterizer's copy of the split-sum data: the prefiltered atlas of a scene's environment
// map (RGB32F) and the DFG table (RG32F), uploaded as the exact floats the tracer reads
// (shading/environment_map.h) and read with texelFetch, so the shaders filter them by hand as the tracer
// does (shaders/ibl.glsl). Uploads only when the map changes. Not the lookups, not the prefilter.
#pragma once

#include "gl/objects.h"
#include "shading/environment_map.h"

#include <cstdint>
#include <memory>

namespace shadelab::raster {

class IblTextures {
public:
    // Makes `map` (may be null: nothing to upload) current, and the DFG table when `needDfg` (it costs tens
    // of milliseconds to compute the first time); cheap when unchanged.
    void prepare(const std::shared_ptr<const shading::PrefilteredEnvironment>& map, bool needDfg);
    // Binds the atlas to texture unit `cubeUnit` and the DFG table to `dfgUnit`.
    void bind(unsigned cubeUnit, unsigned dfgUnit) const;
    // Bumped by every upload of a new map (part of what the reflection cubes depend on).
    uint64_t generation() const { return generation_; }

private:
    gl::Texture atlas_, dfg_;
    // Held, so that a new map can never reuse the address of the one uploaded and be mistaken for it.
    std::shared_ptr<const shading::PrefilteredEnvironment> uploaded_;
    uint64_t generation_ = 0;
};

}  // namespace shadelab::raster
