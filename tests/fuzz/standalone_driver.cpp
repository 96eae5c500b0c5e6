// A main() for the libFuzzer targets where there is no libFuzzer (GCC, the CI's compiler): it replays every file
// of the seed corpora, then runs a fixed-seed mutation loop (mutate.h) until a time or case budget is spent,
// calling LLVMFuzzerTestOneInput for each input. No coverage feedback; instead an input whose outcome
// (fuzz_outcome.h) is one not seen before joins the pool that later cases mutate, so that the loop reaches past
// the first parse error of each kind. Same flags as libFuzzer where they mean the same thing:
//   TARGET [-max_total_time=S] [-runs=N] [-seed=N] [-max_len=BYTES] [-timeout=S] [-rss_limit_mb=MB]
//          [-artifact_prefix=PATH] [-verbose=1] CORPUS_DIR_OR_FILE...
// A crash (a signal, a sanitizer report, an exception of a type the target does not document), an input that
// runs past -timeout, or a peak RSS past -rss_limit_mb saves the input as <artifact_prefix><kind>-<hash>, prints
// what the run wrote on stderr for it and fails. Run the saved file alone to see it again. While cases run,
// stderr (the loaders' warnings) is captured per case and dropped unless the case fails; -verbose=1 keeps it.
#include "fuzz_outcome.h"
#include "mutate.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
// The sanitizers' hook for their reports' end (GCC's and clang's runtimes); null without a sanitizer.
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace {

using shadelab::fuzz::Rng;
namespace fs = std::filesystem;

struct Options {
    double maxTotalTime = 15.0;  // seconds for replay and mutation together; the replay always completes
    uint64_t runs = UINT64_MAX;  // mutated cases at most
    uint64_t seed = 1;
    size_t maxLen = 256 << 10;  // bytes of a mutated case
    unsigned timeout = 30;      // seconds one case may take
    long rssLimitMb = 2048;     // peak resident memory
    std::string artifactPrefix = "./";
    bool verbose = false;
    std::vector<std::string> inputs;  // corpus folders and single files
};

// The case being run, for the signal handlers: they may only read these and call async-signal-safe functions.
const std::string* gCurrent = nullptr;
std::string gArtifactPrefix;
int gStderr = 2;    // the real stderr while fd 2 is the capture file
int gCapture = -1;  // the capture file, or -1 with -verbose=1
volatile sig_atomic_t gReported = 0;

void writeAll(int fd, const char* p, size_t n) {
    while (n > 0) {
        const ssize_t w = write(fd, p, n);
        if (w <= 0) return;
        p += w;
        n -= size_t(w);
    }
}
void say(const char* s) { writeAll(gStderr, s, std::strlen(s)); }

// What the failing case wrote on stderr (the sanitizer's report among it), onto the real stderr.
void replayCapture() {
    if (gCapture < 0) return;
    char buf[4096];
    if (lseek(gCapture, 0, SEEK_SET) < 0) return;
    ssize_t n;
    while ((n = read(gCapture, buf, sizeof buf)) > 0) writeAll(gStderr, buf, size_t(n));
}

// Saves the current case as <prefix><kind>-<FNV-1a hash> and says where; once per process.
void reportFailure(const char* kind) {
    if (gReported) return;
    gReported = 1;
    replayCapture();
    if (!gCurrent) {
        say("fuzz: failure outside any case\n");
        return;
    }
    uint64_t h = 0xcbf29ce484222325ull;
    for (char c : *gCurrent) h = (h ^ uint64_t(static_cast<unsigned char>(c))) * 0x100000001b3ull;
    char path[4096];
    std::snprintf(path, sizeof path, "%s%s-%016llx", gArtifactPrefix.c_str(), kind, (unsigned long long)h);
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        writeAll(fd, gCurrent->data(), gCurrent->size());
        close(fd);
    }
    say("fuzz: ");
    say(kind);
    say(": the input is saved as ");
    say(fd >= 0 ? path : "(could not be saved)");
    say("\n");
}

// Empties the capture file when the last case wrote to it (one lseek when it did not).
void clearCapture() {
    if (gCapture < 0 || lseek(gCapture, 0, SEEK_CUR) <= 0) return;
    if (ftruncate(gCapture, 0) != 0) return;
    lseek(gCapture, 0, SEEK_SET);
}

