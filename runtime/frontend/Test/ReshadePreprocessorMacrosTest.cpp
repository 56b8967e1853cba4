// ReshadePreprocessor's macros: object-like and function-like, # and ##, variadic, self-reference,
// calls over several lines, ReShade's predefined macros and the user's, and the growth limits.
#include "frontend/Test/ReshadePreprocessorTestSupport.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;
using test::lines;

}  // namespace

TEST(ReshadePreprocessorMacros, ObjectLikeCommentsAndContinuationsKeepTheLines) {
    test::ScratchDir dir;
    ReshadeSettings settings;
    settings.width = 800;
    settings.height = 600;
    test::ReshadeRun run = test::preprocessText(dir,
                                                lines({"#define BUFFER_PIXEL_SIZE float2(BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT)",
                                                       "float2 px = BUFFER_PIXEL_SIZE; // a comment",
                                                       "/* a block", "   comment */ int a;", "int b = \\", "  2;",
                                                       "\tstring s = \"BUFFER_WIDTH // not a comment\";"}),
                                                settings);
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.annotated(dir.path().string()),
              (Lines{"main.fx:1|", "main.fx:2|float2 px = float2((1.0 / 800), (1.0 / 600));", "main.fx:3|  int a;",
                     "main.fx:4|", "main.fx:5|int b =   2;", "main.fx:6|",
                     "main.fx:7|\tstring s = \"BUFFER_WIDTH // not a comment\";"}));
    EXPECT_EQ(run.out.origin(2).file, run.main);
    EXPECT_EQ(run.out.origin(2).line, 2);
    EXPECT_EQ(run.out.origin(100).line, 7);  // clamped to the last line
}

TEST(ReshadePreprocessorMacros, StringizeAndPaste) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#define CAT(a, b) a##b", "#define STR(x) #x", "#define XSTR(x) STR(x)", "#define VERSION __RESHADE__",
                    "#define GLUE(a, b) a ## b", "#define AB done", "#define A 1",
                    "CAT(tex, 2D)(s, uv); STR(a \"b\\n\"  c); XSTR(VERSION); STR(VERSION)", "GLUE(A, B) GLUE(A, 2) CAT(A,)"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.solid(dir.path().string()),
              (Lines{"main.fx:8|tex2D(s, uv); \"a \\\"b\\\\n\\\" c\"; \"60000\"; \"VERSION\"", "main.fx:9|done A2 1"}));
}

TEST(ReshadePreprocessorMacros, SelfReferenceStopsAndNamesAloneStay) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#define X X + 1", "#define F(a) F(a) * 2", "#define P Q", "#define Q P", "#define NEG -1",
                    "#define ID(x) x", "X; F(3); P; Q; -NEG; ID + ID(ID)(2);"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:7|X + 1; F(3) * 2; P; Q; - -1; ID + ID(2);"}));
}

TEST(ReshadePreprocessorMacros, CallOverSeveralLinesExpandsOnItsFirst) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#define SUM(a, b) ((a) + (b))", "int s = SUM(1,", "          (2, 3));", "int t = SUM", "(4, 5);", "int u;",
                    "float SUM", "= 1;"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.annotated(dir.path().string()),
              (Lines{"main.fx:1|", "main.fx:2|int s = ((1) + ((2, 3)));", "main.fx:3|", "main.fx:4|int t = ((4) + (5));",
                     "main.fx:5|", "main.fx:6|int u;", "main.fx:7|float SUM", "main.fx:8|= 1;"}));
}

TEST(ReshadePreprocessorMacros, Variadic) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#define V(fmt, ...) f(fmt, ## __VA_ARGS__)", "#define W(...) g(__VA_ARGS__)",
                    "V(1) V(1, 2, 3) W() W(a, (b, c))"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:3|f(1) f(1,2, 3) g() g(a, (b, c))"}));
}

TEST(ReshadePreprocessorMacros, WrongArgumentCountWarnsAndDropsTheCallAsReshadeDoes) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(dir, lines({"#define TWO(a, b) a b", "x TWO(1) y TWO(1, 2, 3) z"}));
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:2: warning: macro TWO: not enough arguments for function-like macro invocation 'TWO' (1 "
                     "given, 2 expected); the call is dropped",
                     "main.fx:2: warning: macro TWO: too many arguments for function-like macro invocation 'TWO' (3 "
                     "given, 2 expected); the call is dropped"}));
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:2|x  y  z"}));
}

TEST(ReshadePreprocessorMacros, PredefinedBuiltInAndCompatibilityMacros) {
    test::ScratchDir dir;
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"__RESHADE__ __RENDERER__ BUFFER_WIDTH BUFFER_HEIGHT BUFFER_COLOR_BIT_DEPTH BUFFER_COLOR_SPACE "
                    "__RESHADE_PERFORMANCE_MODE__ __VENDOR__ __DEVICE__ __APPLICATION__",
                    "__LINE__ __FILE_NAME__ __FILE_STEM__", "tex2Dgather(s, uv, 1) tex2Doffset(s, uv, int2(1, 0))", "__FILE__"}));
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.solid(dir.path().string()),
              (Lines{"main.fx:1|60000 83200 1920 1080 8 1 0 0 0 0", "main.fx:2|2 \"main.fx\" \"main\"",
                     "main.fx:3|tex2DgatherG(s, uv) tex2D(s, uv, int2(1, 0))", "main.fx:4|\"" + run.main + "\""}));
    EXPECT_EQ(predefinedMacros({}).at(8), (std::pair<std::string, std::string>{"BUFFER_RCP_WIDTH", "(1.0 / BUFFER_WIDTH)"}));
}

TEST(ReshadePreprocessorMacros, UserDefinesAndTheirProblems) {
    test::ScratchDir dir;
    ReshadeSettings settings;
    settings.defines = {"QUALITY=3", "FLAG", " SPACED = a b ", "BUFFER_WIDTH=5", "2BAD=1"};
    test::ReshadeRun run = test::preprocessText(dir, "QUALITY FLAG SPACED BUFFER_WIDTH\n", settings);
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"<input>: warning: define BUFFER_WIDTH=5: 'BUFFER_WIDTH' is already defined by ReShade; the value given is ignored",
                     "<input>: error: define 2BAD=1: '2BAD' is no macro name"}));
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:1|3 1 a b 1920"}));
    EXPECT_EQ(splitDefine("NAME="), (std::pair<std::string, std::string>{"NAME", "1"}));
}

TEST(ReshadePreprocessorMacros, ExponentialGrowthIsAnErrorNotAHang) {
    test::ScratchDir dir;
    std::string code = "#define A0 x x\n";
    for (int i = 1; i <= 24; ++i) code += "#define A" + std::to_string(i) + " A" + std::to_string(i - 1) + " A" + std::to_string(i - 1) + "\n";
    code += "A24\n";
    test::ReshadeRun run = test::preprocessText(dir, code);
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:26: error: macro A1: more than 262144 macro expansions on one line"}));
}

TEST(ReshadePreprocessorMacros, NestingLimits) {
    test::ScratchDir dir;
    std::string code;
    for (int i = 0; i < 300; ++i) code += "#define M" + std::to_string(i) + " M" + std::to_string(i + 1) + "\n";
    code += "M0\n#define F(x) x\n";
    for (int i = 0; i < 100; ++i) code += "F(";
    code += "1" + std::string(100, ')') + "\n";
    test::ReshadeRun run = test::preprocessText(dir, code);
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:301: error: macro M256: macro recursion too high (more than 256 macros inside one another)",
                     "main.fx:303: error: macro F: macro arguments nested more than 64 deep"}));
}

}  // namespace rmfx
