// errorLine: control characters escaped, long text capped on a character boundary, short text untouched.
#include "util/error_line.h"

#include "util/input_error.h"

#include <gtest/gtest.h>

#include <random>

namespace shadelab {
namespace {

TEST(ErrorLine, PlainTextIsUnchanged) {
    EXPECT_EQ(errorLine("scene.json: lights[2].color: expected 3 numbers, got 2"),
              "scene.json: lights[2].color: expected 3 numbers, got 2");
}

TEST(ErrorLine, ControlCharactersAreEscaped) {
    EXPECT_EQ(errorLine("a\nb\tc\rd"), "a\\nb\\tc\\rd");
    EXPECT_EQ(errorLine("\x1b[31mred"), "\\x1b[31mred");
    EXPECT_EQ(errorLine(std::string("/etc/passwd\0.gltf", 17)), "/etc/passwd\\x00.gltf");
    EXPECT_EQ(errorLine("x\x7f"), "x\\x7f");
}

TEST(ErrorLine, LongTextIsCappedWithAnEllipsis) {
    const std::string line = errorLine(std::string(100000, 'u'));
    EXPECT_EQ(line.size(), kMaxErrorLineChars + 3);
    EXPECT_EQ(line.substr(line.size() - 3), "\xE2\x80\xA6");
    // Exactly at the cap: no ellipsis (negative control for the cut).
    EXPECT_EQ(errorLine(std::string(kMaxErrorLineChars, 'u')), std::string(kMaxErrorLineChars, 'u'));
}

TEST(ErrorLine, CapNeverSplitsAUtf8Character) {
    std::string text = std::string(9, 'a');
    for (int i = 0; i < 10; ++i) text += "\xC3\xA9";  // é, two bytes
    const std::string line = errorLine(text, 10);     // byte 10 is the second byte of the first é
    EXPECT_EQ(line, std::string(9, 'a') + "\xE2\x80\xA6");
}

TEST(ErrorLine, C1ControlsAreEscaped) {
    // U+009B (C2 9B) is a one-byte CSI to many terminals: "\xC2\x9B" "31m" would turn the line red.
    EXPECT_EQ(errorLine("a\xC2\x9B"
                        "31mred"),
              "a\\xc2\\x9b31mred");
    EXPECT_EQ(errorLine("\xC2\x80\xC2\x9F"), "\\xc2\\x80\\xc2\\x9f");  // both ends of the C1 range
    // Negative control: the characters just past the range, and other text, stay as they are.
    EXPECT_EQ(errorLine("\xC2\xA0 caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80"),
              "\xC2\xA0 caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x98\x80");
}

TEST(ErrorLine, BytesThatAreNotUtf8AreEscaped) {
    EXPECT_EQ(errorLine("x\xFFy"), "x\\xffy");
    EXPECT_EQ(errorLine("\x80"), "\\x80");                             // a continuation byte alone
    EXPECT_EQ(errorLine("\xC0\xAF"), "\\xc0\\xaf");                    // an overlong '/'
    EXPECT_EQ(errorLine("\xED\xA0\x80"), "\\xed\\xa0\\x80");           // a surrogate
    EXPECT_EQ(errorLine("\xF4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // past U+10FFFF
    EXPECT_EQ(errorLine("ab\xE2\x82"), "ab\\xe2\\x82");                // cut short at the end
    EXPECT_EQ(errorLine("\xE2\x82x"), "\\xe2\\x82x");                  // cut short by ASCII
}

// Whether `s` is well-formed UTF-8 with no C0, DEL or C1 control: what every line must be.
bool printableUtf8(const std::string& s) {
    for (size_t i = 0; i < s.size();) {
        const auto b = [&](size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
        const auto cont = [&](size_t k) { return (b(k) & 0xC0) == 0x80; };
        if (b(0) < 0x20 || b(0) == 0x7F) return false;
        if (b(0) < 0x80) {
            i += 1;
        } else if (b(0) >= 0xC2 && b(0) <= 0xDF && cont(1)) {
            if (b(0) == 0xC2 && b(1) <= 0x9F) return false;
            i += 2;
        } else if (b(0) >= 0xE0 && b(0) <= 0xEF && cont(1) && cont(2)) {
            const unsigned cp = (b(0) & 0x0Fu) << 12 | (b(1) & 0x3Fu) << 6 | (b(2) & 0x3Fu);
            if (cp < 0x800 || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
            i += 3;
        } else if (b(0) >= 0xF0 && b(0) <= 0xF4 && cont(1) && cont(2) && cont(3)) {
            const unsigned cp = (b(0) & 0x07u) << 18 | (b(1) & 0x3Fu) << 12 | (b(2) & 0x3Fu) << 6 | (b(3) & 0x3Fu);
            if (cp < 0x10000 || cp > 0x10FFFF) return false;
            i += 4;
        } else {
            return false;
        }
    }
    return true;
}

TEST(ErrorLine, AnyBytesBecomePrintableUtf8) {
    std::mt19937 rng(7);
    int rawFailures = 0;
    for (int n = 0; n < 2000; ++n) {
        std::string text(size_t(rng() % 40), '\0');
        for (char& c : text) c = char(rng() % 256);
        rawFailures += printableUtf8(text) ? 0 : 1;
        const std::string line = errorLine(text, 1000);
        ASSERT_TRUE(printableUtf8(line)) << n << ": " << line;
    }
    // Negative control: the raw strings themselves are mostly not printable UTF-8, so the check can fail.
    EXPECT_GT(rawFailures, 1800);
}

TEST(ErrorLine, ANulIsEscapedInTheMessageItself) {
    const std::string word("trace\0 and more", 15);
    EXPECT_EQ(escapeForMessage(word), "trace\\x00 and more");
    // The exceptions keep the text after the NUL in what(), a C string.
    EXPECT_STREQ(UsageError("renderer: unknown value '" + word + "'").what(),
                 "renderer: unknown value 'trace\\x00 and more'");
    EXPECT_STREQ(InputError("a.json", "lights[0]", "unknown type '" + word + "'").what(),
                 "a.json: lights[0]: unknown type 'trace\\x00 and more'");
    const SettingError setting("renderer", "unknown value '" + word + "'");
    EXPECT_STREQ(setting.what(), "renderer: unknown value 'trace\\x00 and more'");
    EXPECT_EQ(setting.reason(), "unknown value 'trace\\x00 and more'");
    // errorLine writes a NUL the same way, so a message escaped early prints as one escaped late.
    EXPECT_EQ(errorLine(escapeForMessage(word)), errorLine(word));
    // Negative control: a plain std::runtime_error loses everything after the NUL.
    EXPECT_STREQ(std::runtime_error(word).what(), "trace");
}

TEST(ErrorLine, MessagesAreValidUtf8ForPython) {
    // A JSON parse error quotes the bytes it stopped at; Python's str() of a what() that is not UTF-8 was "".
    const std::string quoted = "last read: '\"\xFF\xC2\x9B'";
    const InputError e("bad.json", quoted);
    EXPECT_STREQ(e.what(), "bad.json: last read: '\"\\xff\xC2\x9B'");  // U+009B is UTF-8: errorLine's to escape
    EXPECT_EQ(errorLine(e.what()), "bad.json: last read: '\"\\xff\\xc2\\x9b'");
    // Control characters stay for errorLine; only NUL and the bytes that are not UTF-8 change.
    EXPECT_EQ(escapeForMessage("a\nb\x1b caf\xC3\xA9"), "a\nb\x1b caf\xC3\xA9");
    // Negative control: the raw quote is no UTF-8, as the check above would see if the escape were gone.
    EXPECT_EQ(utf8SequenceLength(quoted, quoted.find('\xFF')), 0u);
}

}  // namespace
}  // namespace shadelab
