// `shadelab compare a.png b.png` (8-bit gates) or `a.exr b.exr` (linear-light gates): metrics, gates and the
// evidence files. Exit codes differ from the other
// commands so that scripts can gate on them: 0 within the gates, 1 outside them, 2 for any error (bad file, usage).
#include "cli/compare_command.h"

#include "cli/args.h"
#include "compare/compare_report.h"
#include "compare/coverage_image.h"
#include "compare/image_compare.h"
#include "compare/linear_compare.h"
#include "image/exr.h"
#include "image/png.h"
#include "util/input_error.h"
#include "util/messages.h"
#include "util/output_file.h"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::cli {
namespace {

const char* const kCompareHelp =
    "usage: shadelab compare a.png b.png [options]\n"
    "       shadelab compare a.exr b.exr [options]\n"
    "\n"
    "Compares two images of the same size under the gates of design.md §4 and prints the metrics: mean,\n"
    "RMS and maximum difference (with its position and channel) and the fraction of pixels over the\n"
    "threshold. Differences are in 8-bit units. Without coverage data every pixel counts as interior; with\n"
    "the two images' coverage (`shadelab render --coverage`), pixels on a silhouette form the band, which\n"
    "only the coverage gate judges, as the renderers' own comparisons do.\n"
    "Two OpenEXR files are compared in linear light instead, by relative differences: per pixel the largest\n"
    "over R, G, B of |a-b| / (max(|a|,|b|) + floor), and the relative RMSE. A .png and an .exr cannot be\n"
    "compared with each other.\n"
    "\n"
    "options:\n"
    "  --diff PATH              write a heatmap of |a-b| (amplified) as PNG; - for stdout\n"
    "  --json PATH              write the full report as JSON; - for stdout\n"
    "  --max-fraction F         fraction of pixels allowed over the threshold (default 0.001)\n"
    "  --gain G                 heatmap amplification (default 16)\n"
    "  --coverage-a PATH        a.png's coverage ids (PNG from `shadelab render --coverage`); needs\n"
    "  --coverage-b PATH        both, each the size of its image; PNG comparisons only\n"
    "PNG gates (8-bit units):\n"
    "  --threshold T            a pixel is over when any channel differs by more than T (default 3)\n"
    "  --hard-max M             no channel may differ by more than M (default 16)\n"
    "  --max-mean X             also gate the mean absolute difference (8-bit units; default: no gate)\n"
    "EXR gates (relative, linear light):\n"
    "  --rel-threshold R        a pixel is over when its relative difference exceeds R (default 0.05)\n"
    "  --rel-hard-max R         no pixel's relative difference may exceed R (default 0.25)\n"
    "  --max-rel-rmse R         relative RMSE allowed: RMS(a-b) / RMS((|a|+|b|)/2) (default 0.01)\n"
    "  --floor V                radiance added to each denominator, so near-black noise is measured\n"
    "                           against V (default 0.01; 1 is display white)\n"
    "  -q, --quiet              print only the verdict line\n"
    "  -h, --help               show this help\n"
    "\n"
    "With --diff - or --json -, the summary goes to stderr. An output that is one of the two images, or an\n"
    "existing file that is not a regular file (device, FIFO, directory), is refused.\n"
    "exit codes: 0 within the gates, 1 outside them, 2 on an error (unreadable file, size mismatch, refused\n"
    "output, usage)\n";

double parseDouble(const std::string& name, const std::string& v, double lo, double hi) {
    char* end = nullptr;
    double d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !(d >= lo && d <= hi))
        throw UsageError(name + ": expected a number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                         ", got '" + v + "'");
    return d;
}

// A coverage PNG, its header checked against its image's size before it is decoded.
std::vector<uint32_t> readCoverage(const std::string& path, const PngFile& image) {
    const PngFile file = readPngFile(path);
    if (file.width != image.width || file.height != image.height)
        throw InputError(path, "coverage is " + std::to_string(file.width) + "x" + std::to_string(file.height) +
                                   ", its image " + image.path + " is " + std::to_string(image.width) + "x" +
                                   std::to_string(image.height));
    return coverageFromImage(decodePng(file), path);
}

}  // namespace

