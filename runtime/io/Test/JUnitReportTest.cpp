// JUnit reports parse back (tinyxml2) with the counts, names, times and failure texts given.

#include "io/xml/JUnitReport.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "tests/support/TestSupport.h"

namespace rmfx {
namespace {

using Outcome = JUnitTestCase::Outcome;

JUnitTestSuite sample() {
    JUnitTestSuite suite;
    suite.name = "replay <ci> & \"more\"";
    suite.seconds = 1.23456;
    suite.cases.push_back({"fine", "replay.ci", 0.5, Outcome::Passed, "", ""});
    suite.cases.push_back({"bad<1>", "replay.ci", 0.25, Outcome::Failed,
                           "output: max error 0.5 > 0.25\nsecond line", "line one & <two>\n  line 'three'\x01"});
    suite.cases.push_back({"broken", "replay.ci", 0.0, Outcome::Error, "fx.xml:3: error: <pass>: bad", ""});
    return suite;
}

TEST(JUnitReport, ParsesBackWithCountsAndEscapedText) {
    std::string text = formatJUnit(sample());
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(text.c_str()), tinyxml2::XML_SUCCESS) << text;
    EXPECT_EQ(text.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0), 0u) << text;
    const tinyxml2::XMLElement* suites = doc.RootElement();
    ASSERT_STREQ(suites->Name(), "testsuites");
    const tinyxml2::XMLElement* suite = suites->FirstChildElement("testsuite");
    ASSERT_TRUE(suite);
    EXPECT_EQ(suite->NextSiblingElement(), nullptr);
    for (const tinyxml2::XMLElement* e : {suites, suite}) {
        EXPECT_STREQ(e->Attribute("name"), "replay <ci> & \"more\"");
        EXPECT_STREQ(e->Attribute("tests"), "3");
        EXPECT_STREQ(e->Attribute("failures"), "1");
        EXPECT_STREQ(e->Attribute("errors"), "1");
        EXPECT_STREQ(e->Attribute("time"), "1.235");
    }
    const tinyxml2::XMLElement* fine = suite->FirstChildElement("testcase");
    ASSERT_TRUE(fine);
    EXPECT_STREQ(fine->Attribute("name"), "fine");
    EXPECT_STREQ(fine->Attribute("classname"), "replay.ci");
    EXPECT_STREQ(fine->Attribute("time"), "0.500");
    EXPECT_EQ(fine->FirstChildElement(), nullptr);

    const tinyxml2::XMLElement* bad = fine->NextSiblingElement("testcase");
    ASSERT_TRUE(bad);
    EXPECT_STREQ(bad->Attribute("name"), "bad<1>");
    const tinyxml2::XMLElement* failure = bad->FirstChildElement("failure");
    ASSERT_TRUE(failure);
    EXPECT_STREQ(failure->Attribute("message"), "output: max error 0.5 > 0.25 second line");
    EXPECT_STREQ(failure->Attribute("type"), "comparison");
    EXPECT_STREQ(failure->GetText(), "line one & <two>\n  line 'three'?");

    const tinyxml2::XMLElement* broken = bad->NextSiblingElement("testcase");
    ASSERT_TRUE(broken);
    EXPECT_EQ(broken->FirstChildElement("failure"), nullptr);
    const tinyxml2::XMLElement* error = broken->FirstChildElement("error");
    ASSERT_TRUE(error);
    EXPECT_STREQ(error->Attribute("message"), "fx.xml:3: error: <pass>: bad");
    EXPECT_EQ(error->GetText(), nullptr);
    EXPECT_EQ(broken->NextSiblingElement(), nullptr);
}

TEST(JUnitReport, WritesTheFileCreatingItsFolder) {
    test::ScratchDir dir;
    auto file = dir / "reports/deep/junit.xml";
    auto written = writeJUnit(file, sample());
    ASSERT_TRUE(written) << written.error();
    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), formatJUnit(sample()));

    auto blocked = writeJUnit(file / "under-a-file.xml", sample());
    ASSERT_FALSE(blocked);
    EXPECT_EQ(blocked.error().rfind((file / "under-a-file.xml").string() + ": cannot", 0), 0u) << blocked.error();
}

}  // namespace
}  // namespace rmfx
