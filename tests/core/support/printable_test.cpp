// The one escaping rule for text from a file in a message (support/printable.hpp).

#include <gtest/gtest.h>

#include "support/printable.hpp"

namespace psb::detail {
namespace {

TEST(Printable, ControlsAndDeleteAreEscaped) {
    EXPECT_EQ(printable("a\x1b[2Jb"), "a\\x1b[2Jb");
    EXPECT_EQ(printable(std::string_view("\0\n\t\x7f", 4)), "\\x00\\x0a\\x09\\x7f");
}

TEST(Printable, WellFormedUtf8ReadsAsWritten) {
    EXPECT_EQ(printable("Gau\xc3\x9f ball \xce\xb2 \xe2\x86\x92 \xf0\x9f\x8e\xb1"),
              "Gau\xc3\x9f ball \xce\xb2 \xe2\x86\x92 \xf0\x9f\x8e\xb1");
}

TEST(Printable, C1ControlsAndMalformedBytesAreEscaped) {
    EXPECT_EQ(printable("\xc2\x9b"
                        "2J"),
              "\\xc2\\x9b2J")
        << "CSI as a C1 control (U+009B)";
    EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
    EXPECT_EQ(printable("\xc3"), "\\xc3") << "a sequence cut short at the end";
    EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf") << "an overlong '/'";
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80") << "a surrogate";
    EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80") << "above U+10FFFF";
}

}  // namespace
}  // namespace psb::detail
