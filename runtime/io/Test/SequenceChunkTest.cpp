#include "io/media/SequenceChunk.h"

#include <vector>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

// The whole run's timeline with pre-roll N, position by position: the image each frame reads and
// its time index (image -1: the first image during pre-roll).
struct Step {
    int image;
    int time;
    bool operator==(const Step&) const = default;
};

std::vector<Step> wholeRunBefore(int first, int preroll) {
    std::vector<Step> steps;
    for (int t = -preroll; t < first; ++t) steps.push_back({t < 0 ? 0 : t, t});
    return steps;
}

std::vector<Step> chunkWarmUp(const SequenceChunk& c) {
    std::vector<Step> steps;
    for (int p = 0; p < c.preroll; ++p) steps.push_back({c.start, c.start - c.preroll + p});
    for (int s = 0; s < c.skip; ++s) steps.push_back({c.start + s, c.start + s});
    return steps;
}

TEST(SequenceChunk, TheFirstChunkIsTheWholeRunsBeginning) {
    SequenceChunk c = planSequenceChunk(0, 5);
    EXPECT_EQ(c.start, 0);
    EXPECT_EQ(c.preroll, 5);
    EXPECT_EQ(c.skip, 0);
    c = planSequenceChunk(0, 0);
    EXPECT_EQ(c.start + c.preroll + c.skip, 0);
}

TEST(SequenceChunk, WarmUpIsTheLastNStepsOfTheWholeRunsTimeline) {
    for (int first : {0, 1, 3, 7, 12, 40})
        for (int preroll : {0, 1, 3, 7, 12, 30}) {
            SCOPED_TRACE("first " + std::to_string(first) + ", preroll " + std::to_string(preroll));
            const SequenceChunk c = planSequenceChunk(first, preroll);
            std::vector<Step> whole = wholeRunBefore(first, preroll);
            // The last `preroll` steps before the chunk's first written frame.
            std::vector<Step> tail(whole.end() - std::min<long>(preroll, static_cast<long>(whole.size())), whole.end());
            EXPECT_EQ(chunkWarmUp(c), tail);
            EXPECT_EQ(c.preroll + c.skip, preroll);
            EXPECT_TRUE(c.preroll == 0 || c.start == 0);
        }
}

TEST(SequenceChunk, AChunkFarIntoTheShotReadsOnlyTheFramesBeforeIt) {
    const SequenceChunk c = planSequenceChunk(100, 24);
    EXPECT_EQ(c.start, 76);
    EXPECT_EQ(c.preroll, 0);
    EXPECT_EQ(c.skip, 24);
}

}  // namespace
}  // namespace rmfx
