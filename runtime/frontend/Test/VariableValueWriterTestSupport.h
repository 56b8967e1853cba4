#pragma once
// What the variable value writer's tests share, independent of the code under test but for
// rewritten(): a value's bits (and two values compared by them), a workspace text around some declarations, parsed, and rewritten.

#include <bit>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/workspace/VariableValueWriter.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test::value_writer {

inline std::vector<std::uint32_t> bits(const Value& v) {
    std::vector<std::uint32_t> out;
    for (int i = 0; i < componentCount(v.type); ++i) out.push_back(std::bit_cast<std::uint32_t>(v.data[i]));
    return out;
}

inline ::testing::AssertionResult sameBits(const Value& actual, const Value& expected) {
    if (actual.type == expected.type && bits(actual) == bits(expected)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << valueTypeName(actual.type) << " " << formatValue(actual) << " (bits differ from) "
                                         << valueTypeName(expected.type) << " " << formatValue(expected);
}

inline Workspace parsed(const std::string& text, const std::string& file = "test.xml") {
    Result<Workspace> p = parseWorkspaceText(text, file, test::sourceDir() / "effects");
    EXPECT_TRUE(p.ok()) << formatAll(p.diagnostics());
    return p ? *p : Workspace{};
}

// A workspace around `body` (its top-level declarations) that the parser accepts.
inline std::string workspace(const std::string& body, const std::string& passBody = "") {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<workspace version=\"1\">\n" + body +
           "  <pass name=\"p\">\n" + passBody +
           "    <shader stage=\"fragment\"><![CDATA[out vec4 c; void main() { c = vec4(1.0); }]]></shader>\n"
           "  </pass>\n</workspace>\n";
}

inline std::string rewritten(std::string_view text, const std::map<std::string, Value>& values) {
    auto out = rewriteVariableValues(text, "test.xml", values);
    EXPECT_TRUE(out.ok()) << (out.ok() ? "" : out.error());
    return out.ok() ? *out : std::string();
}

}  // namespace rmfx::test::value_writer
