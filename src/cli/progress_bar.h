// ProgressBar: a one-line bar on stderr for long renders, drawn only when stderr is a terminal, so logs
// and CI output stay clean.
#pragma once

#include <unistd.h>
#include <cstdio>
#include <string>

namespace shadelab::cli {

class ProgressBar {
public:
    explicit ProgressBar(std::string label) : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1) {}
    ~ProgressBar() { finish(); }

    void update(float fraction) {
        if (!enabled_) return;
        int percent = int(fraction * 100.0f + 0.5f);
        if (percent == last_) return;
        last_ = percent;
        const int width = 30, filled = percent * width / 100;
        std::fprintf(stderr, "\r%s [%s%s] %3d%%", label_.c_str(), std::string(size_t(filled), '#').c_str(),
                     std::string(size_t(width - filled), ' ').c_str(), percent);
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_ && last_ >= 0) std::fprintf(stderr, "\r\033[K");
        last_ = -1;
    }

private:
    std::string label_;
    bool enabled_;
    int last_ = -1;
};

}  // namespace shadelab::cli