void onDeath() { reportFailure("crash"); }

void onSignal(int sig) {
    reportFailure(sig == SIGALRM ? "timeout" : "crash");
    if (sig == SIGALRM) _exit(70);
    signal(sig, SIG_DFL);
    raise(sig);
}

double parseNumber(const std::string& flag, const std::string& value) {
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !(v >= 0)) {
        std::fprintf(stderr, "fuzz: %s: expected a non-negative number, got '%s'\n", flag.c_str(), value.c_str());
        std::exit(2);
    }
    return v;
}

Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.size() < 2 || arg[0] != '-') {
            o.inputs.push_back(arg);
            continue;
        }
        const size_t eq = arg.find('=');
        const std::string flag = arg.substr(0, eq), value = eq == std::string::npos ? "" : arg.substr(eq + 1);
        if (flag == "-max_total_time")
            o.maxTotalTime = parseNumber(flag, value);
        else if (flag == "-runs")
            o.runs = uint64_t(parseNumber(flag, value));
        else if (flag == "-seed")
            o.seed = uint64_t(parseNumber(flag, value));
        else if (flag == "-max_len")
            o.maxLen = std::max<size_t>(1, size_t(parseNumber(flag, value)));
        else if (flag == "-timeout")
            o.timeout = unsigned(parseNumber(flag, value));
        else if (flag == "-rss_limit_mb")
            o.rssLimitMb = long(parseNumber(flag, value));
        else if (flag == "-artifact_prefix")
            o.artifactPrefix = value;
        else if (flag == "-verbose")
            o.verbose = parseNumber(flag, value) != 0;
        else {
            std::fprintf(stderr, "fuzz: unknown flag %s (standalone_driver.cpp lists them)\n", flag.c_str());
            std::exit(2);
        }
    }
    if (o.inputs.empty()) {
        std::fprintf(stderr, "fuzz: usage: %s [-max_total_time=S] [-runs=N] [-seed=N] ... CORPUS_DIR_OR_FILE...\n",
                     argv[0]);
        std::exit(2);
    }
    return o;
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Every regular file of the folders (sorted, so the pool and with it the run are the same everywhere) and the
// single files, in the order given.
std::vector<std::string> loadCorpus(const std::vector<std::string>& inputs) {
    std::vector<std::string> corpus;
    for (const std::string& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            std::vector<fs::path> files;
            for (const auto& entry : fs::directory_iterator(input, ec))
                if (entry.is_regular_file()) files.push_back(entry.path());
            std::sort(files.begin(), files.end());
            for (const fs::path& f : files) corpus.push_back(readBytes(f));
        } else if (fs::is_regular_file(input, ec)) {
            corpus.push_back(readBytes(input));
        } else {
            std::fprintf(stderr, "fuzz: %s: no such file or folder\n", input.c_str());
            std::exit(2);
        }
    }
    return corpus;
}

// An outcome's kind: the message without the stand-in file name the targets give ("fuzz.gltf: "), numbers as
// '#', its first three words up to any quoted text, and nothing after a '=' in a word (what follows a quote or a
// '=' is the input's own bytes).
// "accessors[3]: count 9 ..." and "accessors[7]: count 12 ..." are one kind, as are "resolution line '-Y 2e3'"
// and any other resolution line.
std::string outcomeKind(const std::string& message) {
    std::string s = message;
    if (s.compare(0, 4, "fuzz") == 0 && s.find(": ") != std::string::npos) s = s.substr(s.find(": ") + 2);
    std::string kind;
    int words = 0;
    bool inNumber = false, afterEquals = false;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (c == ' ' && ++words == 3) break;
        if (c == ' ') afterEquals = false;
        if (afterEquals) continue;
        afterEquals = c == '=';
        if (c == '\'' || c == '"' || c == '`') {
            kind += std::string(2, c);
            // A message that starts with a quoted name ("'byteLength' property is missing") goes on after it;
            // elsewhere the input's own text follows, quotes in it included, and the kind ends.
            const size_t end = s.find(c, i + 1);
            if (i > 0 || end == std::string::npos) break;
            i = end;
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            if (!inNumber) kind += '#';
            inNumber = true;
            continue;
        }
        inNumber = false;
        kind += c;
    }
    return kind.substr(0, 80);
}

