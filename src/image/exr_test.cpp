// writeExr / readExr: float round trips exactly, half within half precision, layers are named as exr.h documents
// and read back by name, writes are atomic and refuse inputs, and hostile files (wrong magic, truncated, a huge
// data window, a missing channel, too many channels) are refused with one line naming the file.
#include "image/exr.h"

#include "util/atomic_file.h"
#include "util/input_error.h"
#include "util/input_files.h"
#include "util/read_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <gtest/gtest.h>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

std::string dirFor(const std::string& name) {
    const fs::path dir = fs::path(SHADELAB_TEST_OUTPUT_DIR) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

void writeBytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// A float image with values a PNG cannot hold: above 1, tiny, negative, and many distinct mantissas.
ImageF pattern(int w, int h) {
    ImageF img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = img.pixel(x, y);
            p[0] = float(x) * 0.37f + float(y) * 1.0e-3f;
            p[1] = std::ldexp(1.0f + float(x * 31 + y) / 997.0f, (x + y) % 20 - 10);
            p[2] = (x + y) % 3 == 0 ? -0.25f * float(y) : 1000.0f / float(1 + x);
            p[3] = 1.0f;
        }
    return img;
}

ExrLayer syntheticLayer(const std::string& name, std::vector<std::string> channels, int w, int h, float scale) {
    ExrLayer l;
    l.name = name;
    l.channels = std::move(channels);
    l.samples.resize(size_t(w) * size_t(h) * l.channels.size());
    for (size_t i = 0; i < l.samples.size(); ++i) l.samples[i] = scale * float(i % 101) - 3.0f;
    return l;
}

