#include "core/Result.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rmfx {

namespace {

Diagnostic warning(const std::string& message) {
    return {Diagnostic::Severity::Warning, {"a.xml", 3}, "<pass name=\"p\">", message};
}

Diagnostic error(const std::string& file, int line, const std::string& element, const std::string& message) {
    return {Diagnostic::Severity::Error, {file, line}, element, message};
}

}  // namespace

TEST(Result, SuccessKeepsItsValueAndWarnings) {
    Result<int> r(42, {warning("unused variable")});
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(static_cast<bool>(r));
    EXPECT_EQ(*r, 42);
    EXPECT_EQ(r.value(), 42);
    ASSERT_EQ(r.diagnostics().size(), 1u);
    EXPECT_EQ(r.diagnostics()[0].format(), "a.xml:3: warning: <pass name=\"p\">: unused variable");
    EXPECT_EQ(r.error(), "");
}

TEST(Result, SuccessHoldsMoveOnlyValues) {
    Result<std::unique_ptr<int>> r(std::make_unique<int>(7));
    ASSERT_TRUE(r.ok());
    std::unique_ptr<int> taken = std::move(r.value());
    EXPECT_EQ(*taken, 7);
    EXPECT_TRUE(r.diagnostics().empty());
}

TEST(Result, FailureFromErrorIsItsMessage) {
    Result<std::string> r = Error{"cannot read 'x.png': No such file or directory"};
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(static_cast<bool>(r));
    EXPECT_EQ(r.error(), "cannot read 'x.png': No such file or directory");
    ASSERT_EQ(r.diagnostics().size(), 1u);
    EXPECT_EQ(r.diagnostics()[0].severity, Diagnostic::Severity::Error);
    EXPECT_EQ(r.diagnostics()[0].message, "cannot read 'x.png': No such file or directory");
    EXPECT_TRUE(hasErrors(r.diagnostics()));
}

TEST(Result, FailureFromDiagnosticsKeepsThemAllAndFormatsEachError) {
    Diagnostics found{warning("slow"), error("w.xml", 4, "<texture name=\"t\">", "no such file"),
                      error("w.xml", 9, "", "unknown pass 'p'")};
    Result<int> r = Result<int>::failure(found);
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics().size(), 3u);
    EXPECT_EQ(r.diagnostics()[0].severity, Diagnostic::Severity::Warning);
    EXPECT_EQ(r.error(),
              "w.xml:4: error: <texture name=\"t\">: no such file\n"
              "w.xml:9: error: unknown pass 'p'");
    Diagnostics taken = r.takeDiagnostics();
    EXPECT_EQ(taken.size(), 3u);
}

TEST(Result, VoidSucceedsByDefaultAndWithWarnings) {
    Result<void> plain;
    EXPECT_TRUE(plain.ok());
    EXPECT_TRUE(plain.diagnostics().empty());

    Result<void> warned(Diagnostics{warning("unused texture")});
    EXPECT_TRUE(warned.ok());
    EXPECT_TRUE(static_cast<bool>(warned));
    ASSERT_EQ(warned.diagnostics().size(), 1u);
    EXPECT_EQ(warned.diagnostics()[0].message, "unused texture");
    EXPECT_EQ(warned.error(), "");
}

TEST(Result, VoidFromDiagnosticsWithAnErrorFails) {
    Result<void> r(Diagnostics{warning("slow"), error("", 0, "variable 'k'", "no such variable")});
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(static_cast<bool>(r));
    EXPECT_EQ(r.diagnostics().size(), 2u);
    // An element without a file is still formatted, so the message says what it is about.
    EXPECT_EQ(r.error(), "<input>: error: variable 'k': no such variable");
}

TEST(Result, VoidFailureFromErrorAndFromDiagnostics) {
    Result<void> fromError = Error{"cannot save 'a.xml': it is not a regular file"};
    EXPECT_FALSE(fromError.ok());
    EXPECT_EQ(fromError.error(), "cannot save 'a.xml': it is not a regular file");

    Result<void> fromDiagnostics = Result<void>::failure({error("b.xml", 2, "", "bad")});
    EXPECT_FALSE(fromDiagnostics.ok());
    EXPECT_EQ(fromDiagnostics.error(), "b.xml:2: error: bad");
}

TEST(Result, TakingTheDiagnosticsLeavesAFailureFailed) {
    Result<void> fromDiagnostics(Diagnostics{error("c.xml", 1, "", "broken")});
    EXPECT_EQ(fromDiagnostics.takeDiagnostics().size(), 1u);
    EXPECT_FALSE(fromDiagnostics.ok());
    EXPECT_EQ(fromDiagnostics.error(), "c.xml:1: error: broken");

    Result<void> failed = Result<void>::failure({error("d.xml", 5, "", "also broken")});
    (void)failed.takeDiagnostics();
    EXPECT_FALSE(failed.ok());

    Result<int> value = Result<int>::failure({error("e.xml", 2, "", "no value")});
    (void)value.takeDiagnostics();
    EXPECT_FALSE(value.ok());
}

// A range-for over a temporary's diagnostics once read a destroyed Result (ASan's
// stack-use-after-scope in ReplayRun's applySets): a temporary hands them over by value.
TEST(Result, ATemporaryHandsOverItsDiagnosticsAndErrorByValue) {
    static_assert(std::is_same_v<decltype(std::declval<Result<void>>().diagnostics()), Diagnostics>);
    static_assert(std::is_same_v<decltype(std::declval<Result<int>>().error()), std::string>);
    static_assert(std::is_same_v<decltype(std::declval<Result<int>&>().diagnostics()), const Diagnostics&>);
    auto twoWarnings = [] {
        return Result<int>(7, {{Diagnostic::Severity::Warning, {"w.xml", 1}, "", "first"},
                               {Diagnostic::Severity::Warning, {"w.xml", 2}, "", "second"}});
    };
    std::vector<int> lines;
    for (const Diagnostic& d : twoWarnings().diagnostics()) lines.push_back(d.where.line);
    EXPECT_EQ(lines, (std::vector<int>{1, 2}));
    std::string text = Result<void>(Error{"gone"}).error();
    EXPECT_EQ(text, "gone");
}

}  // namespace rmfx