std::string gOutcome;
void recordOutcome(const std::string& outcome) { gOutcome = outcome; }

long peakRssMb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024;  // Linux reports KiB
}

class Runner {
public:
    explicit Runner(const Options& o) : options_(o) {}

    // Runs one case; returns its outcome kind and whether it is the first of that kind.
    std::pair<std::string, bool> run(const std::string& input) {
        gCurrent = &input;
        gOutcome = "(no outcome noted)";
        clearCapture();
        alarm(options_.timeout);
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(input.data()), input.size());
        alarm(0);
        if (peakRssMb() > options_.rssLimitMb) {
            reportFailure("oom");
            std::fprintf(stdout, "fuzz: peak RSS %ld MB is past -rss_limit_mb=%ld\n", peakRssMb(), options_.rssLimitMb);
            std::exit(71);
        }
        gCurrent = nullptr;
        ++executions_;
        const std::string kind = outcomeKind(gOutcome);
        const bool first = ++outcomes_[kind] == 1;
        return {kind, first};
    }

    uint64_t executions() const { return executions_; }
    const std::map<std::string, uint64_t>& outcomes() const { return outcomes_; }

private:
    const Options& options_;
    uint64_t executions_ = 0;
    std::map<std::string, uint64_t> outcomes_;
};

}  // namespace

int main(int argc, char** argv) {
    const Options options = parseOptions(argc, argv);
    gArtifactPrefix = options.artifactPrefix;
    if (const fs::path folder = fs::path(gArtifactPrefix).parent_path(); !folder.empty()) {
        std::error_code ec;
        fs::create_directories(folder, ec);
    }
    const std::vector<std::string> corpus = loadCorpus(options.inputs);
    const std::string name = fs::path(argv[0]).filename().string();

    shadelab::fuzz::outcomeSink = recordOutcome;
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(onDeath);
    // Under a sanitizer its own handler reports a SIGSEGV with a stack; without one, ours saves the input.
    std::vector<int> signals = {SIGABRT, SIGALRM};
    if (!__sanitizer_set_death_callback) signals.insert(signals.end(), {SIGSEGV, SIGBUS, SIGFPE, SIGILL});
    for (int sig : signals) signal(sig, onSignal);
    if (!options.verbose) {
        std::fflush(stderr);
        gStderr = dup(2);
        FILE* capture = std::tmpfile();
        if (gStderr >= 0 && capture && dup2(fileno(capture), 2) >= 0)
            gCapture = fileno(capture);
        else
            gStderr = 2;
    }

    const auto start = std::chrono::steady_clock::now();
    const auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    Runner runner(options);
    for (const std::string& input : corpus) runner.run(input);
    const uint64_t replayed = runner.executions();

    // The pool: the corpus, then each input that reached a new outcome (a bounded number of them).
    std::vector<std::string> pool = corpus;
    if (pool.empty()) pool.push_back("");
    constexpr size_t kMaxPool = 1024;
    Rng rng(options.seed);
    uint64_t mutants = 0;
    while (mutants < options.runs && elapsed() < options.maxTotalTime) {
        const std::string input = shadelab::fuzz::mutate(pool[rng.below(pool.size())], pool, options.maxLen, rng);
        ++mutants;
        if (runner.run(input).second && pool.size() < kMaxPool) pool.push_back(input);
    }

    std::printf(
        "fuzz: %s: %llu executions (%llu corpus files, %llu mutated cases, seed %llu) in %.1f s; %zu distinct "
        "outcomes; %zu inputs in the pool\n",
        name.c_str(), (unsigned long long)runner.executions(), (unsigned long long)replayed,
        (unsigned long long)mutants, (unsigned long long)options.seed, elapsed(), runner.outcomes().size(),
        pool.size());
    // The most frequent outcomes first: what the run mostly exercised.
    std::vector<std::pair<std::string, uint64_t>> sorted(runner.outcomes().begin(), runner.outcomes().end());
    std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    for (size_t i = 0; i < sorted.size() && i < 25; ++i)
        std::printf("  %8llu  %s\n", (unsigned long long)sorted[i].second, sorted[i].first.c_str());
    return 0;
}
