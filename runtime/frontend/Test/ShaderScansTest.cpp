// The scans that replaced std::regex (libstdc++'s regex was most of the rfx_import fuzz target's
// time under ASan): each finds what its regex found, checked against the regex on awkward text.
#include <cstdint>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/shader/ClipSpaceTurnOver.h"
#include "frontend/shader/HlslMulOperands.h"

namespace rmfx::test {
namespace {

const std::vector<std::string>& awkwardTexts() {
    static const std::vector<std::string> texts = {
        "",
        "float4x4 m = mul(World, View);",
        "float4x4 m=mul(World,View);\nmatrix  n\t=\n  ViewProjection ;",
        "xfloat4x4 m = a; float4x4m = b; matrixm = c; float4x4 m; float4x4 m = d",
        "float4x4 float4x4 m = a; matrix\vm\f=\r;",
        "float4x4 a = b = c; matrix 2x = 3 World; float4x4 _m = __a2 2b c_;",
        "float4x4 m = a\nmatrix k = b; float4x4 last = ",
        "afloat4x4 m = x; matrix float4x4 q = y;;; matrix r =;",
        "uniform vec2 rm_InvTargetSize;",
        "uniform highp vec2 rm_InvTargetSize;",
        "uniform\n\tvec2\v rm_InvTargetSize",
        "uniform vec2 rm_InvTargetSizeX; uniform vec2 vec2 rm_InvTargetSize;",
        "myuniform vec2 rm_InvTargetSize; uniformvec2 rm_InvTargetSize;",
        "uniform lowp mediump vec2 rm_InvTargetSize; uniform vec3 rm_InvTargetSize;",
        "uniform vec2rm_InvTargetSize; uniform x vec2 rm_InvTargetSize2",
        "uniform uniform vec2 rm_InvTargetSize",
        "uniform 9 vec2 rm_InvTargetSize;",
        "uniform vec2 rm_InvTargetSize_",
        "uniform",
    };
    return texts;
}

// Texts strung together from the words and spaces both scans care about (a fixed seed).
std::vector<std::string> randomTexts() {
    static const char* pieces[] = {"float4x4", "matrix", "uniform", "vec2", "rm_InvTargetSize", "highp", " ", "\n", "\t",
                                   "=", ";", "m", "2", "_", "World", "x", "(", ")", "\v"};
    std::vector<std::string> texts;
    std::uint32_t state = 12345;
    for (int n = 0; n < 3000; ++n) {
        std::string text;
        for (int i = 0, count = 1 + n % 12; i < count; ++i) {
            state = state * 1664525u + 1013904223u;
            text += pieces[(state >> 16) % (sizeof(pieces) / sizeof(pieces[0]))];
        }
        texts.push_back(text);
    }
    return texts;
}

TEST(ShaderScans, MatrixAssignmentsFindWhatTheirRegexFound) {
    const std::regex assignment(R"(\b(?:float4x4|matrix)\s+(\w+)\s*=\s*([^;]*);)");
    std::vector<std::string> texts = awkwardTexts();
    for (std::string& text : randomTexts()) texts.push_back(std::move(text));
    for (const std::string& text : texts) {
        std::vector<std::pair<std::string, std::string>> expected, found;
        for (std::sregex_iterator it(text.begin(), text.end(), assignment), end; it != end; ++it)
            expected.emplace_back((*it)[1].str(), (*it)[2].str());
        for (const MatrixAssignment& a : matrixAssignments(text)) found.emplace_back(std::string(a.name), std::string(a.value));
        EXPECT_EQ(found, expected) << text;
    }
    const std::vector<MatrixAssignment> two = matrixAssignments("float4x4 m = mul(World, View);\nmatrix  n\t=\n  ViewProjection ;");
    ASSERT_EQ(two.size(), 2u);
    EXPECT_EQ(two[0].name, "m");
    EXPECT_EQ(two[0].value, "mul(World, View)");
    EXPECT_EQ(two[1].name, "n");
    EXPECT_EQ(two[1].value, "ViewProjection ");
}

TEST(ShaderScans, InvTargetSizeDeclarationsAreFoundAsTheirRegexFoundThem) {
    const std::regex declaration(R"(\buniform\s+(\w+\s+)?vec2\s+rm_InvTargetSize\b)");
    std::vector<std::string> texts = awkwardTexts();
    for (std::string& text : randomTexts()) texts.push_back(std::move(text));
    for (const std::string& text : texts)
        EXPECT_EQ(declaresInvTargetSize(text), std::regex_search(text, declaration)) << text;
    EXPECT_TRUE(declaresInvTargetSize("uniform highp vec2 rm_InvTargetSize;"));
    EXPECT_TRUE(declaresInvTargetSize("uniform vec2 vec2 rm_InvTargetSize;"));
    EXPECT_FALSE(declaresInvTargetSize("uniform vec2 rm_InvTargetSizeX;"));
    EXPECT_FALSE(declaresInvTargetSize("uniform lowp mediump vec2 rm_InvTargetSize;"));
}

}  // namespace
}  // namespace rmfx::test