int compareCommand(int argc, char** argv) {
    try {
        Args args(argc, argv, 2,
                  {"--diff", "--json", "--threshold", "--max-fraction", "--hard-max", "--max-mean", "--gain",
                   "--rel-threshold", "--rel-hard-max", "--max-rel-rmse", "--floor", "--coverage-a", "--coverage-b"},
                  {"-h", "--help", "-q", "--quiet"});
        if (args.flag("-h") || args.flag("--help")) {
            std::fputs(kCompareHelp, stdout);
            return 0;
        }
        if (args.positionals().size() != 2)
            throw UsageError("compare takes two PNG files or two EXR files (see --help)");
        const std::string& pathA = args.positionals()[0];
        const std::string& pathB = args.positionals()[1];
        // The kind of comparison is the files' extension: two .exr in linear light, else the 8-bit gates.
        const bool exr = hasExrExtension(pathA);
        if (exr != hasExrExtension(pathB))
            throw UsageError("compare: " + (exr ? pathA : pathB) + " is an OpenEXR image and " + (exr ? pathB : pathA) +
                             " is not; compare two .png files (8-bit gates) or two .exr files (linear light)");
        for (const char* flag :
             exr ? std::vector<const char*>{"--threshold", "--hard-max", "--max-mean"}
                 : std::vector<const char*>{"--rel-threshold", "--rel-hard-max", "--max-rel-rmse", "--floor"})
            if (args.value(flag))
                throw UsageError(
                    std::string(flag) + ": " +
                    (exr ? "an 8-bit gate; two .exr files are compared in " + std::string("linear light (see --help)")
                         : "a linear-light gate, only for two .exr files"));
        const std::optional<std::string> coverageA = args.value("--coverage-a"), coverageB = args.value("--coverage-b");
        if (coverageA.has_value() != coverageB.has_value())
            throw UsageError(std::string(coverageA ? "--coverage-a" : "--coverage-b") + ": needs " +
                             (coverageA ? "--coverage-b" : "--coverage-a") +
                             " too (the band is both images' silhouettes)");
        if (coverageA && exr) throw UsageError("--coverage-a: only for two .png files");
        CompareGates gates;
        if (auto v = args.value("--threshold")) gates.threshold = parseInt("--threshold", *v, 0, 255);
        if (auto v = args.value("--max-fraction")) gates.maxFractionOver = parseDouble("--max-fraction", *v, 0, 1);
        if (auto v = args.value("--hard-max")) gates.hardMax = parseInt("--hard-max", *v, 0, 255);
        if (auto v = args.value("--max-mean")) gates.maxMean = parseDouble("--max-mean", *v, 0, 255);
        LinearGates linearGates;
        linearGates.maxFractionOver = gates.maxFractionOver;
        if (auto v = args.value("--rel-threshold")) linearGates.threshold = parseDouble("--rel-threshold", *v, 0, 1e6);
        if (auto v = args.value("--rel-hard-max")) linearGates.hardMax = parseDouble("--rel-hard-max", *v, 0, 1e6);
        if (auto v = args.value("--max-rel-rmse"))
            linearGates.maxRelativeRmse = parseDouble("--max-rel-rmse", *v, 0, 1e6);
        if (auto v = args.value("--floor")) linearGates.floor = parseDouble("--floor", *v, 0, 1e6);
        int gain = 16;
        if (auto v = args.value("--gain")) gain = parseInt("--gain", *v, 1, 255);

        const std::optional<std::string> diffPath = args.value("--diff"), jsonPath = args.value("--json");
        if (diffPath && jsonPath && isStdout(*diffPath) && isStdout(*jsonPath))
            throw UsageError("--diff and --json cannot both write to stdout");
        // Before reading anything: an output must not replace either image (nor be a device, a FIFO, ...).
        std::vector<std::string> inputs = {pathA, pathB};
        if (coverageA) inputs.insert(inputs.end(), {*coverageA, *coverageB});
        if (diffPath) checkOutput(*diffPath, "--diff", inputs);
        if (jsonPath) checkOutput(*jsonPath, "--json", inputs);
        // With an output on stdout, stdout carries only that output.
        FILE* summary = (diffPath && isStdout(*diffPath)) || (jsonPath && isStdout(*jsonPath)) ? stderr : stdout;

        if (exr) {
            const ExrImage ea = readExr(pathA);
            const ExrImage eb = readExr(pathB);
            if (ea.width != eb.width || ea.height != eb.height)
                throw InputError(pathB, "image sizes differ: " + std::to_string(ea.width) + "x" +
                                            std::to_string(ea.height) + " (" + pathA + ") vs " +
                                            std::to_string(eb.width) + "x" + std::to_string(eb.height));
            const LinearCompareResult r = compareLinear(colourOf(ea, pathA), colourOf(eb, pathB), linearGates);
            if (diffPath) {
                const std::vector<uint8_t> png = encodePng(linearHeatmap(r, gain));
                writeOutput(*diffPath, png.data(), png.size());
            }
            if (jsonPath) {
                const std::string json = linearReportJson(r, pathA, pathB);
                writeOutput(*jsonPath, json.data(), json.size());
            }
            if (args.flag("-q") || args.flag("--quiet"))
                std::fprintf(summary, "%s\n", r.pass ? "PASS" : "FAIL");
            else
                std::fputs(linearSummary(r).c_str(), summary);
            return r.pass ? 0 : 1;
        }
        // Both headers before either image is decoded: a mismatch or a decompression bomb costs nothing.
        const PngFile fileA = readPngFile(pathA), fileB = readPngFile(pathB);
        if (fileA.width != fileB.width || fileA.height != fileB.height)
            throw InputError(pathB, "image sizes differ: " + std::to_string(fileA.width) + "x" +
                                        std::to_string(fileA.height) + " (" + pathA + ") vs " +
                                        std::to_string(fileB.width) + "x" + std::to_string(fileB.height));
        Image8 a = decodePng(fileA), b = decodePng(fileB);
        std::vector<uint32_t> idsA, idsB;
        if (coverageA) {
            idsA = readCoverage(*coverageA, fileA);
            idsB = readCoverage(*coverageB, fileB);
        }
        CompareResult r = coverageA ? compareImages(a, b, idsA, idsB, gates) : compareImages(a, b, gates);
        if (diffPath) {
            const std::vector<uint8_t> png =
                encodePng(coverageA ? diffHeatmap(a, b, r.bandMask, gain) : diffHeatmap(a, b, gain));
            writeOutput(*diffPath, png.data(), png.size());
        }
        if (jsonPath) {
            const std::string json = compareReportJson(r, pathA, pathB);
            writeOutput(*jsonPath, json.data(), json.size());
        }
        if (args.flag("-q") || args.flag("--quiet"))
            std::fprintf(summary, "%s\n", r.pass ? "PASS" : "FAIL");
        else
            std::fputs(compareSummary(r).c_str(), summary);
        return r.pass ? 0 : 1;
    } catch (const UsageError& e) {
        printUsageError(e.what());
        return 2;
    } catch (const std::exception& e) {
        printError(e.what());
        return 2;
    }
}

}  // namespace shadelab::cli
