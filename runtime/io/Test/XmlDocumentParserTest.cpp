#include "io/xml/XmlDocumentParser.h"

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"

namespace rmfx::xml {

namespace {

// A front end for <list>: the names of its <item name="…"/> children, in order. An item without
// a name is an error; an item named "old" is kept with a warning.
Result<std::vector<std::string>> parseList(const std::string& text, const std::string& file = "l.xml") {
    return parseXmlText(text, file, "list", [&](const XMLElement* root, Diagnostics& diagnostics) {
        std::vector<std::string> names;
        for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
            ElementReader r(e, file, diagnostics, {"name"});
            auto name = r.string("name", true);
            if (!name) continue;
            if (*name == "old") r.warning("'old' is kept for now");
            names.push_back(*name);
        }
        return names;
    });
}

std::vector<std::string> formatted(const Diagnostics& diagnostics) {
    std::vector<std::string> out;
    for (const Diagnostic& d : diagnostics) out.push_back(d.format());
    return out;
}

using Lines = std::vector<std::string>;

TEST(XmlDocumentParser, ReturnsWhatTheFrontEndReadFromTheRoot) {
    auto r = parseList("<list>\n  <item name=\"a\"/>\n  <item name=\"b\"/>\n</list>\n");
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics());
    EXPECT_EQ(*r, (Lines{"a", "b"}));
    EXPECT_TRUE(r.diagnostics().empty());
}

TEST(XmlDocumentParser, WarningsComeWithTheValue) {
    auto r = parseList("<list>\n  <item name=\"old\"/>\n</list>\n");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(*r, (Lines{"old"}));
    EXPECT_EQ(formatted(r.diagnostics()), (Lines{"l.xml:2: warning: <item name=\"old\">: 'old' is kept for now"}));
}

TEST(XmlDocumentParser, AnErrorOfTheFrontEndIsAFailureWithEveryDiagnostic) {
    auto r = parseList("<list>\n  <item name=\"old\"/>\n  <item/>\n</list>\n");
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(formatted(r.diagnostics()), (Lines{"l.xml:2: warning: <item name=\"old\">: 'old' is kept for now",
                                                 "l.xml:3: error: <item>: missing attribute 'name'"}));
    EXPECT_EQ(r.error(), "l.xml:3: error: <item>: missing attribute 'name'");
}

// tinyxml2 names the line of the element left open.
TEST(XmlDocumentParser, MalformedXmlIsOneErrorAtItsLine) {
    auto r = parseList("<list>\n  <item name=\"a\">\n</list>\n");
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(formatted(r.diagnostics()),
              (Lines{"l.xml:2: error: malformed XML: <item> is not closed (its end tag is missing, misspelled or out of order)"}));
}

TEST(XmlDocumentParser, TheRootMustBeTheFrontEndsElement) {
    bool read = false;
    auto r = parseXmlText("<!-- x -->\n<lst/>\n", "l.xml", "list", [&](const XMLElement*, Diagnostics&) {
        read = true;
        return 0;
    });
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(read);
    EXPECT_EQ(formatted(r.diagnostics()), (Lines{"l.xml:2: error: the root element must be <list>, not <lst>"}));
}

TEST(XmlDocumentParser, AnElementAfterTheRootIsReportedAndTheRootStillRead) {
    auto r = parseList("<list>\n  <item/>\n</list>\n<list/>\n");
    EXPECT_FALSE(r.ok());
    EXPECT_EQ(formatted(r.diagnostics()), (Lines{"l.xml:4: error: <list> after </list>: a file holds one <list>",
                                                 "l.xml:2: error: <item>: missing attribute 'name'"}));
}

TEST(XmlDocumentParser, FilesAreReadThenParsed) {
    test::ScratchDir dir;
    std::filesystem::path file = dir.write("l.xml", "<list>\n  <item name=\"c\"/>\n</list>\n");
    std::string seen;
    auto r = parseXmlFile(file, [&](const std::string& text) {
        seen = text;
        return parseList(text, file.string());
    });
    ASSERT_TRUE(r.ok()) << formatAll(r.diagnostics());
    EXPECT_EQ(*r, (Lines{"c"}));
    EXPECT_EQ(seen, "<list>\n  <item name=\"c\"/>\n</list>\n");
}

TEST(XmlDocumentParser, AFileThatCannotBeOpenedIsOneError) {
    bool parsed = false;
    auto r = parseXmlFile(std::filesystem::path("no/such/list.xml"), [&](const std::string& text) {
        parsed = true;
        return parseList(text);
    });
    EXPECT_FALSE(r.ok());
    EXPECT_FALSE(parsed);
    EXPECT_EQ(formatted(r.diagnostics()), (Lines{"no/such/list.xml: error: the file does not exist"}));
}

TEST(XmlDocumentParser, RelativeReferencesResolveInTheFilesFolder) {
    EXPECT_EQ(folderOf("fx/a/w.xml"), std::filesystem::path("fx/a"));
    EXPECT_EQ(folderOf("w.xml"), std::filesystem::path("."));
    EXPECT_EQ(folderOf("/abs/w.xml"), std::filesystem::path("/abs"));
}

}  // namespace

}  // namespace rmfx::xml
