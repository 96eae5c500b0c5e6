// loadEnvironment: reads the scene's environment .hdr and prefilters it once on the CPU (shading/prefilter.h),
// so that both renderers and every copy of the scene share one PrefilteredEnvironment. Not the parser
// (scene_json.cpp) and not the lookups (shading/ibl_lookup.h).
#pragma once

#include "scene/scene.h"
#include "shading/prefilter.h"

#include <string>

namespace shadelab {

// Fills scene.environment->map from its `hdr` (a path relative to `baseDir`, as a mesh's `source`, or
// absolute); does nothing without an environment or for a uniform one. Throws InputError naming the file.
void loadEnvironment(Scene& scene, const std::string& baseDir, const shading::PrefilterSettings& settings = {});

// The prefiltered map of one .hdr file (no cache: every call reads and prefilters).
std::shared_ptr<const shading::PrefilteredEnvironment> loadPrefilteredHdr(
    const std::string& path, const shading::PrefilterSettings& settings = {});

}  // namespace shadelab
