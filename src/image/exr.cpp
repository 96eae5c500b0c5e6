// EXR through OpenEXR's C++ API over memory: MemoryOStream collects the encoded file for writeFileAtomic,
// MemoryIStream reads the bytes readFile returned. The header is checked (as OpenEXR reads it, through
// Header::setMaxImageSize, and again here) before any pixel buffer exists.
#include "image/exr.h"

#include "util/atomic_file.h"
#include "util/check.h"
#include "util/input_error.h"
#include "util/read_file.h"

#include <IexBaseExc.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfThreading.h>
#include <ImfVersion.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

namespace shadelab {
namespace {

// An Imf::OStream that grows a byte buffer; OpenEXR seeks back to fill in the line offset table at the end.
class MemoryOStream : public Imf::OStream {
public:
    explicit MemoryOStream(const std::string& name) : Imf::OStream(name.c_str()) {}
    void write(const char c[], int n) override {
        if (n <= 0) return;
        if (pos_ + size_t(n) > bytes_.size()) bytes_.resize(pos_ + size_t(n));
        std::memcpy(&bytes_[pos_], c, size_t(n));
        pos_ += size_t(n);
    }
    uint64_t tellp() override { return pos_; }
    void seekp(uint64_t pos) override { pos_ = size_t(pos); }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
    size_t pos_ = 0;
};

// An Imf::IStream over bytes already in memory. Reading past the end throws, as a truncated file does.
class MemoryIStream : public Imf::IStream {
public:
    MemoryIStream(const std::string& bytes, const std::string& name) : Imf::IStream(name.c_str()), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || pos_ > bytes_.size() || size_t(n) > bytes_.size() - pos_)
            throw Iex::InputExc("the file is truncated");
        std::memcpy(c, bytes_.data() + pos_, size_t(n));
        pos_ += size_t(n);
        return pos_ < bytes_.size();
    }
    uint64_t tellg() override { return pos_; }
    void seekg(uint64_t pos) override { pos_ = size_t(std::min<uint64_t>(pos, bytes_.size() + 1)); }

private:
    const std::string& bytes_;
    size_t pos_ = 0;
};

// Threads OpenEXR compresses and decompresses blocks of scanlines with (its global pool): the cores, at most 8,
// as encodePng uses them.
int exrThreads() {
    static const int n = int(std::min(8u, std::max(1u, std::thread::hardware_concurrency())));
    return n;
}

// OpenEXR's own header checks, once per process: a data window or tile larger than shadelab reads is refused
// while the header is parsed, before the library sizes its line offset table from it. And its thread pool.
void limitOpenExr() {
    static std::once_flag once;
    std::call_once(once, [] {
        Imf::setGlobalThreadCount(exrThreads());
        Imf::Header::setMaxImageSize(kMaxImageSide, kMaxImageSide);
        // Tiles are read into buffers of a tile's size before anything else is known: 512 x 512 bounds them
        // (64 MiB at 64 float channels); files in the wild use 32..256.
        Imf::Header::setMaxTileSize(512, 512);
    });
}

bool validName(const std::string& s) { return !s.empty() && s.find('.') == std::string::npos; }

// A layer's name may nest ("left.albedo"), as EXR's multi-view naming does, but holds no empty part.
bool validLayerName(const std::string& s) {
    return !s.empty() && s.front() != '.' && s.back() != '.' && s.find("..") == std::string::npos;
}

std::string channelName(const std::string& layer, const std::string& channel) {
    return layer.empty() ? channel : layer + "." + channel;
}

// Where a channel goes in a layer's list: R G B A X Y Z first, then the others alphabetically.
int channelRank(const std::string& c) {
    static const char* const order[] = {"R", "G", "B", "A", "X", "Y", "Z"};
    for (int i = 0; i < 7; ++i)
        if (c == order[i]) return i;
    return 7;
}

// OpenEXR's messages may run over lines; the project's errors are one line.
std::string firstLine(const char* what) {
    std::string s = what ? what : "unknown error";
    const size_t nl = s.find('\n');
    if (nl != std::string::npos) s.resize(nl);
    return s;
}

}  // namespace

std::optional<size_t> ExrLayer::channelIndex(const std::string& channel) const {
    for (size_t i = 0; i < channels.size(); ++i)
        if (channels[i] == channel) return i;
    return std::nullopt;
}

const ExrLayer* ExrImage::layer(const std::string& name) const {
    for (const ExrLayer& l : layers)
        if (l.name == name) return &l;
    return nullptr;
}

