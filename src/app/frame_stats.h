// FrameStats: frame times for --stats (median and 95th percentile, nearest-rank). Pure data.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace shadelab::app {

class FrameStats {
public:
    void add(double ms) { ms_.push_back(ms); }
    size_t count() const { return ms_.size(); }
    // Nearest-rank percentile, p in (0, 100]; 0 when empty.
    double percentile(double p) const {
        if (ms_.empty()) return 0.0;
        std::vector<double> v = ms_;
        std::sort(v.begin(), v.end());
        const size_t rank = size_t(std::ceil(p / 100.0 * double(v.size())));
        return v[std::min(v.size(), std::max<size_t>(rank, 1)) - 1];
    }
    double median() const { return percentile(50.0); }

private:
    std::vector<double> ms_;
};

}  // namespace shadelab::app
