// Edits of a text made in one pass (core/TextEdits): offsets are the original's, insertions at an
// offset keep their order and come before a replacement there.

#include "core/TextEdits.h"

#include <gtest/gtest.h>

namespace rmfx {

TEST(TextEdits, ReplacementsAndInsertionsByTheOriginalsOffsets) {
    const std::string original = "float g; main(){g = g * 2;}";
    // Given out of order: the replacements of both g in the body, a declaration after `float g;`
    // and two insertions at the offset of the first g, which go before it in their order.
    const size_t first = original.find("g =");
    const size_t second = original.find("g *");
    EXPECT_EQ(applyTextEdits(original, {{second, 1, "copy"},
                                        {first, 1, "copy"},
                                        {8, 0, " static float copy;"},
                                        {first, 0, " copy = g;"},
                                        {first, 0, " "}}),
              "float g; static float copy; main(){ copy = g; copy = copy * 2;}");
    EXPECT_EQ(applyTextEdits(original, {}), original);
    EXPECT_EQ(applyTextEdits("abc", {{3, 0, "d"}, {0, 3, "x"}}), "xd");
}

TEST(TextEdits, OverlappingOrOutOfRangeEditsAreDroppedNotCrashedOn) {
    EXPECT_EQ(applyTextEdits("abcdef", {{1, 3, "X"}, {2, 1, "Y"}, {10, 0, "Z"}}), "aXef");
}

}  // namespace rmfx
