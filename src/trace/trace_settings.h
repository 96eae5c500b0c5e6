// TraceSettings: how the tracer renders one image (size, samples, threads, depth), as a plain struct. The
// front ends fill it from a render request (render/render_request.h); validate() is the tracer's own guard.
#pragma once

#include <cstdint>
#include <vector>

namespace shadelab::trace {

// Bounds on the Whitted ray tree within maxDepth (docs/lighting.md, "The tracer's ray tree"). A ray's weight is
// the componentwise product of the kr / kt factors along its path (1 for the camera ray); its contribution
// to the sample is weight ⊙ radiance. With kr + kt <= 1 the weights shrink and minWeight ends every path;
// with kr = kt = 1 they never do, and maxRays is what bounds the work.
struct RayTreeLimits {
    float minWeight = 1.0f / 255.0f;  // POV-Ray's adc_bailout: a child ray whose weight (max channel) is below
                                      // this is not traced; fraction of the sample, [0, 1]; 0 = off
    int maxRays = 1024;               // secondary (reflected + refracted) rays per camera sample, >= 0; -1 = no
                                      // limit. A full tree of depth d <= 9 (2^(d+1) - 2 rays) is never cut
};

struct TraceSettings {
    int width = 1280;       // pixels, >= 1
    int height = 720;       // pixels, >= 1
    int spp = 1;            // samples per pixel: k², a fixed k×k grid in each pixel (scene/sample_grid.h)
    int threads = 0;        // worker threads; 0 = std::thread::hardware_concurrency()
    int maxDepth = -1;      // secondary-ray depth, >= 0; -1 = the scene's maxDepth
    int tileSize = 32;      // tile edge, pixels, >= 1
    bool coverage = true;   // also fill the coverage buffer
    RayTreeLimits rayTree;  // pruning of secondary rays (weight threshold, per-sample ray budget)
};

// Throws SettingError (a std::invalid_argument, util/input_error.h) naming the field, e.g. "spp: expected a
// perfect square from 1 to 64 (1, 4, 9, 16, ...) ..., got 2".
void validate(const TraceSettings& s);

// k for spp = k² (validate() first).
int samplesPerAxis(const TraceSettings& s);

// Worker threads actually used: settings.threads, or every core when it is 0.
int resolveThreads(const TraceSettings& s);

}  // namespace shadelab::trace