ExrLayer colourLayer(const ImageF& image) {
    SHADELAB_CHECK_EQ(image.rgba.size(), size_t(image.width) * size_t(image.height) * 4);
    ExrLayer l;
    l.channels = {"R", "G", "B"};
    const size_t pixels = size_t(image.width) * size_t(image.height);
    l.samples.resize(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
        for (size_t c = 0; c < 3; ++c) l.samples[i * 3 + c] = image.rgba[i * 4 + c];
    return l;
}

ExrImage exrFromImage(const ImageF& image) {
    ExrImage e;
    e.width = image.width;
    e.height = image.height;
    e.layers.push_back(colourLayer(image));
    return e;
}

std::string encodeExr(const ExrImage& image, ExrPrecision precision) {
    SHADELAB_CHECK(image.width >= 1 && image.height >= 1 && image.width <= kMaxImageSide &&
                   image.height <= kMaxImageSide);
    SHADELAB_CHECK(!image.layers.empty());
    limitOpenExr();
    const size_t pixels = size_t(image.width) * size_t(image.height);
    const Imf::PixelType type = precision == ExrPrecision::Half ? Imf::HALF : Imf::FLOAT;
    Imf::Header header(image.width, image.height, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y,
                       Imf::ZIP_COMPRESSION);
    Imf::FrameBuffer frame;
    std::vector<std::string> names;
    // OpenEXR writes a half channel only from half samples: each layer's are converted here (Imath::half,
    // round to nearest even; beyond 65504 is +infinity).
    std::vector<std::vector<Imath::half>> halves(precision == ExrPrecision::Half ? image.layers.size() : 0);
    for (size_t li = 0; li < image.layers.size(); ++li) {
        const ExrLayer& l = image.layers[li];
        SHADELAB_CHECK(l.name.empty() || validLayerName(l.name));
        SHADELAB_CHECK(!l.channels.empty());
        SHADELAB_CHECK_EQ(l.samples.size(), pixels * l.channels.size());
        const size_t n = l.channels.size();
        for (size_t c = 0; c < n; ++c) {
            SHADELAB_CHECK(validName(l.channels[c]));
            const std::string name = channelName(l.name, l.channels[c]);
            SHADELAB_CHECK(std::find(names.begin(), names.end(), name) == names.end());
            names.push_back(name);
            header.channels().insert(name, Imf::Channel(type));
            if (precision == ExrPrecision::Half) {
                if (halves[li].empty()) halves[li].assign(l.samples.begin(), l.samples.end());
                frame.insert(name, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves[li].data() + c),
                                              sizeof(Imath::half) * n, sizeof(Imath::half) * n * size_t(image.width)));
            } else {
                frame.insert(name,
                             Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(l.samples.data() + c)),
                                        sizeof(float) * n, sizeof(float) * n * size_t(image.width)));
            }
        }
    }
    SHADELAB_CHECK(names.size() <= size_t(kMaxExrChannels));
    MemoryOStream out("memory");
    Imf::OutputFile file(out, header, exrThreads());
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
    return std::move(out.bytes());
}

void writeExr(const std::string& path, const ExrImage& image, ExrPrecision precision) {
    std::string bytes;
    try {
        bytes = encodeExr(image, precision);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path, "cannot encode the EXR image: " + firstLine(e.what()));
    }
    writeFileAtomic(path, bytes);
}

