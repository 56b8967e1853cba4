#pragma once
// JUnit XML test reports, the format CI servers (GitLab, Jenkins, GitHub actions) read: one
// <testsuite> in <testsuites>, a <testcase> each, with a <failure> or <error> when it did not pass.

#include <filesystem>
#include <string>
#include <vector>

#include "core/Result.h"

namespace rmfx {

struct JUnitTestCase {
    enum class Outcome {
        Passed,
        Failed,  // a check failed: <failure>
        Error,   // the test could not run: <error>
    };
    std::string name;
    std::string className;
    double seconds = 0;
    Outcome outcome = Outcome::Passed;
    std::string message;  // one line, the failure's message attribute
    std::string details;  // the failure's text: any number of lines
};

struct JUnitTestSuite {
    std::string name;
    double seconds = 0;
    std::vector<JUnitTestCase> cases;
};

// The report as XML text. Text is escaped; characters XML 1.0 cannot hold (control characters
// other than tab and line breaks) become '?', and line breaks in a message become spaces.
std::string formatJUnit(const JUnitTestSuite& suite);
// Writes the report, creating the file's folder. Errors name the file.
Result<void> writeJUnit(const std::filesystem::path& file, const JUnitTestSuite& suite);

}  // namespace rmfx
