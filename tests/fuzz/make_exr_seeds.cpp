// Writes exr_fuzz's seeds into the folder argv[1]: small files in each of OpenEXR's layouts and compressions, so
// that mutation starts from every decoder (the fuzz_exr_seeds ctest fixture runs it before fuzz_exr_smoke). Made
// here, with shadelab's writer and OpenEXR's, rather than kept as binary files in the repository.
#include "image/exr.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace shadelab;

namespace {

ExrLayer layer(const std::string& name, std::vector<std::string> channels, int w, int h) {
    ExrLayer l;
    l.name = name;
    l.channels = std::move(channels);
    for (size_t i = 0; i < size_t(w) * size_t(h) * l.channels.size(); ++i)
        l.samples.push_back(float(i % 7) * 0.75f - 1.0f + (i % 5 == 0 ? 1000.0f : 0.0f));
    return l;
}

void save(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// OpenEXR's own writer for what shadelab's does not write: other compressions, tiles, a displaced data window,
// half and uint channels. `channels` are "name:type" with type h, f or u.
void openexr(const std::string& path, int w, int h, Imf::Compression compression, bool tiled, int x0, int y0,
             const std::vector<std::string>& channels) {
    Imath::Box2i window(Imath::V2i(x0, y0), Imath::V2i(x0 + w - 1, y0 + h - 1));
    Imf::Header header(window, window, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, compression);
    if (tiled) header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
    Imf::FrameBuffer frame;
    std::vector<std::vector<char>> buffers;
    for (const std::string& c : channels) {
        const std::string name = c.substr(0, c.size() - 2);
        const char type = c.back();
        const Imf::PixelType t = type == 'h' ? Imf::HALF : type == 'u' ? Imf::UINT : Imf::FLOAT;
        const size_t bytes = t == Imf::HALF ? 2 : 4;
        header.channels().insert(name, Imf::Channel(t));
        buffers.emplace_back(size_t(w) * size_t(h) * bytes);
        std::vector<char>& b = buffers.back();
        for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
            const float v = std::sin(float(i) * 0.7f) * 4.0f;
            if (t == Imf::HALF) {
                const Imath::half hv(v);
                std::memcpy(&b[i * 2], &hv, 2);
            } else if (t == Imf::UINT) {
                const uint32_t u = uint32_t(i * 2654435761u);
                std::memcpy(&b[i * 4], &u, 4);
            } else {
                std::memcpy(&b[i * 4], &v, 4);
            }
        }
        frame.insert(name, Imf::Slice::Make(t, b.data(), window, bytes, bytes * size_t(w)));
    }
    if (tiled) {
        Imf::TiledOutputFile out(path.c_str(), header, 1);
        out.setFrameBuffer(frame);
        out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
    } else {
        Imf::OutputFile out(path.c_str(), header, 1);
        out.setFrameBuffer(frame);
        out.writePixels(h);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_exr_seeds FOLDER\n");
        return 2;
    }
    const std::string dir = argv[1];
    ExrImage rgb;
    rgb.width = 4;
    rgb.height = 3;
    rgb.layers.push_back(layer("", {"R", "G", "B"}, 4, 3));
    save(dir + "/float_rgb_4x3.exr", encodeExr(rgb, ExrPrecision::Float));
    save(dir + "/half_rgb_4x3.exr", encodeExr(rgb, ExrPrecision::Half));
    ExrImage passes = rgb;
    passes.layers.push_back(layer("albedo", {"R", "G", "B"}, 4, 3));
    passes.layers.push_back(layer("normal", {"X", "Y", "Z"}, 4, 3));
    passes.layers.push_back(layer("depth", {"Z"}, 4, 3));
    save(dir + "/passes_4x3.exr", encodeExr(passes, ExrPrecision::Half));
    openexr(dir + "/piz_tiled_rgba_9x7.exr", 9, 7, Imf::PIZ_COMPRESSION, true, 0, 0, {"R:h", "G:h", "B:h", "A:h"});
    openexr(dir + "/rle_window_5x4.exr", 5, 4, Imf::RLE_COMPRESSION, false, -2, 3, {"B:f", "G:f", "R:f", "id:u"});
    openexr(dir + "/none_y_1x1.exr", 1, 1, Imf::NO_COMPRESSION, false, 0, 0, {"Y:f"});
    openexr(dir + "/pxr24_rgb_6x3.exr", 6, 3, Imf::PXR24_COMPRESSION, false, 0, 0, {"R:f", "G:f", "B:f"});
    openexr(dir + "/b44_rgb_8x8.exr", 8, 8, Imf::B44_COMPRESSION, false, 0, 0, {"R:h", "G:h", "B:h"});
    openexr(dir + "/dwaa_rgb_8x4.exr", 8, 4, Imf::DWAA_COMPRESSION, false, 0, 0, {"R:h", "G:h", "B:h"});
    openexr(dir + "/zips_tiled_nested_8x5.exr", 8, 5, Imf::ZIPS_COMPRESSION, true, 1, 1,
            {"left.albedo.R:f", "left.albedo.G:f", "R:h", "G:h", "B:h"});
    return 0;
}
