// EnumName tables: the one list of words an enum is written as in scene files, flags and scripts, with the
// lookups both ways. Each enum keeps its table beside its definition; callers word their own errors (the
// flag, or the JSON path), listing the choices with nameChoices().
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

template <typename E>
struct EnumName {
    E value;
    const char* name;
    bool alias = false;  // accepted on input, never written, not listed among the choices
};

// The canonical name of `value`: its first entry that is not an alias.
template <typename E, size_t N>
constexpr const char* nameOf(const EnumName<E> (&table)[N], E value) {
    for (const EnumName<E>& e : table)
        if (!e.alias && e.value == value) return e.name;
    return "?";  // a value missing from its table: each table has a round-trip test
}

// The value named `name` (canonical or alias), matched exactly; nullopt for any other word.
template <typename E, size_t N>
constexpr std::optional<E> lookupName(const EnumName<E> (&table)[N], std::string_view name) {
    for (const EnumName<E>& e : table)
        if (name == e.name) return e.value;
    return std::nullopt;
}

// The canonical names in table order, e.g. to refuse or warn about other JSON keys.
template <typename E, size_t N>
std::vector<const char*> canonicalNames(const EnumName<E> (&table)[N]) {
    std::vector<const char*> names;
    for (const EnumName<E>& e : table)
        if (!e.alias) names.push_back(e.name);
    return names;
}

// "a, b or c" for an error message: the canonical names, then `extra` (e.g. "none") as one more choice.
template <typename E, size_t N>
std::string nameChoices(const EnumName<E> (&table)[N], const char* extra = nullptr) {
    std::vector<const char*> names = canonicalNames(table);
    if (extra) names.push_back(extra);
    std::string s;
    for (size_t i = 0; i < names.size(); ++i) {
        if (i > 0) s += i + 1 == names.size() ? " or " : ", ";
        s += names[i];
    }
    return s;
}

}  // namespace shadelab
