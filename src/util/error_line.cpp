// errorLine: escape, then cap on a UTF-8 boundary.
#include "util/error_line.h"

#include <algorithm>
#include <cstdio>

namespace shadelab {

std::string errorLine(const std::string& text, size_t cap) {
    std::string out;
    out.reserve(std::min(text.size(), cap) + 8);
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n')
            out += "\\n";
        else if (c == '\t')
            out += "\\t";
        else if (c == '\r')
            out += "\\r";
        else if (u < 0x20 || u == 0x7f) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", u);
            out += buf;
        } else {
            out += c;
        }
        if (out.size() > cap) break;
    }
    if (out.size() <= cap) return out;
    size_t cut = cap;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 sequence
    out.resize(cut);
    return out + "\xE2\x80\xA6";  // …
}

}  // namespace shadelab
