// libFuzzer target: glTF import of arbitrary bytes, as glTF text and as GLB, with external files refused.
// Every input must import or raise an InputError. Built only with -DSHADELAB_FUZZ=ON and clang.
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
    } catch (const shadelab::InputError&) {}
    return 0;
}
