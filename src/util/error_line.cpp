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

}  // namespace

std::string errorLine(const std::string& text, size_t cap) {
    std::string out;
    out.reserve(std::min(text.size(), cap) + 8);
    for (size_t i = 0; i < text.size() && out.size() <= cap;) {
        const char c = text[i];
        const auto u = static_cast<unsigned char>(c);
        const size_t n = utf8SequenceLength(text, i);
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
