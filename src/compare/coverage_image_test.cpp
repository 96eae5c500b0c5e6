// Coverage ids through an RGB image and back (compare/coverage_image.h): every byte of the id, a PNG round
// trip, and the refusals (an id over 24 bits, a pixel with alpha, a size that disagrees).
#include "compare/coverage_image.h"

#include "image/png.h"
#include "util/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

using namespace shadelab;

TEST(CoverageImage, EveryByteOfTheIdRoundTripsThroughAPng) {
    const std::vector<uint32_t> ids = {0, 1, 255, 256, 65535, 65536, 0x123456, kMaxCoverageImageId};
    const Image8 image = coverageToImage(ids, 4, 2);
    EXPECT_EQ(image.channels, 3);
    EXPECT_EQ(image.data[3 * 2 + 0], 255);  // id 255: the low byte only
    EXPECT_EQ(image.data[3 * 3 + 1], 1);    // id 256: the middle byte
    const std::filesystem::path dir = std::filesystem::path(SHADELAB_TEST_OUTPUT_DIR) / "coverage_image";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "ids.png").string();
    writePng(path, image);
    EXPECT_EQ(coverageFromImage(readPng(path), path), ids);
}

TEST(CoverageImage, RefusesWhatIsNotACoverageImage) {
    EXPECT_THROW(coverageToImage({kMaxCoverageImageId + 1}, 1, 1), std::invalid_argument);
    EXPECT_THROW(coverageToImage({1, 2, 3}, 2, 2), std::invalid_argument);
    Image8 rgba{1, 1, 4, {7, 0, 0, 128}};
    try {
        coverageFromImage(rgba, "cov.png");
        FAIL() << "a pixel with alpha 128 was read as an id";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("cov.png: not a coverage image: pixel (0, 0) has alpha 128"),
                  std::string::npos)
            << e.what();
    }
    rgba.data[3] = 255;
    EXPECT_EQ(coverageFromImage(rgba, "cov.png"), std::vector<uint32_t>{7});
    const Image8 grey{1, 1, 1, {7}};
    EXPECT_THROW(coverageFromImage(grey, "grey.png"), InputError);
}
