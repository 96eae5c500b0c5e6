// Fuzz target: the OpenEXR reader (image/exr.h) over OpenEXR 3.1's decoders. Every input must decode or raise an
// InputError (OpenEXR's own exceptions included, as parseExr promises); a decoded image must be what the reader
// documents (sizes within the limits, each layer's samples exactly width·height·channels), must compare equal to
// itself in linear light (compare/linear_compare.h: the same NaN in both is no difference), and must encode and
// decode again to the same samples bit for bit, or the target aborts.
#include "compare/linear_compare.h"
#include "fuzz_outcome.h"
#include "image/exr.h"
#include "util/input_error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

[[noreturn]] void broken(const char* what) {
    std::fprintf(stderr, "exr_fuzz: %s\n", what);
    std::abort();
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace shadelab;
    ExrImage img;
    try {
        img = parseExr(std::string(reinterpret_cast<const char*>(data), size), "fuzz.exr");
    } catch (const InputError& e) {
        fuzz::noteOutcome(e.what());
        return 0;
    }
    if (img.width < 1 || img.height < 1 || img.width > kMaxImageSide || img.height > kMaxImageSide)
        broken("a decoded size outside the limits");
    size_t channels = 0;
    for (const ExrLayer& l : img.layers) {
        if (l.channels.empty() || l.samples.size() != size_t(img.width) * size_t(img.height) * l.channels.size())
            broken("a layer whose samples do not match its size");
        channels += l.channels.size();
    }
    if (img.layers.empty() || channels > size_t(kMaxExrChannels)) broken("a channel count outside the limits");
    // Re-encoded as float and read again: the same layers, the same bits.
    const ExrImage again = parseExr(encodeExr(img, ExrPrecision::Float), "again.exr");
    if (again.layers.size() != img.layers.size()) broken("the layers changed on a round trip");
    for (size_t i = 0; i < img.layers.size(); ++i)
        if (again.layers[i].name != img.layers[i].name || again.layers[i].channels != img.layers[i].channels ||
            !sameBits(again.layers[i].samples, img.layers[i].samples))
            broken("samples changed on a float round trip");
    try {
        const ImageF colour = colourOf(img, "fuzz.exr");
        if (!compareLinear(colour, colour).pass) broken("an image differs from itself");
    } catch (const InputError& e) {
        fuzz::noteOutcome(std::string("decoded; ") + e.what());
        return 0;
    }
    fuzz::noteOutcome("ok");
    return 0;
}
