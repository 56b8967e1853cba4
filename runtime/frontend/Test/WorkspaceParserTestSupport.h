#pragma once
// What the workspace parser's tests share: a workspace text in place (fx/test.xml), parsed, and its
// diagnostics formatted whole ("fx/test.xml:3: error: ..."), one string each.

#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test::workspace_parser {

inline const std::string kPath = "fx/test.xml";

// A workspace whose body starts on line 2, followed by a pass (a workspace needs one).
inline std::string workspace(std::initializer_list<std::string> body) {
    std::string out = "<workspace version=\"1\">\n";
    for (const std::string& l : body) out += l + "\n";
    return out + "  <pass name=\"last\"/>\n</workspace>\n";
}

inline Result<Workspace> parse(const std::string& text) { return parseWorkspaceText(text, kPath, "fx"); }

inline std::vector<std::string> formatted(const Diagnostics& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) out.push_back(d.format());
    return out;
}

// The formatted diagnostics of text that must fail to parse.
inline std::vector<std::string> errorsOf(const std::string& text) {
    Result<Workspace> p = parse(text);
    EXPECT_FALSE(p.ok());
    return formatted(p.diagnostics());
}

// Text that must parse without any diagnostic.
inline Workspace parsedOk(const std::string& text) {
    Result<Workspace> p = parse(text);
    EXPECT_EQ(formatAll(p.diagnostics()), "");
    EXPECT_TRUE(p.ok());
    return (p ? *p : Workspace{});
}

using Lines = std::vector<std::string>;
inline const std::string at = kPath + ":";

}  // namespace rmfx::test::workspace_parser
