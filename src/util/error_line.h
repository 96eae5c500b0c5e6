// errorLine: how every message reaches the terminal: one line, whatever the text inside it.
// Control characters from user strings (a newline in a light's name, ANSI escapes, a NUL) are escaped,
// and the line is capped so a huge data: URI or name list cannot flood the screen.
#pragma once

#include <cstddef>
#include <string>

namespace shadelab {

inline constexpr size_t kMaxErrorLineChars = 300;  // characters (bytes) before the "…"

// `text` with control characters (< 0x20, 0x7f) written as \n, \t, \r or \xNN, cut to at most `cap` bytes
// (on a UTF-8 character boundary) and ended with "…" when cut.
std::string errorLine(const std::string& text, size_t cap = kMaxErrorLineChars);

}  // namespace shadelab
