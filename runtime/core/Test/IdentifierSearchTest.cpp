#include "core/IdentifierSearch.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(IdentifierSearch, WholeWordsOnly) {
    EXPECT_TRUE(mentionsIdentifier("uniform float Ke;", "Ke"));
    EXPECT_TRUE(mentionsIdentifier("x = Ke*2.0;", "Ke"));
    EXPECT_FALSE(mentionsIdentifier("float Kernel; float aKe; float Ke_2;", "Ke"));
    EXPECT_FALSE(mentionsIdentifier("anything", ""));
}

// A name only a comment or a string holds is not used ("view_position" in a commented-out line
// of MeshLab's Simplempass.rfx made `rmfx list` say the pass needs it).
TEST(IdentifierSearch, MentionsAreCountedAsWholeWordsOutsideComments) {
    EXPECT_EQ(mentionCount("float4x4 ViewI; // ViewI\nfloat4 f() { return mul(p, ViewIT); }", "ViewI"), 1);
    EXPECT_EQ(mentionCount("float4x4 ViewI;\nfloat4 f() { return mul(p, ViewI); }", "ViewI"), 2);
    EXPECT_EQ(mentionCount("", "ViewI"), 0);
    EXPECT_EQ(mentionCount("ViewI", ""), 0);
}

TEST(IdentifierSearch, CommentsAndStringsDoNotCount) {
    EXPECT_FALSE(mentionsIdentifier("// uniform vec4 view_position;\nvoid main() {}", "view_position"));
    EXPECT_FALSE(mentionsIdentifier("/* view_position\n * more */ void main() {}", "view_position"));
    EXPECT_FALSE(mentionsIdentifier("#error \"view_position\"", "view_position"));
    EXPECT_TRUE(mentionsIdentifier("/* old */ uniform vec4 view_position; // used", "view_position"));
    EXPECT_TRUE(mentionsIdentifier("x = 1; /* unterminated\nview_position", "x"));
    EXPECT_FALSE(mentionsIdentifier("x = 1; /* unterminated\nview_position", "view_position"));
}

TEST(IdentifierSearch, CommentsBecomeSpacesKeepingLines) {
    EXPECT_EQ(withoutComments("a // b\nc /* d\ne */ f \"g\" h"), "a     \nc     \n     f     h");
}

TEST(IdentifierSearch, VertexInputDeclarations) {
    EXPECT_TRUE(declaresVertexInput("attribute vec3 rm_Tangent;\nvoid main(){}", "rm_Tangent"));
    EXPECT_TRUE(declaresVertexInput("in  highp vec4 a_position ;", "a_position"));
    EXPECT_TRUE(declaresVertexInput("attribute vec2 a, rm_Uv;", "rm_Uv"));
    EXPECT_FALSE(declaresVertexInput("uniform vec3 rm_Tangent;", "rm_Tangent"));
    EXPECT_FALSE(declaresVertexInput("attribute vec3 other; void main() { x = rm_Tangent; }", "rm_Tangent"));
    EXPECT_FALSE(declaresVertexInput("varying vec3 rm_TangentX;", "rm_Tangent"));
    EXPECT_FALSE(declaresVertexInput("attribute vec3 rm_Tangent", "rm_Tangent"));  // no end of statement
}

TEST(IdentifierSearch, UniformDeclarationsOnALine) {
    EXPECT_TRUE(lineDeclaresUniform("uniform float Gain;", "Gain"));
    EXPECT_TRUE(lineDeclaresUniform("  layout(location = 3) uniform vec4 a, Gain[2];", "Gain"));
    EXPECT_TRUE(lineDeclaresUniform("int x; uniform float Gain;", "Gain"));
    EXPECT_FALSE(lineDeclaresUniform("uniform float GainB;", "Gain"));
    EXPECT_FALSE(lineDeclaresUniform("uniform float Other; float Gain;", "Gain"));  // after the ';'
    EXPECT_FALSE(lineDeclaresUniform("float Gain; // uniforms", "Gain"));
    EXPECT_FALSE(lineDeclaresUniform("myuniform float Gain;", "Gain"));
    EXPECT_FALSE(lineDeclaresUniform("uniform float Gain;", ""));
    // A line of a million characters (std::regex overflowed the stack on far less).
    std::string longLine = "uniform float " + std::string(1'000'000, 'x') + ", Gain;";
    EXPECT_TRUE(lineDeclaresUniform(longLine, "Gain"));
    EXPECT_FALSE(lineDeclaresUniform(longLine, "Missing"));
}

}  // namespace
}  // namespace rmfx