// The one-line refusal of `bytes` as `path`: an InputError whose message starts with the file's name.
std::string refusal(const std::string& bytes, const std::string& path) {
    try {
        parseExr(bytes, path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expectRefused(const std::string& bytes, const std::string& path, const std::string& words) {
    const std::string m = refusal(bytes, path);
    ASSERT_FALSE(m.empty()) << path << " was read";
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
}

}  // namespace

TEST(Exr, FloatRoundTripIsExact) {
    const std::string dir = dirFor("float_round_trip");
    ImageF img = pattern(37, 23);
    img.pixel(3, 4)[0] = std::numeric_limits<float>::infinity();
    img.pixel(5, 6)[1] = std::numeric_limits<float>::denorm_min();
    writeExr(dir + "/a.exr", exrFromImage(img), ExrPrecision::Float);
    const ExrImage back = readExr(dir + "/a.exr");
    ASSERT_EQ(back.width, 37);
    ASSERT_EQ(back.height, 23);
    ASSERT_EQ(back.layers.size(), 1u);
    EXPECT_EQ(back.layers[0].name, "");
    EXPECT_EQ(back.layers[0].channels, (std::vector<std::string>{"R", "G", "B"}));
    const ImageF rgb = colourOf(back, "a.exr");
    ASSERT_EQ(rgb.rgba.size(), img.rgba.size());
    EXPECT_EQ(std::memcmp(rgb.rgba.data(), img.rgba.data(), img.rgba.size() * sizeof(float)), 0)
        << "float samples must come back bit for bit";
    // Negative control: one changed sample is seen.
    ImageF changed = img;
    changed.pixel(10, 10)[2] = std::nextafter(changed.pixel(10, 10)[2], 1e30f);
    EXPECT_NE(std::memcmp(rgb.rgba.data(), changed.rgba.data(), img.rgba.size() * sizeof(float)), 0);
}

TEST(Exr, HalfRoundTripIsWithinHalfPrecision) {
    const std::string dir = dirFor("half_round_trip");
    const ImageF img = pattern(41, 19);
    writeExr(dir + "/h.exr", exrFromImage(img), ExrPrecision::Half);
    const ImageF back = colourOf(readExr(dir + "/h.exr"), "h.exr");
    // Round to nearest with 11 significant bits: relative error at most 2^-11 for normal halves (|x| >= 2^-14),
    // absolute at most 2^-25 below (subnormal spacing 2^-24).
    size_t inexact = 0;
    for (size_t i = 0; i < img.rgba.size(); ++i) {
        const float a = img.rgba[i], b = back.rgba[i];
        const float bound =
            std::fabs(a) >= std::ldexp(1.0f, -14) ? std::fabs(a) * std::ldexp(1.0f, -11) : std::ldexp(1.0f, -25);
        EXPECT_LE(std::fabs(a - b), bound) << "sample " << i << ": " << a << " -> " << b;
        inexact += a != b;
    }
    // Negative control: half really is narrower than float, so most of these samples moved.
    EXPECT_GT(inexact, img.rgba.size() / 4);
    // And it is smaller on disk.
    writeExr(dir + "/f.exr", exrFromImage(img), ExrPrecision::Float);
    EXPECT_LT(fs::file_size(dir + "/h.exr"), fs::file_size(dir + "/f.exr"));
}

TEST(Exr, LayersAreNamedAsDocumentedAndReadBackByName) {
    const std::string dir = dirFor("layers");
    const int w = 16, h = 9;
    ExrImage img = exrFromImage(pattern(w, h));
    // Given out of order, as a caller might: read back by name whatever the order.
    img.layers.push_back(syntheticLayer("normal", {"X", "Y", "Z"}, w, h, 0.5f));
    img.layers.push_back(syntheticLayer("albedo", {"R", "G", "B"}, w, h, 0.01f));
    img.layers.push_back(syntheticLayer("depth", {"Z"}, w, h, 7.0f));
    img.layers.push_back(syntheticLayer("variance", {"R", "G", "B"}, w, h, 1e-4f));
    writeExr(dir + "/passes.exr", img, ExrPrecision::Float);

    // The file's own channel names, read with OpenEXR alone: the standard "<layer>.<channel>" names.
    const ExrImage back = readExr(dir + "/passes.exr");
    std::vector<std::string> layerNames;
    for (const ExrLayer& l : back.layers) layerNames.push_back(l.name);
    EXPECT_EQ(layerNames, (std::vector<std::string>{"", "albedo", "depth", "normal", "variance"}));
    const std::string bytes = readFile(dir + "/passes.exr");
    for (const char* name :
         {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z", "variance.R"})
        EXPECT_NE(bytes.find(std::string(name) + '\0'), std::string::npos) << name << " missing from the header";

    for (const ExrLayer& given : img.layers) {
        const ExrLayer* l = back.layer(given.name);
        ASSERT_NE(l, nullptr) << given.name;
        EXPECT_EQ(l->channels, given.channels) << given.name << ": channels in R G B / X Y Z order";
        EXPECT_EQ(l->samples, given.samples) << given.name;
    }
    EXPECT_EQ(back.layer("normal")->channelIndex("Y"), std::optional<size_t>(1));
    EXPECT_EQ(back.layer("depth")->channelIndex("Y"), std::nullopt);
    EXPECT_EQ(back.layer("shadow"), nullptr) << "control: a layer never written is not found";
}

TEST(Exr, WriteIsAtomicAndNeverReplacesAnInput) {
    const std::string dir = dirFor("atomic");
    const std::string input = dir + "/scene.json";
    writeBytes(input, "{}");
    InputFiles inputs;
    {
        InputRecorder rec(inputs);
        readFile(input);
    }
    try {
        writeExr(input, exrFromImage(pattern(4, 4)), ExrPrecision::Float);
        ADD_FAILURE() << "an input was replaced";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("refusing to overwrite an input"), std::string::npos) << e.what();
    }
    EXPECT_EQ(readFile(input), "{}");
    // Control: another name in the same folder is written, and nothing else is left there.
    writeExr(dir + "/out.exr", exrFromImage(pattern(4, 4)), ExrPrecision::Float);
    EXPECT_EQ(readExr(dir + "/out.exr").width, 4);
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u);
}

TEST(Exr, HostileFilesAreRefusedInOneLine) {
    const std::string dir = dirFor("hostile");
    const std::string good = encodeExr(exrFromImage(pattern(24, 20)), ExrPrecision::Half);
    ASSERT_NO_THROW(parseExr(good, "good.exr")) << "control";

    expectRefused("", "empty.exr", "not an OpenEXR file");
    expectRefused("\x89PNG\r\n\x1a\n" + good.substr(8), "png.exr", "not an OpenEXR file");
    std::string wrongMagic = good;
    wrongMagic[0] = 'w';
    expectRefused(wrongMagic, "magic.exr", "not an OpenEXR file");

    // Truncated anywhere: in the header, in the offset table, in the pixels.
    for (size_t keep : {size_t(8), size_t(40), good.size() / 3, good.size() - 200, good.size() - 1})
        expectRefused(good.substr(0, keep), "cut" + std::to_string(keep) + ".exr", "");

    // A data window of 10^6 x 10^6 pixels declared in a header that is otherwise the good one's.
    std::string huge = good;
    const size_t at = huge.find(std::string("dataWindow\0box2i\0", 17));
    ASSERT_NE(at, std::string::npos);
    const size_t value = at + 17 + 4;  // past the name, the type and the size
    const int32_t box[4] = {0, 0, 999999, 999999};
    std::memcpy(&huge[value], box, sizeof box);
    expectRefused(huge, "huge.exr", "data window");
    // The largest window shadelab reads, declared by a 24x20 file: within the limits, so the pixels are looked
    // for, and their absence is the refusal (the rows are reserved, not filled, so this costs no 3 GiB).
    const int32_t largest[4] = {0, 0, kMaxImageSide - 1, kMaxImageSide - 1};
    std::string claims = good;
    std::memcpy(&claims[value], largest, sizeof largest);
    expectRefused(claims, "claims.exr", "not a readable OpenEXR image");
    // The same file from disk, through readExr: the message names the path.
    writeBytes(dir + "/huge.exr", huge);
    try {
        readExr(dir + "/huge.exr");
        ADD_FAILURE() << "read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(dir + "/huge.exr: ", 0), 0u) << e.what();
    }

    // A missing channel: R and G but no B.
    ExrImage rg;
    rg.width = 8;
    rg.height = 8;
    rg.layers.push_back(syntheticLayer("", {"R", "G"}, 8, 8, 1.0f));
    const ExrImage rgBack = parseExr(encodeExr(rg, ExrPrecision::Float), "rg.exr");
    try {
        colourOf(rgBack, "rg.exr");
        ADD_FAILURE() << "an image without B was read as colour";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "rg.exr: missing channel B of R, G, B");
    }
    // Only passes, no colour at all.
    ExrImage passes;
    passes.width = passes.height = 4;
    passes.layers.push_back(syntheticLayer("depth", {"Z"}, 4, 4, 1.0f));
    EXPECT_THROW(colourOf(parseExr(encodeExr(passes, ExrPrecision::Half), "p.exr"), "p.exr"), InputError);

    // An absurd channel count, written with OpenEXR directly (shadelab's writer refuses it).
    {
        Imf::Header header(2, 2);
        Imf::FrameBuffer frame;
        std::vector<float> zeros(4, 0.0f);
        for (int c = 0; c < 500; ++c) {
            const std::string name = "c" + std::to_string(c);
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
            frame.insert(
                name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(zeros.data()), sizeof(float), 2 * sizeof(float)));
        }
        Imf::OutputFile out((dir + "/many.exr").c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(2);
    }
    try {
        readExr(dir + "/many.exr");
        ADD_FAILURE() << "500 channels were read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), dir + "/many.exr: more than 64 channels");
    }

    // Every single-byte change of the header is read or refused with one InputError, never anything else.
    const size_t headerEnd = good.find(std::string("\0\0", 2), 8);
    for (size_t i = 8; i < std::min<size_t>(headerEnd + 64, good.size()); ++i) {
        std::string b = good;
        b[i] = char(b[i] ^ 0x5a);
        try {
            parseExr(b, "flip.exr");
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("flip.exr: ", 0), 0u) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    }
}

TEST(Exr, ExtensionIsRecognisedInAnyCase) {
    EXPECT_TRUE(hasExrExtension("a.exr"));
    EXPECT_TRUE(hasExrExtension("dir.x/A.EXR"));
    EXPECT_FALSE(hasExrExtension("a.png"));
    EXPECT_FALSE(hasExrExtension("exr"));
    EXPECT_FALSE(hasExrExtension("a.exr.png"));
}
