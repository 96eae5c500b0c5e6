// Image comparison (design.md §4): one pass over both images accumulating integer sums per region,
// then the gates. Nothing here allocates per pixel; the band needs one width*height mask and a 3-row ring.
#include "compare/image_compare.h"

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
    int64_t maxIndex = -1;  // pixel index of the first pixel reaching max
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

// Adds one pixel's differences to a region.
inline void addPixel(RegionAcc& r, int64_t i, uint32_t sum, uint32_t sumSq, int pixelMax, int pixelChannel,
                     int threshold, int hardMax) {
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

// The single pass. CA and CB are the channel counts, so the inner loop is unrolled and a missing
// alpha reads as opaque (255). band == nullptr puts every pixel in the interior. The accumulators are
// locals picked by a branch, not an indexed array: byte loads may alias anything, and only locals
// whose address never escapes stay in registers.
template <int CA, int CB>
void accumulate(const Image8& a, const Image8& b, const uint8_t* band, int threshold, int hardMax, RegionAcc& interior,
                RegionAcc& inBand) {
    constexpr int kChannels = CA > CB ? CA : CB;
    const int64_t n = int64_t(a.width) * a.height;
    const uint8_t* pa = a.data.data();
    const uint8_t* pb = b.data.data();
    RegionAcc accIn, accBand;
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
        if (band && band[i])
            addPixel(accBand, i, sum, sumSq, pixelMax, pixelChannel, threshold, hardMax);
        else
            addPixel(accIn, i, sum, sumSq, pixelMax, pixelChannel, threshold, hardMax);
    }
    interior = accIn;
    inBand = accBand;
}

void checkImages(const Image8& a, const Image8& b) {
    if (a.width != b.width || a.height != b.height) {
        throw InputError("", "image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                 " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
    }
    for (const Image8* img : {&a, &b}) {
        if (img->channels != 3 && img->channels != 4) {
            throw InputError(
                "", "cannot compare an image with " + std::to_string(img->channels) + " channels (need RGB or RGBA)");
        }
        SHADELAB_CHECK_EQ(img->data.size(), size_t(img->width) * size_t(img->height) * size_t(img->channels));
    }
}

void checkGates(const CompareGates& g) {
    const auto fail = [](const std::string& what) { throw InputError("", "compare gates: " + what); };
    if (g.threshold < 0 || g.threshold > 255) {
        fail("threshold must be in [0, 255], got " + std::to_string(g.threshold));
    }
    if (g.hardMax < 0 || g.hardMax > 255) fail("hard max must be in [0, 255], got " + std::to_string(g.hardMax));
    const auto isFraction = [](double f) { return f >= 0 && f <= 1; };  // false for NaN too
    if (!isFraction(g.maxFractionOver)) fail("max fraction over must be in [0, 1]");
    if (!isFraction(g.maxSilhouetteFraction)) fail("max silhouette fraction must be in [0, 1]");
    if (g.maxMean && !(*g.maxMean >= 0)) fail("max mean must be >= 0");
}

// Largest count that stays within a fraction limit; the epsilon keeps exact products (0.001 * 1000)
// from rounding down.
int64_t allowedCount(double fraction, int64_t total) { return int64_t(std::floor(fraction * double(total) + 1e-9)); }

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
        r.reasons.push_back("interior: max " + std::to_string(in.max) + "/255 at (" + std::to_string(in.maxX) + ", " +
                            std::to_string(in.maxY) + ") channel " + channelName(in.maxChannel) + " (limit " +
                            std::to_string(g.hardMax) + "/255; " + std::to_string(in.overHardMax) + " pixels over)");
    }
    if (g.maxMean && in.mean > *g.maxMean) {
        r.reasons.push_back(format("interior: mean %.3f/255 (limit %.3f/255)", in.mean, *g.maxMean));
    }
    if (r.mismatchesOutsideBand > 0) {
        r.reasons.push_back("coverage differs at " + std::to_string(r.mismatchesOutsideBand) +
                            " pixels outside the silhouette band");
    }
    if (r.hasCoverage && r.coverageMismatches > allowedCount(g.maxSilhouetteFraction, r.band.pixels)) {
        r.reasons.push_back(
            format("coverage differs at %.2f%% of silhouette band pixels (limit %.2f%%; "
                   "%lld of %lld pixels)",
                   100.0 * r.mismatchFractionOfBand(), 100.0 * g.maxSilhouetteFraction, (long long)r.coverageMismatches,
                   (long long)r.band.pixels));
    }
    r.pass = r.reasons.empty();
}

