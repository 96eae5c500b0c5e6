// libFuzzer target: glTF import of arbitrary bytes, as glTF text and as GLB, with external files refused.
// Every input must import or raise an InputError. Built with libFuzzer (-DSHADELAB_FUZZ=ON, clang) or with the
// standalone driver (standalone_driver.cpp) in every build with tests.
#include "fuzz_outcome.h"
#include "scene/gltf/gltf_import.h"
#include "util/input_error.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const bool binary = size >= 4 && bytes.compare(0, 4, "glTF") == 0;
    try {
        shadelab::importGltfBytes(bytes, binary, binary ? "fuzz.glb" : "fuzz.gltf");
        shadelab::fuzz::noteOutcome("ok");
    } catch (const shadelab::InputError& e) {
        shadelab::fuzz::noteOutcome(e.what());
    }
    return 0;
}
