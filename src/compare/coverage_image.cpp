#include "compare/coverage_image.h"

#include "util/input_error.h"

#include <stdexcept>

namespace shadelab {

Image8 coverageToImage(const std::vector<uint32_t>& ids, int width, int height) {
    if (width < 0 || height < 0 || ids.size() != size_t(width) * size_t(height))
        throw std::invalid_argument("coverageToImage: " + std::to_string(ids.size()) + " ids for a " +
                                    std::to_string(width) + "x" + std::to_string(height) + " image");
    Image8 image{width, height, 3, std::vector<uint8_t>(ids.size() * 3)};
    for (size_t i = 0; i < ids.size(); ++i) {
        const uint32_t id = ids[i];
        if (id > kMaxCoverageImageId)
            throw std::invalid_argument("coverageToImage: id " + std::to_string(id) + " does not fit 24 bits");
        image.data[i * 3 + 0] = uint8_t(id & 0xff);
        image.data[i * 3 + 1] = uint8_t((id >> 8) & 0xff);
        image.data[i * 3 + 2] = uint8_t(id >> 16);
    }
    return image;
}

std::vector<uint32_t> coverageFromImage(const Image8& image, const std::string& path) {
    if (image.channels != 3 && image.channels != 4)
        throw InputError(
            path, "a coverage image is RGB or RGBA, this one has " + std::to_string(image.channels) + " channels");
    const size_t n = size_t(image.width) * size_t(image.height), c = size_t(image.channels);
    std::vector<uint32_t> ids(n);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = &image.data[i * c];
        if (c == 4 && p[3] != 255)
            throw InputError(path, "not a coverage image: pixel (" + std::to_string(i % size_t(image.width)) + ", " +
                                       std::to_string(i / size_t(image.width)) + ") has alpha " + std::to_string(p[3]) +
                                       " (coverage ids have alpha 255)");
        ids[i] = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16;
    }
    return ids;
}

}  // namespace shadelab
