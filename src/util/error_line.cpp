// errorLine: validate UTF-8 and escape, then cap on a character boundary.
#include "util/error_line.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace shadelab {
namespace {

void appendHex(std::string& out, unsigned char u) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02x", u);
    out += buf;
}

// The length of the well-formed UTF-8 sequence starting at text[i] (RFC 3629, table 3-7 of the Unicode
// standard), or 0 when the byte there does not start one.
size_t utf8Length(const std::string& text, size_t i) {
    const auto at = [&](size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
    const unsigned b0 = at(0);
    const auto cont = [&](size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) { return at(k) >= lo && at(k) <= hi; };
    if (b0 < 0x80) return 1;
    if (b0 >= 0xC2 && b0 <= 0xDF) return cont(1) ? 2 : 0;
    if (b0 == 0xE0) return cont(1, 0xA0) && cont(2) ? 3 : 0;        // no overlong forms
    if (b0 == 0xED) return cont(1, 0x80, 0x9F) && cont(2) ? 3 : 0;  // no surrogates
    if (b0 >= 0xE1 && b0 <= 0xEF) return cont(1) && cont(2) ? 3 : 0;
    if (b0 == 0xF0) return cont(1, 0x90) && cont(2) && cont(3) ? 4 : 0;
    if (b0 == 0xF4) return cont(1, 0x80, 0x8F) && cont(2) && cont(3) ? 4 : 0;  // nothing past U+10FFFF
    if (b0 >= 0xF1 && b0 <= 0xF3) return cont(1) && cont(2) && cont(3) ? 4 : 0;
    return 0;  // a continuation byte alone, C0/C1 (overlong), or F5..FF
}

}  // namespace

std::string errorLine(const std::string& text, size_t cap) {
    std::string out;
    out.reserve(std::min(text.size(), cap) + 8);
    for (size_t i = 0; i < text.size() && out.size() <= cap;) {
        const char c = text[i];
        const auto u = static_cast<unsigned char>(c);
        const size_t n = utf8Length(text, i);
        if (n == 0) {
            appendHex(out, u);  // not UTF-8: the byte itself, so nothing reaches the terminal raw
            ++i;
            continue;
        }
        if (c == '\n')
            out += "\\n";
        else if (c == '\t')
            out += "\\t";
        else if (c == '\r')
            out += "\\r";
        else if (u < 0x20 || u == 0x7f)
            appendHex(out, u);
        else if (n == 2 && u == 0xC2 && static_cast<unsigned char>(text[i + 1]) <= 0x9F) {
            appendHex(out, u);  // a C1 control, U+0080..U+009F: U+009B is a CSI to many terminals
            appendHex(out, static_cast<unsigned char>(text[i + 1]));
        } else
            out.append(text, i, n);
        i += n;
    }
    if (out.size() <= cap) return out;
    size_t cut = cap;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 sequence
    out.resize(cut);
    return out + "\xE2\x80\xA6";  // …
}

}  // namespace shadelab
