// Distribution1D: a piecewise-constant discrete distribution over n weights, sampled by inverting its CDF
// (pbrt-v4 §A.4.1). The path tracer picks emitters and environment texels with it.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace shadelab::trace {

class Distribution1D {
public:
    Distribution1D() = default;
    // Negative or non-finite weights count as 0. All zero: empty().
    explicit Distribution1D(const std::vector<double>& weights) {
        cdf_.resize(weights.size());
        double sum = 0.0;
        for (size_t i = 0; i < weights.size(); ++i) {
            const double w = weights[i];
            sum += (w > 0.0 && w < 1e300) ? w : 0.0;
            cdf_[i] = sum;
        }
        total_ = sum;
        if (!(total_ > 0.0)) cdf_.clear();
    }

    bool empty() const { return cdf_.empty(); }
    size_t size() const { return cdf_.size(); }
    double total() const { return total_; }

    // The index whose CDF interval holds u ∈ [0, 1); never an index of weight 0.
    size_t sample(float u) const {
        const double target = double(u) * total_;
        const size_t i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin());
        return std::min(i, cdf_.size() - 1);
    }
    // Probability of index i.
    float probability(size_t i) const {
        if (i >= cdf_.size()) return 0.0f;
        return float((cdf_[i] - (i ? cdf_[i - 1] : 0.0)) / total_);
    }

private:
    std::vector<double> cdf_;
    double total_ = 0.0;
};

}  // namespace shadelab::trace
