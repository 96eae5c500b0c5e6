// Image comparison (design.md §4): one pass over both images accumulating integer sums per region,
// then the gates. Nothing here allocates per pixel; the band needs two width*height byte masks.
#include "image/compare.h"

#include "util/check.h"
#include "util/input_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace shadelab {

namespace {

// Integer accumulator for one region; turned into RegionStats at the end.
struct RegionAcc {
    int64_t pixels = 0;
    uint64_t sum = 0;
    uint64_t sumSq = 0;
    int max = 0;
    int64_t maxIndex = -1;                   // pixel index of the first pixel reaching max
    int maxChannel = -1;
    int64_t over = 0;
    int64_t overHard = 0;

    void merge(const RegionAcc& o) {
        pixels += o.pixels;
        sum += o.sum;
        sumSq += o.sumSq;
        over += o.over;
        overHard += o.overHard;
        // Ties go to the earlier pixel, as in a single row-major scan.
        if (o.max > max || (o.max == max && o.max > 0 && o.maxIndex < maxIndex)) {
            max = o.max;
            maxIndex = o.maxIndex;
            maxChannel = o.maxChannel;
        }
    }

    RegionStats stats(int channels, int width) const {
        RegionStats s;
        s.pixels = pixels;
        const double samples = double(pixels) * channels;
        s.mean = samples > 0 ? double(sum) / samples : 0.0;
        s.rms = samples > 0 ? std::sqrt(double(sumSq) / samples) : 0.0;
        s.max = max;
        if (max > 0) {
            s.maxX = int(maxIndex % width);
            s.maxY = int(maxIndex / width);
            s.maxChannel = maxChannel;
        }
        s.overThreshold = over;
        s.overHardMax = overHard;
        return s;
    }
};

// The single pass. CA and CB are the channel counts, so the inner loop is unrolled and a missing
// alpha reads as opaque (255). band == nullptr puts every pixel in region 0 (interior).
template <int CA, int CB>
void accumulate(const Image8& a, const Image8& b, const uint8_t* band, int threshold, int hardMax,
                RegionAcc acc[2]) {
    constexpr int kChannels = CA > CB ? CA : CB;
    const int64_t n = int64_t(a.width) * a.height;
    const uint8_t* pa = a.data.data();
    const uint8_t* pb = b.data.data();
    for (int64_t i = 0; i < n; ++i, pa += CA, pb += CB) {
        int pixelMax = 0, pixelChannel = 0;
        uint32_t sum = 0, sumSq = 0;
        for (int c = 0; c < kChannels; ++c) {
            const int va = c < CA ? pa[c] : 255;
            const int vb = c < CB ? pb[c] : 255;
            const int d = va > vb ? va - vb : vb - va;
            sum += uint32_t(d);
            sumSq += uint32_t(d * d);
            if (d > pixelMax) {
                pixelMax = d;
                pixelChannel = c;
            }
        }
        RegionAcc& r = acc[band ? band[i] : 0];
        r.pixels++;
        r.sum += sum;
        r.sumSq += sumSq;
        r.over += pixelMax > threshold;
        r.overHard += pixelMax > hardMax;
        if (pixelMax > r.max) {
            r.max = pixelMax;
            r.maxIndex = i;
            r.maxChannel = pixelChannel;
        }
    }
}

void checkImages(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height) {
        throw InputError("", "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                 " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
    }
    for (const Image8* img : {&a, &b}) {
        if (img->channels != 3 && img->channels != 4) {
            throw InputError("", "cannot compare an image with " + std::to_string(img->channels) +
                                     " channels (need RGB or RGBA)");
        }
        SHADELAB_CHECK_EQ(img->data.size(), size_t(img->width) * size_t(img->height) * size_t(img->channels));
    }
}

void checkGates(const CompareGates& g) {
    const auto fail = [](const std::string& what) { throw InputError("", "compare gates: " + what); };
    if (g.threshold < 0 || g.threshold > 255) fail("threshold must be in [0, 255], got " + std::to_string(g.threshold));
    if (g.hardMax < 0 || g.hardMax > 255) fail("hard max must be in [0, 255], got " + std::to_string(g.hardMax));
    if (!(g.maxFractionOver >= 0 && g.maxFractionOver <= 1)) fail("max fraction over must be in [0, 1]");
    if (!(g.maxSilhouetteFraction >= 0 && g.maxSilhouetteFraction <= 1)) fail("max silhouette fraction must be in [0, 1]");
    if (g.maxMean && !(*g.maxMean >= 0)) fail("max mean must be >= 0");
}

// Largest count that stays within a fraction limit; the epsilon keeps exact products (0.001 * 1000)
// from rounding down.
int64_t allowedCount(double fraction, int64_t total) {
    return int64_t(std::floor(fraction * double(total) + 1e-9));
}

template <typename... Args>
std::string format(const char* fmt, Args... args) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}

