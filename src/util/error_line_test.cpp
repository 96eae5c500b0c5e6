// errorLine: control characters escaped, long text capped on a character boundary, short text untouched.
#include "util/error_line.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace shadelab
