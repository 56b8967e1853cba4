// ReshadePreprocessor's #include: the including file's folder, then the search paths; #pragma
// once; recursion, depth and fan-out limits; the files read; the effect's preprocessor definitions.
#include "frontend/Test/ReshadePreprocessorTestSupport.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using Lines = std::vector<std::string>;
using test::lines;

}  // namespace

TEST(ReshadePreprocessorIncludes, FolderThenSearchPathsAndPragmaOnce) {
    test::ScratchDir dir;
    dir.write("lib/a.fxh", lines({"#pragma once", "a __FILE_NAME__ __LINE__", "#include \"b.fxh\""}));
    dir.write("lib/b.fxh", "b\n");
    dir.write("inc/shared.fxh", "shared\n");
    dir.write("inc/Case.fxh", "case\n");
    ReshadeSettings settings;
    settings.includePaths = {dir / "inc"};
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#include \"lib/a.fxh\"", "#include \"lib\\a.fxh\"", "#include <shared.fxh>", "#define NAME \"shared.fxh\"",
                    "#include NAME", "#include \"case.FXH\"", "main"}),
        settings);
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    EXPECT_EQ(run.annotated(dir.path().string()),
              (Lines{"main.fx:1|", "lib/a.fxh:1|", "lib/a.fxh:2|a \"a.fxh\" 2", "lib/a.fxh:3|", "lib/b.fxh:1|b", "main.fx:2|",
                     "main.fx:3|", "inc/shared.fxh:1|shared", "main.fx:4|", "main.fx:5|", "inc/shared.fxh:1|shared",
                     "main.fx:6|", "inc/Case.fxh:1|case", "main.fx:7|main"}));
    std::vector<std::string> files;
    for (const std::filesystem::path& f : run.out.files) files.push_back(f.lexically_relative(dir.path()).string());
    EXPECT_EQ(files, (Lines{"main.fx", "lib/a.fxh", "lib/b.fxh", "inc/shared.fxh", "inc/Case.fxh"}));
}

TEST(ReshadePreprocessorIncludes, ProblemsInsideIncludedFilesAtTheirLines) {
    test::ScratchDir dir;
    dir.write("inc/broken.fxh", lines({"#define TWO(a, b) a b", "", "TWO(1)", "#if 1"}));
    dir.write("self.fxh", lines({"x", "#include \"self.fxh\""}));
    ReshadeSettings settings;
    settings.includePaths = {dir / "inc"};
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#include \"nothere.fxh\"", "#include \"broken.fxh\"", "#include \"self.fxh\"", "#include", "#include NOTHING"}),
        settings);
    const std::string folder = dir.path().string();
    EXPECT_EQ(run.problems(folder),
              (Lines{"main.fx:1: error: #include: cannot find \"nothere.fxh\" (looked in " + folder + ", inc)",
                     "inc/broken.fxh:3: warning: macro TWO: not enough arguments for function-like macro invocation 'TWO' (1 "
                     "given, 2 expected); the call is dropped",
                     "inc/broken.fxh:4: error: #if: unterminated #if",
                     "self.fxh:2: error: #include: recursive #include of \"self.fxh\"",
                     "main.fx:4: error: #include: expected \"file\" or <file> after #include",
                     "main.fx:5: error: #include: expected \"file\" or <file> after #include"}));
}

TEST(ReshadePreprocessorIncludes, DepthAndFanOutLimitsEndTheRun) {
    test::ScratchDir dir;
    for (int i = 1; i <= 40; ++i) dir.write("d" + std::to_string(i) + ".fxh", "#include \"d" + std::to_string(i + 1) + ".fxh\"\n");
    test::ReshadeRun deep = test::preprocessText(dir, "#include \"d1.fxh\"\n");
    EXPECT_EQ(deep.problems(dir.path().string()),
              (Lines{"d32.fxh:1: error: #include: includes nested more than 32 deep at \"d33.fxh\""}));

    test::ScratchDir wide;
    for (int i = 0; i < 14; ++i)
        wide.write("w" + std::to_string(i) + ".fxh",
                   lines({"#include \"w" + std::to_string(i + 1) + ".fxh\"", "#include \"w" + std::to_string(i + 1) + ".fxh\""}));
    wide.write("w14.fxh", "leaf\n");
    test::ReshadeRun fan = test::preprocessText(wide, "#include \"w0.fxh\"\n");
    ASSERT_EQ(fan.diagnostics.size(), 1u);
    EXPECT_EQ(fan.diagnostics[0].message, "more than 4096 includes (is a file included over and over?)");
    EXPECT_LT(fan.out.lineOrigins.size(), 8200u);  // an include line and at most one more per include
}

