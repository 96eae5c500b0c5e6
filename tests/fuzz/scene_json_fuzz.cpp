// libFuzzer target: the scene JSON loader must turn any bytes into a Scene or an InputError, never a
// crash, hang or sanitizer report. Built only with -DSHADELAB_FUZZ=ON and clang (tests/fuzz/run.sh).
#include "scene/scene_json.h"
#include "util/input_error.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        shadelab::Scene s =
            shadelab::parseSceneJson(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
        // A scene that loads must also save and load again.
        shadelab::parseSceneJson(shadelab::sceneToJson(s), "fuzz-resaved.json");
    } catch (const shadelab::InputError&) {}
    return 0;
}
