// Broken and damaged models: every glTF/GLB file in Debian's assimp-testmodels, and damaged
// copies of valid ones (truncated at many offsets, bytes flipped under a fixed seed), run through
// `shadelab render`. Each must write a PNG, or exit 1 with one line that names the file; never crash or
// hang (10 s limit). Failures list every offending file and its output.
#include "test_output.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

const fs::path kModels = "/usr/share/assimp/models";

struct Outcome {
    int code = -1;
    std::string out;
};

Outcome renderFile(const std::string& model, const std::string& png) {
    std::string cmd = "timeout -s KILL 10 " + std::string(SHADELAB_BINARY) + " render '" + model + "' -o '" + png +
                      "' --size 48x32 2>&1";
    Outcome o;
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return o;
    std::array<char, 4096> buf;
    while (size_t n = fread(buf.data(), 1, buf.size(), p)) o.out.append(buf.data(), n);
    int status = pclose(p);
    o.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return o;
}

// Empty when the outcome keeps the promise; otherwise why not.
std::string check(const std::string& model, const std::string& png, const Outcome& o) {
    std::vector<std::string> errors;
    size_t start = 0;
    while (start < o.out.size()) {
        size_t end = o.out.find('\n', start);
        std::string line = o.out.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (!line.empty() && line.find("warning:") == std::string::npos) errors.push_back(line);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (o.code == 0) return fs::exists(png) ? "" : "exit 0 but no PNG";
    if (o.code != 1) return "exit " + std::to_string(o.code) + (o.code == 137 ? " (killed after 10 s)" : " (crash?)");
    if (fs::exists(png)) return "exit 1 but a PNG was written";
    if (errors.size() != 1) return "expected one error line, got " + std::to_string(errors.size());
    if (errors[0].find(fs::path(model).filename().string()) == std::string::npos)
        return "the error does not name the file";
    return "";
}

std::vector<fs::path> corpus() {
    std::vector<fs::path> files;
    for (const char* dir : {"glTF2", "glTF"}) {
        if (!fs::exists(kModels / dir)) continue;
        for (const auto& e : fs::recursive_directory_iterator(kModels / dir)) {
            std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(e.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

TEST(ModelCorpus, EveryFileRendersOrFailsCleanly) {
    std::vector<fs::path> files = corpus();
    if (files.empty()) GTEST_SKIP() << "assimp-testmodels is not installed (" << kModels << ")";
    EXPECT_GE(files.size(), 40u);
    int rendered = 0, refused = 0;
    std::string failures;
    for (const fs::path& f : files) {
        std::string png = test::outputPath("corpus.png");
        fs::remove(png);
        Outcome o = renderFile(f.string(), png);
        std::string why = check(f.string(), png, o);
        if (!why.empty()) failures += f.string() + ": " + why + "\n" + o.out + "\n";
        (o.code == 0 ? rendered : refused)++;
    }
    std::printf("%zu files: %d rendered, %d refused with one line\n", files.size(), rendered, refused);
    EXPECT_TRUE(failures.empty()) << failures;
    EXPECT_GT(rendered, 20) << "most of the corpus is valid and should render";
    EXPECT_GT(refused, 3) << "the corpus holds known-broken files (IndexOutOfRange, MissingBin, ...)";
}

TEST(ModelCorpus, DamagedCopiesFailCleanly) {
    const std::vector<fs::path> seeds = {kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                                         kModels / "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf",
                                         fs::path(SHADELAB_SOURCE_DIR) / "assets/models/torus.gltf"};
    std::mt19937 rng(6);  // fixed seed: the same damage every run
    std::string failures;
    int runs = 0;
    for (const fs::path& seed : seeds) {
        if (!fs::exists(seed)) continue;
        std::ifstream in(seed, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::vector<std::string> copies;
        for (int i = 1; i <= 12; ++i) copies.push_back(bytes.substr(0, bytes.size() * size_t(i) / 13));  // truncated
        for (int i = 0; i < 12; ++i) {  // 1 to 8 bytes flipped at random places
            std::string c = bytes;
            int flips = 1 + int(rng() % 8);
            for (int k = 0; k < flips; ++k) c[rng() % c.size()] ^= char(1 + rng() % 255);
            copies.push_back(c);
        }
        for (size_t i = 0; i < copies.size(); ++i) {
            std::string name = "damaged_" + std::to_string(i) + seed.extension().string();
            std::string path = test::outputPath(name), png = test::outputPath("damaged.png");
            std::ofstream(path, std::ios::binary) << copies[i];
            fs::remove(png);
            Outcome o = renderFile(path, png);
            std::string why = check(path, png, o);
            if (!why.empty())
                failures += seed.filename().string() + " copy " + std::to_string(i) + ": " + why + "\n" + o.out;
            ++runs;
        }
    }
    if (runs == 0) GTEST_SKIP() << "no seed models found";
    EXPECT_TRUE(failures.empty()) << failures;
}

// The checker itself must reject each broken promise, or the tests above prove nothing.
TEST(ModelCorpus, CheckerRejectsBrokenPromises) {
    const std::string model = "/x/broken.glb", png = test::outputPath("never_written.png");
    fs::remove(png);
    EXPECT_EQ(check(model, png, {1, "shadelab: error: /x/broken.glb: accessors[0]: out of range\n"}), "");
    EXPECT_NE(check(model, png, {139, "Segmentation fault\n"}), "");
    EXPECT_NE(check(model, png, {137, ""}), "");
    EXPECT_NE(check(model, png, {1, "shadelab: error: something went wrong\n"}), "") << "must name the file";
    EXPECT_NE(check(model, png, {1, "error: /x/broken.glb: a\nerror: /x/broken.glb: b\n"}), "") << "one line";
    EXPECT_NE(check(model, png, {0, ""}), "") << "exit 0 needs a PNG";
    EXPECT_EQ(check(model, png, {1, "shadelab: warning: /x/broken.glb: odd\nshadelab: error: /x/broken.glb: bad\n"}),
              "");
}