TEST(ReshadePreprocessorIncludes, MissingEffectFile) {
    test::ScratchDir dir;
    ReshadeInput input;
    input.file = dir / "nothing.fx";
    Diagnostics diagnostics;
    PreprocessedReshade out = preprocessReshade(input, diagnostics);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].format(), input.file.string() + ": error: cannot read the effect file");
    EXPECT_EQ(out.code, "");
    EXPECT_TRUE(out.files.empty());
}

TEST(ReshadePreprocessorIncludes, ReadingMoreThan16MiBEndsTheRun) {
    test::ScratchDir dir;
    dir.write("big.fxh", "// " + std::string(size_t(2) << 20, 'x') + "\n");  // 2 MiB and 4 bytes
    std::string code;
    for (int i = 0; i < 9; ++i) code += "#include \"big.fxh\"\n";
    test::ReshadeRun run = test::preprocessText(dir, code + "after\n");
    EXPECT_EQ(run.problems(dir.path().string()),
              (Lines{"main.fx:8: error: #include: the effect's includes read more than 16 MiB"}));
    EXPECT_EQ(run.solid(dir.path().string()), Lines{});
}

TEST(ReshadePreprocessorIncludes, ExistsLooksWhereIncludeLooks) {
    test::ScratchDir dir;
    dir.write("inc/there.fxh", "");
    ReshadeSettings settings;
    settings.includePaths = {dir / "inc"};
    test::ReshadeRun run = test::preprocessText(
        dir, lines({"#define THERE \"there.fxh\"", "#if exists \"there.fxh\" && exists(THERE) && !exists \"missing.fxh\"", "yes",
                    "#endif", "#if exists 12", "#endif"}),
        settings);
    EXPECT_EQ(run.problems(dir.path().string()), (Lines{"main.fx:5: error: #if: expected \"file\" after 'exists'"}));
    EXPECT_EQ(run.solid(dir.path().string()), (Lines{"main.fx:3|yes"}));
}

TEST(ReshadePreprocessorIncludes, EffectDefinitionsAsReshadeListsThem) {
    test::ScratchDir dir;
    ReshadeSettings settings;
    settings.defines = {"USER_CHOSEN_VALUE=7"};
    test::ReshadeRun run = test::preprocessText(
        dir,
        lines({"#ifndef MY_QUALITY_LEVEL", "  #define MY_QUALITY_LEVEL 2", "#endif", "#ifndef SHORT", "  #define SHORT 1",
               "#endif", "#ifndef USER_CHOSEN_VALUE", "  #define USER_CHOSEN_VALUE 5 // the default", "#endif",
               "#ifndef RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN", "  #define RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN 0", "#endif",
               "#define LATER_DEFINED 1", "#ifdef LATER_DEFINED", "#endif", "#ifndef FUNC_LIKE_MACRO",
               "  #define FUNC_LIKE_MACRO(x) x", "#endif", "#ifdef NEVER_DEFINED_NAME", "#endif"}),
        settings);
    EXPECT_EQ(run.problems(dir.path().string()), Lines{});
    Lines definitions;
    for (const ReshadeDefinition& d : run.out.definitions)
        definitions.push_back(d.name + "=" + d.value + " default=" + d.defaultValue + (d.fromUser ? " user" : "") +
                              (d.shownInUi ? " shown" : "") + " line " + std::to_string(d.where.line));
    EXPECT_EQ(definitions, (Lines{"MY_QUALITY_LEVEL=2 default=2 shown line 1",
                                  "RESHADE_DEPTH_INPUT_IS_UPSIDE_DOWN=0 default=0 line 10", "SHORT=1 default=1 line 4",
                                  "USER_CHOSEN_VALUE=7 default=5 user shown line 7"}));
}

}  // namespace rmfx