void applyGates(CompareResult& r) {
    const CompareGates& g = r.gates;
    const RegionStats& in = r.interior;
    if (in.overThreshold > allowedCount(g.maxFractionOver, in.pixels)) {
        r.reasons.push_back(format("interior: %.2f%% of pixels over %d/255 (limit %.2f%%; %lld of %lld pixels)",
                                   100.0 * in.fractionOver(), g.threshold, 100.0 * g.maxFractionOver,
                                   (long long)in.overThreshold, (long long)in.pixels));
    }
    if (in.overHardMax > 0) {
        r.reasons.push_back("interior: max " + std::to_string(in.max) + "/255 at (" + std::to_string(in.maxX) +
                            ", " + std::to_string(in.maxY) + ") channel " + channelName(in.maxChannel) +
                            " (limit " + std::to_string(g.hardMax) + "/255; " + std::to_string(in.overHardMax) +
                            " pixels over)");
    }
    if (g.maxMean && in.mean > *g.maxMean) {
        r.reasons.push_back(format("interior: mean %.3f/255 (limit %.3f/255)", in.mean, *g.maxMean));
    }
    if (r.mismatchesOutsideBand > 0) {
        r.reasons.push_back("coverage differs at " + std::to_string(r.mismatchesOutsideBand) +
                            " pixels outside the silhouette band");
    }
    if (r.hasCoverage && r.coverageMismatches > allowedCount(g.maxSilhouetteFraction, r.band.pixels)) {
        r.reasons.push_back(format("coverage differs at %.2f%% of silhouette band pixels (limit %.2f%%; "
                                   "%lld of %lld pixels)",
                                   100.0 * r.mismatchFractionOfBand(), 100.0 * g.maxSilhouetteFraction,
                                   (long long)r.coverageMismatches, (long long)r.band.pixels));
    }
    r.pass = r.reasons.empty();
}

CompareResult compareWithBand(const Image8& a, const Image8& b, const uint8_t* band, const CompareGates& gates) {
    RegionAcc acc[2];
    const int ca = a.channels, cb = b.channels;
    if (ca == 3 && cb == 3) accumulate<3, 3>(a, b, band, gates.threshold, gates.hardMax, acc);
    else if (ca == 4 && cb == 4) accumulate<4, 4>(a, b, band, gates.threshold, gates.hardMax, acc);
    else if (ca == 3) accumulate<3, 4>(a, b, band, gates.threshold, gates.hardMax, acc);
    else accumulate<4, 3>(a, b, band, gates.threshold, gates.hardMax, acc);

    CompareResult r;
    r.width = a.width;
    r.height = a.height;
    r.channels = std::max(ca, cb);
    r.gates = gates;
    r.interior = acc[0].stats(r.channels, r.width);
    r.band = acc[1].stats(r.channels, r.width);
    RegionAcc all = acc[0];
    all.merge(acc[1]);
    r.all = all.stats(r.channels, r.width);
    return r;
}

}  // namespace

const char* channelName(int channel) {
    static const char* const kNames[] = {"R", "G", "B", "A"};
    return channel >= 0 && channel < 4 ? kNames[channel] : "-";
}

std::vector<uint8_t> silhouetteBand(const std::vector<uint32_t>& coverageA, const std::vector<uint32_t>& coverageB,
                                    int width, int height) {
    const size_t n = size_t(width) * size_t(height);
    SHADELAB_CHECK_EQ(coverageA.size(), n);
    SHADELAB_CHECK_EQ(coverageB.size(), n);
    // A 3x3 window is mixed iff one of its three row segments is mixed, or the three segments are each
    // uniform but differ from one another; a uniform segment's id is its centre id. Clamping at the
    // borders only repeats a pixel, which cannot change whether a window is mixed.
    std::vector<uint8_t> rowMixed(n), band(n);
    const uint32_t* ids[2] = {coverageA.data(), coverageB.data()};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            const size_t l = x > 0 ? i - 1 : i, rt = x + 1 < width ? i + 1 : i;
            uint8_t m = 0;
            for (int k = 0; k < 2; ++k) m |= uint8_t((ids[k][l] != ids[k][i]) | (ids[k][rt] != ids[k][i]));
            rowMixed[i] = m;
        }
    }
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            const size_t up = y > 0 ? i - size_t(width) : i, dn = y + 1 < height ? i + size_t(width) : i;
            uint8_t m = rowMixed[up] | rowMixed[i] | rowMixed[dn];
            for (int k = 0; k < 2; ++k) m |= uint8_t((ids[k][up] != ids[k][i]) | (ids[k][dn] != ids[k][i]));
            band[i] = m;
        }
    }
    return band;
}

CompareResult compareImages(const Image8& a, const Image8& b, const CompareGates& gates) {
    checkImages(a, b);
    checkGates(gates);
    CompareResult r = compareWithBand(a, b, nullptr, gates);
    applyGates(r);
    return r;
}

CompareResult compareImages(const Image8& a, const Image8& b, const std::vector<uint32_t>& coverageA,
                            const std::vector<uint32_t>& coverageB, const CompareGates& gates) {
    checkImages(a, b);
    checkGates(gates);
    std::vector<uint8_t> band = silhouetteBand(coverageA, coverageB, a.width, a.height);
    CompareResult r = compareWithBand(a, b, band.data(), gates);
    r.hasCoverage = true;
    for (size_t i = 0; i < band.size(); ++i) {
        const int64_t differs = coverageA[i] != coverageB[i];
        r.coverageMismatches += differs;
        r.mismatchesOutsideBand += differs & int64_t(band[i] == 0);
    }
    r.bandMask = std::move(band);
    applyGates(r);
    return r;
}

}  // namespace shadelab