// Silhouette band and coverage mismatch counts in one pass over both buffers. A 3x3 window is mixed
// iff one of its three row segments is mixed, or the segments are each uniform but differ; a uniform
// segment's id is its centre id. Row-segment flags live in a 3-row ring, so the coverage is read from
// memory once. Clamping at the borders only repeats a pixel, which cannot make a window mixed.
void bandAndMismatches(const std::vector<uint32_t>& coverageA, const std::vector<uint32_t>& coverageB, int width,
                       int height, std::vector<uint8_t>& band, int64_t& mismatches, int64_t& outside) {
    const size_t n = size_t(width) * size_t(height);
    SHADELAB_CHECK_EQ(coverageA.size(), n);
    SHADELAB_CHECK_EQ(coverageB.size(), n);
    band.assign(n, 0);
    if (n == 0) return;
    const size_t w = size_t(width);
    std::vector<uint8_t> ring(3 * w);
    const auto rowMixed = [&](int y) {
        const uint32_t* ra = coverageA.data() + size_t(y) * w;
        const uint32_t* rb = coverageB.data() + size_t(y) * w;
        uint8_t* m = ring.data() + size_t(y % 3) * w;
        const auto mixedAt = [&](int x, int l, int r) {
            return uint8_t((ra[l] != ra[x]) | (ra[r] != ra[x]) | (rb[l] != rb[x]) | (rb[r] != rb[x]));
        };
        for (int x = 1; x + 1 < width; ++x) m[x] = mixedAt(x, x - 1, x + 1);  // straight loop: vectorises
        m[0] = mixedAt(0, 0, std::min(1, width - 1));
        if (width > 1) m[width - 1] = mixedAt(width - 1, width - 2, width - 1);
    };
    rowMixed(0);
    for (int y = 0; y < height; ++y) {
        if (y + 1 < height) rowMixed(y + 1);
        const int yu = y > 0 ? y - 1 : y, yd = y + 1 < height ? y + 1 : y;
        const uint8_t *mu = &ring[size_t(yu % 3) * w], *mc = &ring[size_t(y % 3) * w], *md = &ring[size_t(yd % 3) * w];
        const uint32_t* ca = coverageA.data();
        const uint32_t* cb = coverageB.data();
        const uint32_t *au = ca + size_t(yu) * w, *ac = ca + size_t(y) * w, *ad = ca + size_t(yd) * w;
        const uint32_t *bu = cb + size_t(yu) * w, *bc = cb + size_t(y) * w, *bd = cb + size_t(yd) * w;
        uint8_t* out = &band[size_t(y) * w];
        int64_t rowMismatches = 0, rowOutside = 0;
        for (size_t x = 0; x < w; ++x) {
            const uint8_t inBand = uint8_t(mu[x] | mc[x] | md[x] | (au[x] != ac[x]) | (ad[x] != ac[x]) |
                                           (bu[x] != bc[x]) | (bd[x] != bc[x]));
            const int differs = ac[x] != bc[x];
            out[x] = inBand;
            rowMismatches += differs;
            rowOutside += differs & (inBand ^ 1);
        }
        mismatches += rowMismatches;
        outside += rowOutside;
    }
}

CompareResult compareWithBand(const Image8& a, const Image8& b, const uint8_t* band, const CompareGates& gates) {
    RegionAcc acc[2];
    const int ca = a.channels, cb = b.channels, t = gates.threshold, h = gates.hardMax;
    if (ca == 3 && cb == 3)
        accumulate<3, 3>(a, b, band, t, h, acc[0], acc[1]);
    else if (ca == 4 && cb == 4)
        accumulate<4, 4>(a, b, band, t, h, acc[0], acc[1]);
    else if (ca == 3)
        accumulate<3, 4>(a, b, band, t, h, acc[0], acc[1]);
    else
        accumulate<4, 3>(a, b, band, t, h, acc[0], acc[1]);

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
    std::vector<uint8_t> band;
    int64_t mismatches = 0, outside = 0;
    bandAndMismatches(coverageA, coverageB, width, height, band, mismatches, outside);
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
    std::vector<uint8_t> band;
    int64_t mismatches = 0, outside = 0;
    bandAndMismatches(coverageA, coverageB, a.width, a.height, band, mismatches, outside);
    CompareResult r = compareWithBand(a, b, band.data(), gates);
    r.hasCoverage = true;
    r.coverageMismatches = mismatches;
    r.mismatchesOutsideBand = outside;
    r.bandMask = std::move(band);
    applyGates(r);
    return r;
}

}  // namespace shadelab
