// The target browser's health badges: the last pass of the frame that wrote a target decides its
// badge (what its thumbnail shows), errors first and red, warnings amber; the frame's first
// finding of a kind is in the tooltip of its target; normalised targets say they were not inspected.

#include <gtest/gtest.h>

#include "editor/TargetHealthBadge.h"

namespace rmfx::editor {
namespace {

PassHealth pass(const std::string& name, const std::string& target, std::array<long long, healthKindCount> counts,
                bool inspected = true, bool ownPixelsOnly = false) {
    PassHealth p;
    p.pass = name;
    p.target = target;
    p.counts = counts;
    p.inspected = inspected;
    p.countedWhileDrawing = ownPixelsOnly;
    p.ownPixelsOnly = ownPixelsOnly;
    return p;
}

TEST(EditorTargetHealthBadge, TheLastWriterDecidesAndErrorsComeFirst) {
    FrameHealth health;
    health.passes = {pass("blur_h", "blur", {4, 0, 0, 0, 0}),  // overwritten below: not what the thumbnail shows
                     pass("scene", "scene", {0, 0, 0, 12, 3}),
                     pass("blur_v", "blur", {0, 2, 0, 7, 0}),
                     pass("show", "ldr", {}, false),
                     pass("final", "output", {})};
    HealthFinding nan;
    nan.kind = HealthKind::NaN;
    nan.pass = "blur_h";
    nan.target = "blur";
    nan.count = 4;
    nan.pixel = {3, 1};
    nan.value = {0, 0, 0, 1};
    health.findings = {nan};

    auto badges = targetHealthBadges(health);
    ASSERT_EQ(badges.size(), 4u);
    EXPECT_EQ(badges["blur"].text, "+Inf 2 neg 7");
    EXPECT_TRUE(badges["blur"].error);
    EXPECT_NE(badges["blur"].details.find("+Inf: 2 pixels, written by pass 'blur_v'"), std::string::npos)
        << badges["blur"].details;
    EXPECT_NE(badges["blur"].details.find("first in this frame: pass 'blur_h' wrote NaN into target 'blur' (4 pixels; "
                                          "first at x=3 y=1"),
              std::string::npos)
        << badges["blur"].details;
    EXPECT_EQ(badges["scene"].text, "neg 12 max 3");
    EXPECT_FALSE(badges["scene"].error);
    EXPECT_FALSE(badges["ldr"].inspected);
    EXPECT_EQ(badges["ldr"].text, "");
    EXPECT_TRUE(badges["output"].inspected);
    EXPECT_EQ(badges["output"].text, "");
    EXPECT_FALSE(badges["output"].error);
}

// Passes that counted only what they drew over the target (meshes drawn while drawing-counting,
// after a pass that cleared it) add to what the target holds; a pass covering the whole target
// starts again.
TEST(EditorTargetHealthBadge, PassesDrawingOverTheTargetAddUpBackToOneThatCoveredIt) {
    FrameHealth health;
    health.passes = {pass("sky", "scene", {0, 0, 0, 0, 5}),                // covers the target: overwritten below
                     pass("floor", "scene", {12, 0, 0, 0, 0}),             // clears colour, then draws: covers it
                     pass("teapot", "scene", {}, true, true),              // draws over it, clean
                     pass("panel", "scene", {0, 0, 0, 3, 0}, true, true),  // draws over it
                     pass("blur_h", "blur", {0, 0, 0, 4, 0}, true, true),
                     pass("blur_v", "blur", {})};                          // a full-screen pass: replaces it
    auto badges = targetHealthBadges(health);
    EXPECT_EQ(badges["scene"].text, "NaN 12 neg 3");
    EXPECT_TRUE(badges["scene"].error);
    EXPECT_NE(badges["scene"].details.find("NaN: 12 pixels, written by pass 'floor'"), std::string::npos) << badges["scene"].details;
    EXPECT_NE(badges["scene"].details.find("negative values: 3 pixels, written by pass 'panel'"), std::string::npos)
        << badges["scene"].details;
    EXPECT_EQ(badges["scene"].details.find("sky"), std::string::npos) << badges["scene"].details;
    EXPECT_EQ(badges["blur"].text, "");
    EXPECT_FALSE(badges["blur"].error);
}

}  // namespace
}  // namespace rmfx::editor
