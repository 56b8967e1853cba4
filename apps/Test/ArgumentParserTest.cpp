#include "apps/ArgumentParser.h"

#include <gtest/gtest.h>

namespace rmfx::apps {

namespace {

using Args = std::vector<std::string>;

// A parser like a command's: --out DIR, repeatable --case NAME, --quiet/-q, --media DIR read by
// its own handler, --level N checked, and one positional file.
struct Command {
    std::string out, file;
    std::vector<std::string> cases, media;
    bool quiet = false;
    int level = 0;
    ArgumentParser parser;

    Command() {
        parser.own([this](const Args& args, size_t& i) -> std::optional<std::string> {
                  if (args[i] != "--media") return std::nullopt;
                  if (i + 1 >= args.size()) return std::string("--media needs a folder");
                  media.push_back(args[++i]);
                  return std::string();
              })
            .option({"--out"}, [this](const std::string& v) { out = v; return ""; })
            .option({"--case"}, [this](const std::string& v) { cases.push_back(v); return ""; })
            .option({"--level"}, [this](const std::string& v) -> std::string {
                if (v != "1" && v != "2") return "--level: expected 1 or 2, got '" + v + "'";
                level = v[0] - '0';
                return "";
            })
            .flag({"-q", "--quiet"}, [this] { quiet = true; })
            .positional([this](const std::string& v) -> std::string {
                if (!file.empty()) return "one file at a time; got '" + file + "' and '" + v + "'";
                file = v;
                return "";
            });
    }
};

TEST(ArgumentParser, TakesOptionsFlagsAndPositionalsInAnyOrder) {
    Command c;
    EXPECT_EQ(c.parser.parse({"-q", "--out", "dir", "a.xml", "--case", "x", "--level", "2", "--case", "y"}), "");
    EXPECT_EQ(c.out, "dir");
    EXPECT_EQ(c.file, "a.xml");
    EXPECT_EQ(c.cases, (Args{"x", "y"}));
    EXPECT_TRUE(c.quiet);
    EXPECT_EQ(c.level, 2);
}

TEST(ArgumentParser, NoArgumentsTakeNothing) {
    Command c;
    EXPECT_EQ(c.parser.parse({}), "");
    EXPECT_EQ(c.file, "");
    EXPECT_FALSE(c.quiet);
}

TEST(ArgumentParser, EachNameOfAFlagSetsIt) {
    Command c;
    EXPECT_EQ(c.parser.parse({"--quiet"}), "");
    EXPECT_TRUE(c.quiet);
}

TEST(ArgumentParser, OwnHandlersComeFirstAndMayReadAValue) {
    Command c;
    EXPECT_EQ(c.parser.parse({"--media", "m1", "f", "--media", "--out"}), "");
    EXPECT_EQ(c.media, (Args{"m1", "--out"}));  // the handler's value, though it looks like an option
    EXPECT_EQ(c.out, "");
    EXPECT_EQ(Command().parser.parse({"--media"}), "--media needs a folder");
}

TEST(ArgumentParser, AMissingOrEmptyValueIsRefused) {
    EXPECT_EQ(Command().parser.parse({"f", "--out"}), "--out needs a value");
    EXPECT_EQ(Command().parser.parse({"--out", "", "f"}), "--out needs a value");
}

TEST(ArgumentParser, AnEmptyValueCanBeAllowed) {
    std::string seen = "unset";
    ArgumentParser p;
    p.option({"--target"}, [&](const std::string& v) { seen = v; return ""; }, ArgumentParser::EmptyValue::Allowed);
    EXPECT_EQ(p.parse({"--target", ""}), "");
    EXPECT_EQ(seen, "");
    EXPECT_EQ(p.parse({"--target"}), "--target needs a value");
}

TEST(ArgumentParser, TheFirstHandlersMessageStopsTheParse) {
    Command c;
    EXPECT_EQ(c.parser.parse({"--level", "3", "--out", "d"}), "--level: expected 1 or 2, got '3'");
    EXPECT_EQ(c.out, "");
    EXPECT_EQ(Command().parser.parse({"a", "b"}), "one file at a time; got 'a' and 'b'");
}

TEST(ArgumentParser, UnknownOptionsAreNamedWithTheHint) {
    EXPECT_EQ(Command().parser.parse({"--nope"}), "unknown option '--nope' (see rmfx --help)");
    Command c;
    c.parser.unknownOptionHint("");
    EXPECT_EQ(c.parser.parse({"-x"}), "unknown option '-x'");
}

TEST(ArgumentParser, AnEmptyArgumentIsPositional) {
    Command c;
    c.file = "first";
    EXPECT_EQ(c.parser.parse({""}), "one file at a time; got 'first' and ''");
}

TEST(ArgumentParser, PositionalsWithoutAHandlerAreRefused) {
    ArgumentParser p;
    EXPECT_EQ(p.parse({"x"}), "unexpected argument 'x'");
}

}  // namespace

}  // namespace rmfx::apps
