// A small command-line parser: positionals, --flag, --option value (or --option=value). Unknown options
// and missing values are UsageErrors (exit code 2).
#pragma once

#include "util/input_error.h"
#include "util/name_table.h"

#include <optional>
#include <string>
#include <vector>

namespace shadelab::cli {

class Args {
public:
    // `valued` lists the options that take a value; every other --name is a flag.
    Args(int argc, char** argv, int first, std::vector<std::string> valued, std::vector<std::string> flags);

    bool flag(const std::string& name) const;
    std::optional<std::string> value(const std::string& name) const;
    const std::vector<std::string>& positionals() const { return positionals_; }

private:
    std::vector<std::string> valued_, flags_, seenFlags_;
    std::vector<std::pair<std::string, std::string>> values_;
    std::vector<std::string> positionals_;
};

// A whole number in [lo, hi] for option `name`. Throws UsageError naming the option.
int parseInt(const std::string& name, const std::string& value, int lo, int hi);

// A whole number, possibly negative, for option `name` whose range a render request checks
// (render/render_request.h). Throws UsageError naming the option when it is not one.
int parseWhole(const std::string& name, const std::string& value);

// A number (NaN and infinities included: a render request refuses them by field) for option `name`. Throws
// UsageError naming the option when it is not one.
double parseReal(const std::string& name, const std::string& value);

// A finite number in [lo, hi] for option `name`. Throws UsageError naming the option.
float parseNumber(const std::string& name, const std::string& value, float lo, float hi);

// "1920x1080" → {1920, 1080}: two whole numbers of up to six digits (a render request checks their range).
// Throws UsageError naming --size.
std::pair<int, int> parseSize(const std::string& s);

// The word `value` of option `name`, looked up in an enum's name table (util/name_table.h). Throws
// UsageError "<name>: expected a, b or c, got '<value>'", listing the table's names.
template <typename E, size_t N>
E parseChoice(const std::string& name, const std::string& value, const EnumName<E> (&table)[N]) {
    if (auto v = lookupName(table, value)) return *v;
    throw UsageError(name + ": expected " + nameChoices(table) + ", got '" + value + "'");
}

}  // namespace shadelab::cli
