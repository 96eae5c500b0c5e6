// Fuzz target: the Radiance .hdr parser, then the environment prefilter on what it returns, held to
// kMaxRadiance as loadPrefilteredHdr (scene/environment_load.cpp) holds it. Every input must decode or raise an
// InputError; a decoded map must prefilter to finite texels and finite SH coefficients (RGBE reaches 1.7e38, and
// the bound is what keeps the prefilter's sums finite), or the target aborts. A 16-texel cube with few samples
// keeps one case fast; the sums it overflows are the same at every size.
#include "fuzz_outcome.h"
#include "image/hdr.h"
#include "scene/scene_limits.h"
#include "shading/prefilter.h"
#include "util/input_error.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

void requireFinite(float v, const char* what, size_t index) {
    if (std::isfinite(v)) return;
    std::fprintf(stderr, "hdr_fuzz: prefiltered %s[%zu] is %g, not finite\n", what, index, double(v));
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace shadelab;
    HdrImage hdr;
    try {
        hdr = parseHdr(std::string(reinterpret_cast<const char*>(data), size), "fuzz.hdr");
    } catch (const InputError& e) {
        fuzz::noteOutcome(e.what());
        return 0;
    }
    shading::EquirectMap map;
    map.width = hdr.width;
    map.height = hdr.height;
    map.rgb = std::move(hdr.rgb);
    for (float& v : map.rgb) v = std::min(v, kMaxRadiance);
    shading::PrefilterSettings settings;
    settings.size = 16;
    settings.samples = 4;
    settings.threads = 1;
    const shading::PrefilteredEnvironment env = shading::prefilterEnvironment(map, settings);
    for (size_t i = 0; i < env.atlas.size(); ++i) requireFinite(env.atlas[i], "atlas", i);
    for (size_t i = 0; i < env.sh.size(); ++i)
        for (int c = 0; c < 3; ++c) requireFinite(env.sh[i][c], "sh", i * 3 + size_t(c));
    fuzz::noteOutcome("ok");
    return 0;
}
