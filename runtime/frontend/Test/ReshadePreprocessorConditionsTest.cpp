// ReshadePreprocessor's #if family, its other directives (#error, #warning, #pragma, #line), and
// the exact file:line of every problem.
#include "frontend/Test/ReshadePreprocessorTestSupport.h"

#include <gtest/gtest.h>

#include "frontend/reshade/ReshadeExpression.h"

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;
using test::lines;

int64_t value(const std::string& expression) {
    ExpressionValue v = evaluateExpression(tokenize(expression));
    EXPECT_EQ(v.error, "") << expression;
    return v.value;
}

}  // namespace

TEST(ReshadePreprocessorConditions, VersionChecksDefinedAndEveryOperator) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#if __RESHADE__ < 30101", "old", "#elif __RESHADE__ >= 60000 && defined(BUFFER_WIDTH) && defined BUFFER_HEIGHT",
                    "new", "#else", "mid", "#endif",
                    "#if 0x10 == 16 && 010 == 8 && (1 ? 2 : 3) == 2 && -1 < 0 && (~0 & 0xFF) == 255 && (1 << 4 | 1) == 17 "
                    "&& 7 % 4 == 3 && UNKNOWN == 0 && !UNKNOWN && 10u / 3 == 3 && (5 ^ 1) == 4 && 'A' == 65 && 2 >= 2 && 1 != 2",
                    "all", "#endif", "#ifdef NOPE", "#error \"not reached\"", "#endif", "#ifndef NOPE", "#define NOPE 2",
                    "#endif", "NOPE", "#if 0", "#if garbage ((", "#else", "#endif", "#elif defined(NOPE) && NOPE == 3", "skipped", "#endif"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:4|new", "main.fx:9|all", "main.fx:17|2"}));
    EXPECT_EQ(run.out.lineOrigins.size(), 24u);
}

TEST(ReshadePreprocessorConditions, ExpressionEvaluator) {
    EXPECT_EQ(value("1 + 2 * 3 - 4 / 2"), 5);
    EXPECT_EQ(value("(1 + 2) * 3"), 9);
    EXPECT_EQ(value("1 || 0 && 0"), 1);
    EXPECT_EQ(value("0 ? 1 : 0 ? 2 : 3"), 3);
    EXPECT_EQ(value("-(-3) + +2 - ~1"), 7);
    EXPECT_EQ(value("1 << 63 >> 63"), -1);
    EXPECT_EQ(value("0xFFFFFFFF + 1"), 4294967296);
    EXPECT_EQ(evaluateExpression(tokenize("1 / 0")).error, "division by zero in #if");
    EXPECT_EQ(evaluateExpression(tokenize("5 % 0")).error, "remainder by zero in #if");
    EXPECT_EQ(evaluateExpression(tokenize("1.5 > 1")).error, "'1.5' is no integer");
    EXPECT_EQ(evaluateExpression(tokenize("(1")).error, "expected ')'");
    EXPECT_EQ(evaluateExpression(tokenize("1 2")).error, "unexpected '2'");
    EXPECT_EQ(evaluateExpression(tokenize("")).error, "#if with no expression");
    EXPECT_EQ(evaluateExpression(tokenize(std::string(100000, '(') + "1")).error, "expression nested too deep");
}

TEST(ReshadePreprocessorConditions, DefinedFromAMacroAsReshadeReadsIt) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#define X 1", "#define HAS_X defined(X)", "#define HAS_Y defined Y", "#if HAS_X && !HAS_Y", "yes",
                    "#endif", "#define CALL(a) a", "#if CALL(1", "#endif"}));
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:8: error: macro CALL: the arguments of macro 'CALL' are not closed before the next directive "
                     "or the end of the file",
                     "main.fx:8: error: #if: #if with no expression"}));
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:5|yes"}));
}

TEST(ReshadePreprocessorConditions, ProblemsAtTheirLines) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#if 1 / 0", "#endif", "#else", "#if 1", "#else", "#elif 1", "#endif", "#foo", "#define A 1",
                    "#define A 1", "#pragma unknownthing", "#warning \"careful\"", "#if (1", "#endif", "#ifdef", "#endif",
                    "#error \"stop here\"", "after", "#if 1"}));
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:1: error: #if: division by zero in #if",
                     "main.fx:3: error: #else: missing #if for #else",
                     "main.fx:6: error: #elif: #elif is not allowed after #else",
                     "main.fx:8: error: #foo: unrecognized preprocessing directive 'foo'",
                     "main.fx:10: error: #define A: redefinition of 'A' (defined before by main.fx:9)",
                     "main.fx:11: warning: #pragma unknownthing: unknown pragma ignored",
                     "main.fx:12: warning: #warning: careful",
                     "main.fx:13: error: #if: expected ')'",
                     "main.fx:15: error: #ifdef: macro name expected",
                     "main.fx:17: error: #error: stop here"}));
    EXPECT_EQ(run.solid(dir.path().string()), Lines{});
}

TEST(ReshadePreprocessorConditions, UnterminatedIfAndComment) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(dir, lines({"#if 1", "x", "#ifdef Y", "/* open"}));
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:4: warning: unterminated /* comment", "main.fx:1: error: #if: unterminated #if",
                     "main.fx:3: error: #ifdef: unterminated #ifdef"}));
}

TEST(ReshadePreprocessorConditions, PragmasAndMessages) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#pragma once", "#pragma message \"Hello \" \"world\"", "#define MODE skipoptimization",
                    "#pragma reshade MODE", "#pragma warning(disable: 3571)", "#", "code"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    ASSERT_EQ(run.out.messages.size(), 1u);
    EXPECT_EQ(run.out.messages[0].text, "Hello world");
    EXPECT_EQ(run.out.messages[0].where.line, 2);
    ASSERT_EQ(run.out.pragmas.size(), 2u);
    EXPECT_EQ(run.out.pragmas[0].name + " " + run.out.pragmas[0].arguments, "reshade skipoptimization");
    EXPECT_EQ(run.out.pragmas[1].name + " " + run.out.pragmas[1].arguments, "warning (disable: 3571)");
    EXPECT_EQ(run.out.pragmas[1].where.line, 5);
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:7|code"}));
}

TEST(ReshadePreprocessorConditions, LineDirectiveRenumbers) {
    test::ScratchDir dir;
    test::ReshadeRun run =
        test::preprocessText(dir, lines({"a", "#line 100 \"other.fx\"", "b __LINE__ __FILE__", "c", "#line 7", "#x"}));
    EXPECT_EQ(run.problems(dir.path().string()), (Lines{"other.fx:7: error: #x: unrecognized preprocessing directive 'x'"}));
    EXPECT_EQ(run.annotated(dir.path().string()),
              (Lines{"main.fx:1|a", "main.fx:2|", "other.fx:100|b 100 \"other.fx\"", "other.fx:101|c", "other.fx:102|",
                     "other.fx:7|"}));
}

}  // namespace rmfx
