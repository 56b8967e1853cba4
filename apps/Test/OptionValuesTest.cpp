#include "apps/OptionValues.h"

#include <gtest/gtest.h>

namespace rmfx::apps {
namespace {

TEST(OptionValues, SizeTakesWidthByHeightFromOneToTheLimit) {
    glm::ivec2 size{0};
    EXPECT_EQ(sizeValue(size)("640x360"), "");
    EXPECT_EQ(size, glm::ivec2(640, 360));
    EXPECT_EQ(sizeValue(size)("16384x1"), "");
    EXPECT_EQ(size, glm::ivec2(16384, 1));
    for (const char* bad : {"16385x1", "0x4", "4x0", "-4x4", "4", "4x4x", "4X4", ""})
        EXPECT_EQ(sizeValue(size)(bad),
                  std::string("--size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, got '") + bad + "'")
            << bad;
    EXPECT_EQ(size, glm::ivec2(16384, 1));  // a refused value leaves the last good one
}

TEST(OptionValues, FramesAreACountFromOneToAMillion) {
    int frames = 0;
    EXPECT_EQ(frameCountValue(frames)("1000000"), "");
    EXPECT_EQ(frames, 1000000);
    for (const char* bad : {"0", "1000001", "-3", "2.5", "", "ten"})
        EXPECT_EQ(frameCountValue(frames)(bad),
                  std::string("--frames: expected a count from 1 to 1000000, got '") + bad + "'")
            << bad;
    std::optional<int> maybe;
    EXPECT_NE(frameCountValue(maybe)("0"), "");
    EXPECT_FALSE(maybe.has_value());
    EXPECT_EQ(frameCountValue(maybe)("7"), "");
    EXPECT_EQ(maybe, 7);
}

TEST(OptionValues, SecondsAreFiniteAndNotNegative) {
    float dt = 1.0f;
    bool given = false;
    EXPECT_EQ(secondsValue(dt, &given)("0"), "");
    EXPECT_EQ(dt, 0.0f);
    EXPECT_TRUE(given);
    EXPECT_EQ(secondsValue(dt)("0.25"), "");
    EXPECT_EQ(dt, 0.25f);
    for (const char* bad : {"-0.1", "inf", "nan", "", "1s"})
        EXPECT_EQ(secondsValue(dt)(bad), std::string("--dt: expected seconds ≥ 0, got '") + bad + "'") << bad;
    EXPECT_EQ(dt, 0.25f);
}

TEST(OptionValues, OverridesKeepTheirOrderAndEverythingAfterTheFirstEquals) {
    std::vector<std::pair<std::string, std::string>> overrides;
    EXPECT_EQ(overrideValue(overrides)("Exposure_Level=2"), "");
    EXPECT_EQ(overrideValue(overrides)("Sun=0 1 0"), "");
    EXPECT_EQ(overrideValue(overrides)("Expr=a=b"), "");
    EXPECT_EQ(overrideValue(overrides)("Empty="), "");
    ASSERT_EQ(overrides.size(), 4u);
    EXPECT_EQ(overrides[0], std::make_pair(std::string("Exposure_Level"), std::string("2")));
    EXPECT_EQ(overrides[1].second, "0 1 0");
    EXPECT_EQ(overrides[2], std::make_pair(std::string("Expr"), std::string("a=b")));
    EXPECT_EQ(overrides[3].second, "");
    EXPECT_EQ(overrideValue(overrides)("=2"), "--set: expected NAME=VALUE, got '=2'");
    EXPECT_EQ(overrideValue(overrides)("Exposure_Level"), "--set: expected NAME=VALUE, got 'Exposure_Level'");
    EXPECT_EQ(overrides.size(), 4u);
}

}  // namespace
}  // namespace rmfx::apps
