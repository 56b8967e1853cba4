#include "frontend/shader/CompilerLogLine.h"

#include <string>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(CompilerLogLine, TheThreeStyles) {
    auto glslang = parseCompilerLogLine("WARNING: 0:12:   'x' : unused");
    ASSERT_TRUE(glslang);
    EXPECT_FALSE(glslang->error);
    EXPECT_EQ(glslang->lineDigits, "12");
    EXPECT_EQ(glslang->message, "'x' : unused");

    auto mesa = parseCompilerLogLine("0:7(15): error: `y' undeclared");
    ASSERT_TRUE(mesa);
    EXPECT_TRUE(mesa->error);
    EXPECT_EQ(mesa->lineDigits, "7");
    EXPECT_EQ(mesa->message, "`y' undeclared");

    auto nvidia = parseCompilerLogLine("0(31) : warning C7022: unrecognized profile specifier");
    ASSERT_TRUE(nvidia);
    EXPECT_FALSE(nvidia->error);
    EXPECT_EQ(nvidia->lineDigits, "31");
    EXPECT_EQ(nvidia->message, "C7022: unrecognized profile specifier");
}

TEST(CompilerLogLine, NearMissesAreNotParsed) {
    for (const char* line : {"ERROR: Linking fragment stage: missing main", "ERROR: 0:: x", "ERROR 0:2: x",
                             "error: 0:2: x", "0:2: error: no column", "0:2(1) error: no colon", "0(x) : error x",
                             "0(2) : note: x", "(2) : error x", "", "ERROR:"})
        EXPECT_FALSE(parseCompilerLogLine(line)) << line;
}

TEST(CompilerLogLine, ALineOfAMegabyteParses) {
    // libstdc++'s std::regex, used here before, recursed per character and overflowed the stack.
    std::string message(1 << 20, 'm');
    const std::string line = "ERROR: 0:99999999999999: " + message;  // the result views it
    auto parsed = parseCompilerLogLine(line);
    ASSERT_TRUE(parsed);
    EXPECT_EQ(parsed->lineDigits, "99999999999999");
    EXPECT_EQ(parsed->message.size(), message.size());
    EXPECT_FALSE(parseCompilerLogLine(std::string(1 << 20, '0')));
}

}  // namespace
}  // namespace rmfx
