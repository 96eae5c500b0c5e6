// denoise_quality: how good the denoised preview is, not how fast: at each sample count, the relative RMSE
// (image_error.h, the lamp left out) of the raw and the denoised Cornell box against a converged reference,
// and the denoised error split into its noise and its bias. Two renders of independent seeds are denoised
// alike; half the squared difference of their results is the noise that the filter left (its variance), and
// what remains of the squared error is the filter's bias (blur, lost detail). A filter that smooths too little
// leaves noise; one that smooths too much shows bias.
//
// Usage: denoise_quality [--size WxH] [--spp 4,16,...] [--ref-spp N] [--scene PATH] [--out DIR]
//        [--iterations K] [--sigma-luminance S] [--sigma-normal S] [--sigma-depth S] [--sigma-albedo S]
// The reference (split halves, seeds 1 and 2, path_reference.h) is cached in --cache (build/bench-cache) by
// the scene's bytes, the size and the samples, and the path tracer's library alone: a changed denoiser
// renders no new reference. --out writes each denoised image as EXR.
#include "bench_timing.h"
#include "image/denoise.h"
#include "image/encode.h"
#include "image/exr.h"
#include "image/png.h"
#include "image_error.h"
#include "path_reference.h"
#include "scene/scene_load.h"
#include "trace/first_hit_passes.h"
#include "trace/path/path_denoise.h"
#include "trace/path/path_render.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace shadelab;
using namespace shadelab::bench;

struct Options {
    int width = 640, height = 360, refSpp = 512;
    std::vector<int> spp{4, 16};
    std::string scene = SHADELAB_SOURCE_DIR "/assets/scenes/cornell.json";
    std::string cache = SHADELAB_BENCH_CACHE_DIR, out;
    int biasSeeds = 0;  // --bias-map N: the mean of N seeds' denoised images against the reference, to --out
    DenoiseSettings denoise;
};

[[noreturn]] void usage(const char* problem) {
    std::fprintf(stderr, "denoise_quality: %s\n", problem);
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) usage(("missing a value after " + a).c_str());
        const char* v = argv[++i];
        if (a == "--size") {
            if (std::sscanf(v, "%dx%d", &o.width, &o.height) != 2) usage("--size wants WxH");
        } else if (a == "--spp") {
            o.spp.clear();
            std::stringstream list(v);
            for (std::string n; std::getline(list, n, ',');) o.spp.push_back(std::atoi(n.c_str()));
        } else if (a == "--ref-spp") {
            o.refSpp = std::atoi(v);
        } else if (a == "--scene") {
            o.scene = v;
        } else if (a == "--cache") {
            o.cache = v;
        } else if (a == "--out") {
            o.out = v;
        } else if (a == "--bias-map") {
            o.biasSeeds = std::atoi(v);
        } else if (a == "--iterations") {
            o.denoise.iterations = std::atoi(v);
        } else if (a == "--sigma-luminance") {
            o.denoise.sigmaLuminance = float(std::atof(v));
        } else if (a == "--sigma-normal") {
            o.denoise.sigmaNormal = float(std::atof(v));
        } else if (a == "--sigma-depth") {
            o.denoise.sigmaDepth = float(std::atof(v));
        } else if (a == "--sigma-albedo") {
            o.denoise.sigmaAlbedo = float(std::atof(v));
        } else {
            usage(("unknown option " + a).c_str());
        }
    }
    return o;
}

// Σ|a − b|² / 2 over the pixels the error counts, relative to Σ|r|²: the squared relative noise of one of two
// independent estimates whose difference a − b is.
double relativeNoiseSquared(const ImageF& a, const ImageF& b, const PathReference& ref) {
    double num = 0.0, den = 0.0;
    for (size_t i = 0, p = 0; i < a.rgba.size(); i += 4, ++p) {
        if (ref.image.rgba[i] > 1.0f) continue;
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[i + c]) - double(b.rgba[i + c]);
            num += 0.5 * d * d;
            den += double(ref.image.rgba[i + c]) * ref.image.rgba[i + c] - double(ref.variance[3 * p + c]);
        }
    }
    return num / den;
}

// Σ a / Σ r over the counted pixels and channels: how much lighter (> 1) or darker the image is on the whole.
double meanRatio(const ImageF& a, const PathReference& ref) {
    double num = 0.0, den = 0.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        if (ref.image.rgba[i] > 1.0f) continue;
        for (size_t c = 0; c < 3; ++c) {
            num += a.rgba[i + c];
            den += ref.image.rgba[i + c];
        }
    }
    return num / den;
}

}  // namespace

