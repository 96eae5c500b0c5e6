// loadEnvironment: reads the scene's environment .hdr and prefilters it once on the CPU (shading/prefilter.h),
// so that both renderers and every copy of the scene share one PrefilteredEnvironment. Not the parser
// (scene_json.cpp) and not the lookups (shading/ibl_lookup.h).
#pragma once

#include "scene/scene.h"
#include "shading/prefilter.h"

#include <cstdint>
#include <string>

namespace shadelab {

// A memory limit that a load is held to, with the name the front end gives it (`--max-memory`, `max_memory`)
// for the message. bytes 0: no limit.
struct MemoryLimit {
    uint64_t bytes = 0;
    std::string name;
};

// The most memory reading and prefiltering a width x height .hdr file of `fileBytes` bytes takes at once: the
// file's bytes, its pixels as floats, the prefilter's source cube with its mips and the atlas it fills, and
// the process itself. An estimate for refusing: it errs on the generous side.
uint64_t environmentLoadBytes(int width, int height, uint64_t fileBytes,
                              const shading::PrefilterSettings& settings = {});

// Fills scene.environment->map from its `hdr` (a path relative to `baseDir`, as a mesh's `source`, or
// absolute); does nothing without an environment or for a uniform one. Throws InputError naming the file;
// with a limit, also when environmentLoadBytes exceeds it, from the file's size and header, before a pixel is
// decoded.
void loadEnvironment(Scene& scene, const std::string& baseDir, const shading::PrefilterSettings& settings = {},
                     const MemoryLimit& limit = {});

// The prefiltered map of one .hdr file (no cache: every call reads and prefilters), held to `limit` as
// loadEnvironment is.
std::shared_ptr<const shading::PrefilteredEnvironment> loadPrefilteredHdr(
    const std::string& path, const shading::PrefilterSettings& settings = {}, const MemoryLimit& limit = {});

}  // namespace shadelab
