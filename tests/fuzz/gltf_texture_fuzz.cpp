// Fuzz target: glTF with textures and KHR_texture_transform, imported from bytes (glTF text or GLB, external
// files refused, data: URIs allowed) and, when it imports, traced: an 8x6 image at 1 spp with the Whitted
// tracer of a Scene made as loadScene makes one of a bare model (scene/scene_load.cpp: no shadows or
// reflections, the model's lights or the default rig, a camera framing its bounds), so that texture sampling
// runs with whatever offsets, rotations, scales and texCoord sets the file holds. Every input must import or
// raise an InputError; an image must have no NaN or infinite pixel (numbers in a file must not make one), or the
// target aborts. The shading model follows the input's length, Phong or pbr, so both read the maps.
#include "fuzz_outcome.h"
#include "image/encode.h"
#include "scene/gltf/gltf_import.h"
#include "scene/scene_load.h"
#include "trace/trace_image.h"
#include "util/input_error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace shadelab;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const bool binary = size >= 4 && bytes.compare(0, 4, "glTF") == 0;
    GltfImport imported;
    try {
        imported = importGltfBytes(bytes, binary, binary ? "fuzz.glb" : "fuzz.gltf");
    } catch (const InputError& e) {
        fuzz::noteOutcome(e.what());
        return 0;
    }
    Scene scene;
    scene.terms.shadows = false;
    scene.terms.reflections = false;
    scene.model = size % 2 == 0 ? ShadingModel::Phong : ShadingModel::Pbr;
    Mesh mesh;
    mesh.name = "fuzz";
    mesh.parts = std::move(imported.parts);
    scene.meshes.push_back(std::move(mesh));
    const Bounds bounds = sceneBounds(scene);
    scene.lights = imported.lights.empty() ? defaultLightRig(bounds) : std::move(imported.lights);
    if (scene.lights.size() > size_t(kMaxLights)) scene.lights.resize(size_t(kMaxLights));
    scene.camera = frameBounds(bounds);

    trace::TraceSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.spp = 1;
    settings.threads = 1;
    settings.coverage = false;
    const trace::TraceOutput out = trace::traceImage(scene, settings);
    uint64_t nonFinite = 0;
    toImage8(out.color, Encoding::Srgb, DisplaySettings{}, &nonFinite);
    if (nonFinite > 0) {
        std::fprintf(stderr, "gltf_texture_fuzz: %llu of %d pixels are NaN or infinite\n",
                     (unsigned long long)nonFinite, settings.width * settings.height);
        std::abort();
    }
    fuzz::noteOutcome(scene.meshes[0].parts.empty() ? "ok: nothing to draw" : "ok: traced");
    return 0;
}
