// The standalone driver's negative control: a target that fails on purpose, so that ctest can show the driver
// sees each kind of failure its smoke runs rely on it to see. The input names the failure: "abort" aborts,
// "throw" raises an exception of a type no target documents (std::terminate, an abort), "hang" never returns
// (the driver's -timeout), "overflow" reads past a heap block (an AddressSanitizer report, in builds with it);
// anything else succeeds.
#include "fuzz_outcome.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    if (input == "abort") std::abort();
    if (input == "throw") throw std::runtime_error("an exception no target documents");
    if (input == "hang")
        while (true) std::this_thread::sleep_for(std::chrono::seconds(1));
    if (input == "overflow") {
        const std::unique_ptr<volatile char[]> block(new volatile char[4]());
        shadelab::fuzz::noteOutcome(std::string(1, block[input.size()]));  // index 8 of 4
    }
    shadelab::fuzz::noteOutcome("ok");
    return 0;
}
