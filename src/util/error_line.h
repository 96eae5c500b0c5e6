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

// The length of the well-formed UTF-8 sequence that starts at text[i] (RFC 3629; table 3-7 of the Unicode
// standard), or 0 when the byte there starts none: a continuation byte alone, an overlong form, a
// surrogate, a code point past U+10FFFF, or a sequence cut short.
inline size_t utf8SequenceLength(const std::string& text, size_t i) {
    const auto at = [&](size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
    const auto cont = [&](size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) { return at(k) >= lo && at(k) <= hi; };
    const unsigned b0 = at(0);
    if (b0 < 0x80) return 1;
    if (b0 >= 0xC2 && b0 <= 0xDF) return cont(1) ? 2 : 0;
    if (b0 == 0xE0) return cont(1, 0xA0) && cont(2) ? 3 : 0;
    if (b0 == 0xED) return cont(1, 0x80, 0x9F) && cont(2) ? 3 : 0;
    if (b0 >= 0xE1 && b0 <= 0xEF) return cont(1) && cont(2) ? 3 : 0;
    if (b0 == 0xF0) return cont(1, 0x90) && cont(2) && cont(3) ? 4 : 0;
    if (b0 == 0xF4) return cont(1, 0x80, 0x8F) && cont(2) && cont(3) ? 4 : 0;
    if (b0 >= 0xF1 && b0 <= 0xF3) return cont(1) && cont(2) && cont(3) ? 4 : 0;
    return 0;
}

// `text` as an exception's message can hold it: each NUL and each byte that is not well-formed UTF-8 written
// as \xNN (as errorLine writes them). what() is a C string, so a NUL would cut the message short, and
// Python turns what() into str only when it is UTF-8 (else the message is lost). Control characters are
// left for errorLine to escape where the message is printed.
// Inline, so that the header-only exceptions of util/input_error.h can use it without a library.
inline std::string escapeForMessage(const std::string& text) {
    static const char* hex = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const auto u = static_cast<unsigned char>(text[i]);
        const size_t n = u == 0 ? 0 : utf8SequenceLength(text, i);
        if (n == 0) {
            out += {'\\', 'x', hex[u >> 4], hex[u & 15]};
            ++i;
        } else {
            out.append(text, i, n);
            i += n;
        }
    }
    return out;
}

}  // namespace shadelab
