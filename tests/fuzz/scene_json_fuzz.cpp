// Fuzz target: the scene JSON loader must turn any bytes into a Scene or an InputError, never a crash, hang or
// sanitizer report. A scene that loads must also save and load again: a refusal of the saved text aborts.
// Built with libFuzzer (-DSHADELAB_FUZZ=ON, clang; tests/fuzz/run.sh) or with the standalone driver
// (standalone_driver.cpp) in every build with tests.
#include "fuzz_outcome.h"
#include "scene/scene_json.h"
#include "util/input_error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    shadelab::Scene s;
    try {
        s = shadelab::parseSceneJson(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    } catch (const shadelab::InputError& e) {
        shadelab::fuzz::noteOutcome(e.what());
        return 0;
    }
    try {
        shadelab::parseSceneJson(shadelab::sceneToJson(s), "fuzz-resaved.json");
    } catch (const shadelab::InputError& e) {
        std::fprintf(stderr, "scene_json_fuzz: a loaded scene, saved, does not load again: %s\n", e.what());
        std::abort();
    }
    shadelab::fuzz::noteOutcome("ok");
    return 0;
}
