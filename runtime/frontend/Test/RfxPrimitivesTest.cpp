// The small conversions of the RenderMonkey importer: packed colours, float bits, D3D formats,
// the inline DTD.

#include <gtest/gtest.h>

#include "frontend/rfx/detail/RfxD3dFormat.h"
#include "frontend/rfx/detail/RfxDoctype.h"
#include "frontend/rfx/detail/RfxPackedColor.h"
#include "frontend/rfx/detail/RfxRenderStates.h"

namespace rmfx::rfx {
namespace {

TEST(RfxPackedColor, ArgbFromTheTopByteDown) {
    glm::vec4 c = unpackArgb(-16744448);  // 0xFF008000
    EXPECT_FLOAT_EQ(c.r, 0.0f);
    EXPECT_FLOAT_EQ(c.g, 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(c.b, 0.0f);
    EXPECT_FLOAT_EQ(c.a, 1.0f);
    glm::vec4 d = unpackArgb(0x12345678);
    EXPECT_FLOAT_EQ(d.a, 0x12 / 255.0f);
    EXPECT_FLOAT_EQ(d.r, 0x34 / 255.0f);
    EXPECT_FLOAT_EQ(d.g, 0x56 / 255.0f);
    EXPECT_FLOAT_EQ(d.b, 0x78 / 255.0f);
    // The unsigned spelling of the same bits gives the same colour.
    glm::vec4 e = unpackArgb(4278222848LL);
    EXPECT_EQ(e, c);
}

TEST(RfxRenderStates, FloatStatesHoldIeeeBits) {
    EXPECT_EQ(floatFromBits(1065353216), 1.0f);    // 0x3F800000
    EXPECT_EQ(floatFromBits(1075838976), 2.5f);    // 0x40200000
    EXPECT_EQ(floatFromBits(-1082130432), -1.0f);  // 0xBF800000 as a signed int
    EXPECT_EQ(floatFromBits(0), 0.0f);
}

TEST(RfxD3dFormat, NumbersOfTheIssueAndTheirFormats) {
    struct Case {
        int number;
        TargetFormat format;
    };
    for (Case c : {Case{21, TargetFormat::RGBA8}, Case{34, TargetFormat::RG16}, Case{36, TargetFormat::RGBA16},
                   Case{111, TargetFormat::R16F}, Case{112, TargetFormat::RG16F}, Case{113, TargetFormat::RGBA16F},
                   Case{114, TargetFormat::R32F}, Case{115, TargetFormat::RG32F}, Case{116, TargetFormat::RGBA32F}}) {
        auto f = d3dFormat(c.number);
        ASSERT_TRUE(f.has_value()) << c.number;
        EXPECT_EQ(f->format, c.format) << c.number;
    }
    EXPECT_FALSE(d3dFormat(75).has_value());  // D3DFMT_D24S8: depth, not a colour target
    EXPECT_FALSE(d3dFormat(-1).has_value());
}

TEST(RfxDoctype, TheWholeInternalSubsetIsBlankedKeepingLines) {
    std::string text = "<?xml version=\"1.0\"?>\n<!DOCTYPE R [\n <!ELEMENT R (a|b)?>\n <!ATTLIST R X CDATA \"]>\">\n]>\n<R/>\n";
    std::string out = blankDoctype(text);
    EXPECT_EQ(out.size(), text.size());
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
    EXPECT_EQ(out.find("DOCTYPE"), std::string::npos);
    EXPECT_EQ(out.find("ATTLIST"), std::string::npos);
    EXPECT_NE(out.find("\n<R/>"), std::string::npos);
    EXPECT_EQ(blankDoctype("<R/>"), "<R/>");
    EXPECT_EQ(blankDoctype("<!DOCTYPE R [ <!ELEMENT R ANY>"), "<!DOCTYPE R [ <!ELEMENT R ANY>");  // never closed
}

}  // namespace
}  // namespace rmfx::rfx
