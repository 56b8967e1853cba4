#include "editor/TimingHistory.h"

#include <gtest/gtest.h>

namespace rmfx::editor {

TEST(EditorTimingHistory, AveragesEachPassOverTheFramesHeld) {
    TimingHistory h(3);
    h.add({{"a", 1.0}, {"b", 10.0}}, 11.5);
    h.add({{"a", 2.0}, {"b", 20.0}}, 22.5);
    auto rows = h.rows();
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].pass, "a");
    EXPECT_EQ(rows[0].lastMilliseconds, 2.0);
    EXPECT_DOUBLE_EQ(rows[0].averageMilliseconds, 1.5);
    EXPECT_DOUBLE_EQ(rows[1].averageMilliseconds, 15.0);
    EXPECT_EQ(h.lastFrameMilliseconds(), 22.5);
    EXPECT_DOUBLE_EQ(h.averageFrameMilliseconds(), 17.0);
}

TEST(EditorTimingHistory, KeepsOnlyTheNewestFrames) {
    TimingHistory h(3);
    for (int i = 1; i <= 5; ++i) h.add({{"a", double(i)}}, double(i) * 10.0);
    EXPECT_EQ(h.size(), 3u);
    EXPECT_DOUBLE_EQ(h.rows()[0].averageMilliseconds, 4.0);  // frames 3, 4, 5
    EXPECT_EQ(h.frameTotals(), (std::vector<float>{30.0f, 40.0f, 50.0f}));
}

TEST(EditorTimingHistory, OtherPassesStartOverAndEmptyFramesAreIgnored) {
    TimingHistory h(10);
    h.add({{"a", 1.0}}, 1.0);
    h.add({}, 99.0);  // no frame completed yet
    EXPECT_EQ(h.size(), 1u);
    h.add({{"a", 3.0}, {"new", 4.0}}, 7.0);  // a reload changed the passes
    EXPECT_EQ(h.size(), 1u);
    ASSERT_EQ(h.rows().size(), 2u);
    EXPECT_EQ(h.rows()[0].averageMilliseconds, 3.0);
}

}  // namespace rmfx::editor