ExrImage parseExr(const std::string& bytes, const std::string& name) {
    const auto fail = [&name](const std::string& reason) { return InputError(name, reason); };
    if (bytes.size() < 8 || !Imf::isImfMagic(bytes.data()))
        throw fail("not an OpenEXR file (no magic number 76 2f 31 01 at its start)");
    limitOpenExr();
    try {
        MemoryIStream in(bytes, name);
        Imf::InputFile file(in, exrThreads());
        const Imf::Header& header = file.header();
        const Imath::Box2i dw = header.dataWindow();
        const int64_t w = int64_t(dw.max.x) - int64_t(dw.min.x) + 1, h = int64_t(dw.max.y) - int64_t(dw.min.y) + 1;
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
            throw fail("data window of " + std::to_string(w) + "x" + std::to_string(h) +
                       " pixels; each side must be 1.." + std::to_string(kMaxImageSide));
        // Channels grouped into layers by the name before their last '.'.
        std::map<std::string, std::vector<std::string>> layers;
        int count = 0;
        for (Imf::ChannelList::ConstIterator it = header.channels().begin(); it != header.channels().end(); ++it) {
            if (++count > kMaxExrChannels) throw fail("more than " + std::to_string(kMaxExrChannels) + " channels");
            const std::string full = it.name();
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
                throw fail("channel '" + full.substr(0, 64) +
                           "' is subsampled; only full-resolution channels are read");
            const size_t dot = full.rfind('.');
            const std::string layer = dot == std::string::npos ? std::string() : full.substr(0, dot);
            const std::string channel = dot == std::string::npos ? full : full.substr(dot + 1);
            if (channel.empty() || (dot != std::string::npos && !validLayerName(layer)))
                throw fail("channel '" + full.substr(0, 64) + "' has an empty layer or channel name");
            layers[layer].push_back(channel);
        }
        if (count == 0) throw fail("no channels");
        const uint64_t decoded = uint64_t(w) * uint64_t(h) * uint64_t(count) * sizeof(float);
        if (decoded > kMaxExrDecodedBytes)
            throw fail(std::to_string(count) + " channels of " + std::to_string(w) + "x" + std::to_string(h) +
                       " pixels need " + std::to_string(decoded >> 20) + " MiB as floats; at most " +
                       std::to_string(kMaxExrDecodedBytes >> 20) + " MiB are read");
        ExrImage img;
        img.width = int(w);
        img.height = int(h);
        const size_t pixels = size_t(w) * size_t(h);
        img.layers.reserve(layers.size());
        for (auto& [layerName, channels] : layers) {  // std::map: the colour layer ("") first, then by name
            std::stable_sort(channels.begin(), channels.end(), [](const std::string& a, const std::string& b) {
                const int ra = channelRank(a), rb = channelRank(b);
                return ra != rb ? ra < rb : (ra == 7 && a < b);
            });
            ExrLayer l;
            l.name = layerName;
            l.channels = channels;
            // Reserved, not filled: the pages of rows not yet read are never touched, so a small file that
            // declares a large image and then lacks its pixels costs the rows it has, not the ones it claims.
            l.samples.reserve(pixels * channels.size());
            img.layers.push_back(std::move(l));
        }
        // Bands of rows (whole tiles for a tiled file, so that none is decoded twice), each read into the rows
        // the vectors have just grown by; their storage was reserved above, so no pointer moves.
        const int64_t band =
            header.hasTileDescription() ? std::max<int64_t>(64, int64_t(header.tileDescription().ySize)) : 64;
        for (int64_t y0 = dw.min.y; y0 <= dw.max.y; y0 += band) {
            const int64_t y1 = std::min<int64_t>(dw.max.y, y0 + band - 1);
            Imf::FrameBuffer frame;
            for (ExrLayer& l : img.layers) {
                const size_t n = l.channels.size();
                l.samples.resize(size_t(y1 - dw.min.y + 1) * size_t(w) * n);
                for (size_t c = 0; c < n; ++c)
                    // Slice::Make places the buffer's first sample at the data window's origin.
                    frame.insert(channelName(l.name, l.channels[c]),
                                 Imf::Slice::Make(Imf::FLOAT, l.samples.data() + c, dw, sizeof(float) * n,
                                                  sizeof(float) * n * size_t(w)));
            }
            file.setFrameBuffer(frame);
            file.readPixels(int(y0), int(y1));
        }
        return img;
    } catch (const InputError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw fail("out of memory while decoding the EXR image");
    } catch (const std::exception& e) {
        throw fail("not a readable OpenEXR image: " + firstLine(e.what()));
    }
}

ExrImage readExr(const std::string& path) { return parseExr(readFile(path, kMaxExrFileBytes), path); }

ImageF colourOf(const ExrImage& image, const std::string& name) {
    const ExrLayer* l = image.layer("");
    if (!l) throw InputError(name, "no colour channels R, G, B (the layers are not an image)");
    std::optional<size_t> idx[4];
    const char* rgba[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        idx[c] = l->channelIndex(rgba[c]);
        if (c < 3 && !idx[c]) throw InputError(name, std::string("missing channel ") + rgba[c] + " of R, G, B");
    }
    ImageF out(image.width, image.height);
    const size_t n = l->channels.size(), pixels = size_t(image.width) * size_t(image.height);
    for (size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) out.rgba[i * 4 + size_t(c)] = l->samples[i * n + *idx[c]];
        out.rgba[i * 4 + 3] = idx[3] ? l->samples[i * n + *idx[3]] : 1.0f;
    }
    return out;
}

bool hasExrExtension(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".exr";
}

}  // namespace shadelab