int main(int argc, char** argv) try {
    const Options o = parse(argc, argv);
    const auto scene = std::make_shared<const trace::TraceScene>(loadScene(o.scene));
    trace::PathSettings ps;
    ps.width = o.width;
    ps.height = o.height;
    ps.threads = 2;
    trace::PathSettings rs = ps;
    rs.spp = o.refSpp;
    rs.seed = 1;
    const PathReference ref = cachedReference(o.scene, scene, rs, ReferenceMethod::SplitHalves, o.cache);
    const SurfacePasses passes = trace::firstHitPasses(*scene, o.width, o.height, ps.threads);
    std::printf("%s at %dx%d against %d spp; %d iterations, sigma luminance %g, normal %g, depth %g, albedo %g\n",
                o.scene.c_str(), o.width, o.height, ref.spp, o.denoise.iterations, double(o.denoise.sigmaLuminance),
                double(o.denoise.sigmaNormal), double(o.denoise.sigmaDepth), double(o.denoise.sigmaAlbedo));
    if (!o.out.empty()) writePng(o.out + "/reference.png", toImage8(ref.image, Encoding::Srgb, {}, nullptr));
    std::printf("%6s %9s %9s %9s %9s %9s %7s\n", "spp", "raw", "denoised", "of raw", "noise", "bias", "mean");
    for (int spp : o.spp) {
        ImageF raw[2], denoised[2];
        double ms = 0.0;
        for (int k = 0; k < 2; ++k) {
            trace::PathSettings s = ps;
            s.spp = spp;
            s.seed = k == 0 ? 0u : 7u;
            trace::PathRender render(scene, s);
            render.addSamples(spp);
            raw[k] = render.image();
            const Clock::time_point t0 = Clock::now();
            denoised[k] = trace::denoisedImage(render, passes, o.denoise);
            ms += msSince(t0) / 2.0;
        }
        const double rawError = relativeRmse(raw[0], ref.image, &ref.variance);
        const double error = relativeRmse(denoised[0], ref.image, &ref.variance);
        const double noise2 = relativeNoiseSquared(denoised[0], denoised[1], ref);
        const double bias2 = std::max(0.0, error * error - noise2);
        std::printf("%6d %9.4f %9.4f %9.3f %9.4f %9.4f %7.4f   (denoise %.0f ms)\n", spp, rawError, error,
                    error / rawError, std::sqrt(noise2), std::sqrt(bias2), meanRatio(denoised[0], ref), ms);
        if (!o.out.empty()) {
            const std::string stem = o.out + "/" + std::to_string(spp);
            writeExr(stem + "-denoised.exr", exrFromImage(denoised[0]), ExrPrecision::Half);
            writePng(stem + "-denoised.png", toImage8(denoised[0], Encoding::Srgb, {}, nullptr));
            writePng(stem + "-raw.png", toImage8(raw[0], Encoding::Srgb, {}, nullptr));
        }
        if (!o.out.empty() && o.biasSeeds > 0) {
            // The mean of biasSeeds denoised images: its difference from the reference is the filter's bias
            // (and 1/biasSeeds of its noise), drawn as |mean − ref| / ref, 10 % a full step of 255 (grey).
            ImageF mean(o.width, o.height);
            for (int k = 0; k < o.biasSeeds; ++k) {
                trace::PathSettings s = ps;
                s.spp = spp;
                s.seed = 100u + unsigned(k);
                trace::PathRender render(scene, s);
                render.addSamples(spp);
                const ImageF d = trace::denoisedImage(render, passes, o.denoise);
                for (size_t i = 0; i < d.rgba.size(); ++i) mean.rgba[i] += d.rgba[i] / float(o.biasSeeds);
            }
            Image8 map{o.width, o.height, 4, std::vector<uint8_t>(4 * size_t(o.width) * size_t(o.height))};
            for (size_t i = 0, p = 0; i < mean.rgba.size(); i += 4, ++p) {
                float l = 0.0f, r = 0.0f;
                for (size_t c = 0; c < 3; ++c) {
                    l += mean.rgba[i + c];
                    r += ref.image.rgba[i + c];
                }
                const float rel = r > 0.0f ? (l - r) / r : 0.0f;  // red: too light, blue: too dark
                const auto v = uint8_t(std::min(255.0f, std::abs(rel) * 2550.0f));
                map.data[i] = rel > 0 ? v : 0;
                map.data[i + 1] = 0;
                map.data[i + 2] = rel < 0 ? v : 0;
                map.data[i + 3] = 255;
            }
            writePng(o.out + "/" + std::to_string(spp) + "-bias.png", map);
            writePng(o.out + "/" + std::to_string(spp) + "-mean.png", toImage8(mean, Encoding::Srgb, {}, nullptr));
            std::printf("       mean of %d seeds: error %.4f\n", o.biasSeeds,
                        relativeRmse(mean, ref.image, &ref.variance));
        }
    }
    return 0;
} catch (const std::exception& e) {
    std::fprintf(stderr, "denoise_quality: %s\n", e.what());
    return 1;
}
