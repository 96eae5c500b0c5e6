// Encoding: how linear colour becomes 8-bit (design.md §2), and its one name table: the words of
// `--encoding` and of viewer scripts. Parsing only; the conversion itself is encode.h.
#pragma once

#include "util/name_table.h"

namespace shadelab {

enum class Encoding { Srgb, Linear };

inline constexpr EnumName<Encoding> kEncodingNames[] = {
    {Encoding::Srgb, "srgb"},
    {Encoding::Linear, "linear"},
};

inline const char* toString(Encoding e) { return nameOf(kEncodingNames, e); }
inline std::optional<Encoding> parseEncoding(std::string_view name) { return lookupName(kEncodingNames, name); }

}  // namespace shadelab
