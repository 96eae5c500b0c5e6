// Command-line parsing helpers.
#include "cli/args.h"

#include "util/input_error.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace shadelab::cli {
namespace {
bool contains(const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
}
}  // namespace

Args::Args(int argc, char** argv, int first, std::vector<std::string> valued, std::vector<std::string> flags)
    : valued_(std::move(valued)), flags_(std::move(flags)) {
    bool onlyPositionals = false;
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (onlyPositionals || a.size() < 2 || a[0] != '-' || a == "-") {
            positionals_.push_back(a);
            continue;
        }
        if (a == "--") {
            onlyPositionals = true;
            continue;
        }
        std::string name = a, val;
        bool hasInline = false;
        if (size_t eq = a.find('='); eq != std::string::npos) {
            name = a.substr(0, eq);
            val = a.substr(eq + 1);
            hasInline = true;
        }
        if (contains(valued_, name)) {
            if (!hasInline) {
                if (i + 1 >= argc) throw UsageError(name + " needs a value");
                val = argv[++i];
            }
            values_.emplace_back(name, val);
        } else if (contains(flags_, name) && !hasInline) {
            seenFlags_.push_back(name);
        } else {
            throw UsageError("unknown option '" + a + "' (see --help)");
        }
    }
}

bool Args::flag(const std::string& name) const { return contains(seenFlags_, name); }

std::optional<std::string> Args::value(const std::string& name) const {
    std::optional<std::string> last;
    for (const auto& [n, v] : values_)
        if (n == name) last = v;
    return last;
}

int parseInt(const std::string& name, const std::string& value, int lo, int hi) {
    const std::string what = name + ": expected a whole number from " + std::to_string(lo) + " to " +
                             std::to_string(hi) + ", got '" + value + "'";
    if (value.empty() || value.size() > 9 || value.find_first_not_of("0123456789") != std::string::npos)
        throw UsageError(what);
    int v = std::atoi(value.c_str());
    if (v < lo || v > hi) throw UsageError(what);
    return v;
}

int parseWhole(const std::string& name, const std::string& value) {
    const size_t digits = value.size() - (value.rfind('-', 0) == 0 ? 1 : 0);
    if (digits == 0 || digits > 9 || value.find_first_not_of("0123456789", value.size() - digits) != std::string::npos)
        throw UsageError(name + ": expected a whole number, got '" + value + "'");
    return std::atoi(value.c_str());
}

double parseReal(const std::string& name, const std::string& value) {
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (value.empty() || std::isspace(static_cast<unsigned char>(value[0])) || *end != '\0')
        throw UsageError(name + ": expected a number, got '" + value + "'");
    return v;
}

float parseNumber(const std::string& name, const std::string& value, float lo, float hi) {
    char range[64];
    std::snprintf(range, sizeof range, "from %g to %g", double(lo), double(hi));
    char* end = nullptr;
    const float v = std::strtof(value.c_str(), &end);
    if (value.empty() || std::isspace(static_cast<unsigned char>(value[0])) || *end != '\0' || !(v >= lo && v <= hi))
        throw UsageError(name + ": expected a number " + range + ", got '" + value + "'");
    return v;
}

std::pair<int, int> parseSize(const std::string& s) {
    const std::string what = "--size: expected WxH such as 1280x720, got '" + s + "'";
    size_t x = s.find_first_of("xX");
    if (x == std::string::npos || x == 0 || x + 1 >= s.size()) throw UsageError(what);
    auto side = [&](const std::string& part) {
        if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos) throw UsageError(what);
        if (part.size() > 6) throw UsageError(what);
        return std::atoi(part.c_str());
    };
    return {side(s.substr(0, x)), side(s.substr(x + 1))};
}

}  // namespace shadelab::cli
