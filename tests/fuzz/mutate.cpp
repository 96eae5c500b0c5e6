// mutate: a stack of byte-level and number-level edits, each chosen by the Rng.
#include "mutate.h"

#include <algorithm>
#include <cctype>

namespace shadelab::fuzz {
namespace {

// Bytes that sit on the edges of the formats' fields: 0 and 255, signed-byte limits, Radiance's run-length
// markers (2, 128 + n), ASCII structure.
constexpr unsigned char kInterestingBytes[] = {0,    1,   2,   3,   4,   7,   8,   0x7f, 0x80, 0x81, 0xfe, 0xff,
                                               '\n', '"', ',', ':', '[', ']', '{', '}',  '-',  '.',  'e',  '0'};

// Tokens that change a JSON document's structure rather than a value.
const char* const kTokens[] = {"{",    "}",    "[",     "]",  ",",  ":",    "\"",
                               "null", "true", "false", "[]", "{}", "\"\"", "\\u0000"};

// Where a decimal number in text starts and how long it is: [-+]?digits[.digits][(e|E)[-+]?digits], not
// preceded by a letter, digit, '_' or '.' (so TEXCOORD_0 and v1.2 keep their names).
struct Span {
    size_t pos = 0, len = 0;
};

size_t numberAt(const std::string& s, size_t i) {
    size_t j = i;
    if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
    const size_t digits = j;
    while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
    if (j < s.size() && s[j] == '.') {
        ++j;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
    }
    if (j == digits || (j == digits + 1 && s[digits] == '.')) return 0;
    if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
        size_t k = j + 1;
        if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
        const size_t expDigits = k;
        while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
        if (k > expDigits) j = k;
    }
    return j - i;
}

// One number of `s` chosen uniformly (reservoir sampling over a single pass); len 0 when there is none.
Span pickNumber(const std::string& s, Rng& rng) {
    Span chosen;
    size_t seen = 0;
    for (size_t i = 0; i < s.size();) {
        const unsigned char prev = i > 0 ? static_cast<unsigned char>(s[i - 1]) : ' ';
        const size_t len = std::isalnum(prev) || prev == '_' || prev == '.' ? 0 : numberAt(s, i);
        if (len == 0) {
            ++i;
            continue;
        }
        if (rng.below(++seen) == 0) chosen = Span{i, len};
        i += len;
    }
    return chosen;
}

std::string randomBytes(size_t n, Rng& rng) {
    std::string out(n, '\0');
    for (char& c : out)
        c = char(rng.below(2) ? kInterestingBytes[rng.below(sizeof kInterestingBytes)] : rng.below(256));
    return out;
}

// A range [pos, pos + len) of `s` with 1 <= len <= maxLen; s non-empty.
Span pickRange(const std::string& s, size_t maxLen, Rng& rng) {
    const size_t len = 1 + rng.below(std::min(maxLen, s.size()));
    return Span{rng.below(s.size() - len + 1), len};
}

// Text (the JSON formats, an .hdr's header): the first bytes are printable or white space.
bool looksLikeText(const std::string& s) {
    const size_t n = std::min<size_t>(s.size(), 64);
    for (size_t i = 0; i < n; ++i) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        if (!std::isprint(c) && !std::isspace(c)) return false;
    }
    return n > 0;
}

void mutateOnce(std::string& s, const std::vector<std::string>& others, Rng& rng) {
    const std::string& other = others.empty() ? s : others[rng.below(others.size())];
    // Text mostly gets its numbers and structure changed, which keeps it parsing far more often than byte
    // edits do; binary mostly gets byte edits.
    const size_t roll = rng.below(20);
    const bool text = looksLikeText(s);
    const size_t kind = roll < (text ? 14u : 2u) ? 8 : roll < (text ? 15u : 3u) ? 7 : rng.below(7);
    switch (kind) {
        case 0:  // flip one bit
            if (!s.empty()) s[rng.below(s.size())] ^= char(1u << rng.below(8));
            return;
        case 1:  // overwrite one byte
            if (!s.empty()) s[rng.below(s.size())] = randomBytes(1, rng)[0];
            return;
        case 2:  // insert a few bytes
            s.insert(rng.below(s.size() + 1), randomBytes(1 + rng.below(8), rng));
            return;
        case 3:  // delete a range
            if (!s.empty()) {
                const Span r = pickRange(s, 64, rng);
                s.erase(r.pos, r.len);
            }
            return;
        case 4:  // repeat a range in place (a run of scanlines, an array's elements)
            if (!s.empty()) {
                const Span r = pickRange(s, 256, rng);
                s.insert(r.pos, s.substr(r.pos, r.len));
            }
            return;
        case 5:  // splice: the head of this input, the tail of another
            if (!other.empty()) {
                const size_t cutHere = rng.below(s.size() + 1), cutThere = rng.below(other.size());
                s = s.substr(0, cutHere) + other.substr(cutThere);
            }
            return;
        case 6:  // insert a piece of another input
            if (!other.empty()) {
                const Span r = pickRange(other, 512, rng);
                s.insert(rng.below(s.size() + 1), other.substr(r.pos, r.len));
            }
            return;
        case 7:  // insert a structural token
            s.insert(rng.below(s.size() + 1), kTokens[rng.below(sizeof kTokens / sizeof kTokens[0])]);
            return;
        default: {  // replace a number with a hostile one
            const Span n = pickNumber(s, rng);
            const std::vector<std::string>& hostile = hostileNumbers();
            if (n.len > 0) s.replace(n.pos, n.len, hostile[rng.below(hostile.size())]);
            return;
        }
    }
}

}  // namespace

const std::vector<std::string>& hostileNumbers() {
    static const std::vector<std::string> numbers = {
        "1e308",
        "-1e308",
        "1.7976931348623157e308",
        "1e309",
        "1e999",
        "-0",
        "-0.0",
        "0",
        "3e38",
        "-3e38",
        "3.4028235e38",
        "3.4028236e38",
        "1e38",
        "1e15",
        "1e16",
        "1e-45",
        "1.4e-45",
        "1e-38",
        "1.17549435e-38",
        "4.9e-324",
        "1e-400",
        "2147483647",
        "2147483648",
        "-2147483649",
        "4294967295",
        "4294967296",
        "9223372036854775807",
        "9223372036854775808",
        "-9223372036854775809",
        "18446744073709551615",
        "18446744073709551616",
        "99999999999999999999999999999",
        "16777217",
        "65536",
        "-1",
        "0.5",
        "1e5",
        "NaN",
        "nan",
        "-nan",
        "Infinity",
        "-Infinity",
        "inf",
        "0x7fffffff",
        "1e",
        "--1",
        "1.e5",
        ".5",
    };
    return numbers;
}

std::string mutate(const std::string& base, const std::vector<std::string>& others, size_t maxLen, Rng& rng) {
    std::string s = base;
    // One edit half the time, two a quarter, three or four the rest: a few edits keep a text parsing.
    const size_t roll = rng.below(4);
    const size_t count = roll < 2 ? 1 : roll == 2 ? 2 : 3 + rng.below(2);
    for (size_t i = 0; i < count; ++i) mutateOnce(s, others, rng);
    if (s.size() > maxLen) s.resize(maxLen);
    return s;
}

}  // namespace shadelab::fuzz
