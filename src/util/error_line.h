// errorLine: how every message reaches the terminal: one line, whatever the text inside it.
// Control characters from user strings (a newline in a light's name, ANSI escapes, a NUL, the C1 controls
// such as U+009B, a terminal's one-byte CSI) and bytes that are not UTF-8 are escaped, and the line is
// capped so a huge data: URI or name list cannot flood the screen.
#pragma once

#include <cstddef>
#include <string>

namespace shadelab {

inline constexpr size_t kMaxErrorLineChars = 300;  // characters (bytes) before the "…"

// `text` with C0 controls (< 0x20) and DEL written as \n, \t, \r or \xNN, each C1 control (U+0080..U+009F)
// as the \xNN of its two UTF-8 bytes, and each byte that is not part of well-formed UTF-8 (RFC 3629: no
// overlong forms, no surrogates, nothing past U+10FFFF) as \xNN; cut to at most `cap` bytes (on a UTF-8
// character boundary) and ended with "…" when cut. The result is valid UTF-8 with no control character.
std::string errorLine(const std::string& text, size_t cap = kMaxErrorLineChars);

// `text` with each NUL written as \x00 (as errorLine writes it), so that a message holding a user string
// survives being a C string: an exception's what() and Python's str() of it keep what follows the NUL.
// Every other byte is left for errorLine to escape where the message is printed.
// Inline, so that the header-only exceptions of util/input_error.h can use it without a library.
inline std::string escapeNul(std::string text) {
    for (size_t at = text.find('\0'); at != std::string::npos; at = text.find('\0', at + 4))
        text.replace(at, 1, "\\x00");
    return text;
}

}  // namespace shadelab
