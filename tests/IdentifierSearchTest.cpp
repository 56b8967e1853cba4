#include "runtime/IdentifierSearch.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(IdentifierSearch, WholeWordsOnly) {
    EXPECT_TRUE(mentionsIdentifier("uniform float Ke;", "Ke"));
    EXPECT_TRUE(mentionsIdentifier("x = Ke*2.0;", "Ke"));
    EXPECT_FALSE(mentionsIdentifier("float Kernel; float aKe; float Ke_2;", "Ke"));
    EXPECT_FALSE(mentionsIdentifier("anything", ""));
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

}  // namespace
}  // namespace rmfx
