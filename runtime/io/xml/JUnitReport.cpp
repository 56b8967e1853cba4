#include "io/xml/JUnitReport.h"

#include "io/file/AtomicFile.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include <tinyxml2.h>

namespace rmfx {

namespace {

// XML 1.0 holds no control characters but tab, line feed and carriage return.
std::string xmlSafe(std::string text, bool oneLine) {
    for (char& c : text) {
        auto u = static_cast<unsigned char>(c);
        if (oneLine && (c == '\n' || c == '\r' || c == '\t')) c = ' ';
        else if ((u < 0x20 && c != '\n' && c != '\r' && c != '\t') || u == 0x7f) c = '?';
    }
    return text;
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", std::max(s, 0.0));
    return text;
}

long countOf(const JUnitTestSuite& suite, JUnitTestCase::Outcome outcome) {
    return static_cast<long>(std::count_if(suite.cases.begin(), suite.cases.end(),
                                           [&](const JUnitTestCase& c) { return c.outcome == outcome; }));
}

}  // namespace

std::string formatJUnit(const JUnitTestSuite& suite) {
    tinyxml2::XMLPrinter printer;
    printer.PushDeclaration("xml version=\"1.0\" encoding=\"UTF-8\"");
    std::string tests = std::to_string(suite.cases.size());
    std::string failures = std::to_string(countOf(suite, JUnitTestCase::Outcome::Failed));
    std::string errors = std::to_string(countOf(suite, JUnitTestCase::Outcome::Error));
    std::string name = xmlSafe(suite.name, true);
    for (const char* element : {"testsuites", "testsuite"}) {
        printer.OpenElement(element);
        printer.PushAttribute("name", name.c_str());
        printer.PushAttribute("tests", tests.c_str());
        printer.PushAttribute("failures", failures.c_str());
        printer.PushAttribute("errors", errors.c_str());
        printer.PushAttribute("time", seconds(suite.seconds).c_str());
    }
    for (const JUnitTestCase& c : suite.cases) {
        printer.OpenElement("testcase");
        printer.PushAttribute("name", xmlSafe(c.name, true).c_str());
        printer.PushAttribute("classname", xmlSafe(c.className, true).c_str());
        printer.PushAttribute("time", seconds(c.seconds).c_str());
        if (c.outcome != JUnitTestCase::Outcome::Passed) {
            bool failed = c.outcome == JUnitTestCase::Outcome::Failed;
            printer.OpenElement(failed ? "failure" : "error");
            printer.PushAttribute("message", xmlSafe(c.message, true).c_str());
            printer.PushAttribute("type", failed ? "comparison" : "error");
            if (!c.details.empty()) printer.PushText(xmlSafe(c.details, false).c_str());
            printer.CloseElement();
        }
        printer.CloseElement();
    }
    printer.CloseElement();
    printer.CloseElement();
    return printer.CStr();
}

Result<void> writeJUnit(const std::filesystem::path& file, const JUnitTestSuite& suite) {
    std::error_code ec;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
    if (ec) return Error{file.string() + ": cannot create the folder: " + ec.message()};
    return writeFileAtomically(file, formatJUnit(suite), false);
}

}  // namespace rmfx
