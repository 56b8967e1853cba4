// splitLogicalLines where ReShade's lexer differs from C's: a line comment ends with its physical
// line even after a backslash, and a backslash with no line after it at the end of a file is
// nothing. Both from GShade-Shaders (Clarity2.fx; Censor.fx, DropShadow.fx and StageDepth.fx's
// headers), which ReShade reads.

#include "frontend/reshade/ReshadeTokens.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(ReshadeTokens, ALineCommentEndsWithItsLineEvenAfterABackslash) {
    const std::vector<LogicalLine> lines = splitLogicalLines("a // path C:\\\\\n#if 1\nb // one \\\nc\n");
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0].text, "a  ");
    EXPECT_EQ(lines[1].text, "#if 1");
    EXPECT_EQ(lines[1].line, 2);
    EXPECT_EQ(lines[2].text, "b  ");
    EXPECT_EQ(lines[3].text, "c");
    EXPECT_EQ(lines[3].line, 4);
    // A continuation outside a comment still joins lines.
    const std::vector<LogicalLine> joined = splitLogicalLines("#define A 1 \\\n + 2\nx\n");
    ASSERT_EQ(joined.size(), 2u);
    EXPECT_EQ(joined[0].text, "#define A 1  + 2");
    EXPECT_EQ(joined[0].span, 2);
    EXPECT_EQ(joined[1].line, 3);
}

TEST(ReshadeTokens, ABackslashEndingTheFileIsNothing) {
    const std::vector<LogicalLine> lines = splitLogicalLines("#define B 2\nfloat x; \\");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[1].text, "float x; ");
    EXPECT_EQ(lines[1].line, 2);
}

}  // namespace
}  // namespace rmfx
