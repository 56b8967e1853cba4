#include "core/Diagnostic.h"

#include <gtest/gtest.h>

namespace rmfx {

TEST(Diagnostic, FormatsFileLineElementAndMessage) {
    Diagnostic d{Diagnostic::Severity::Error, {"fx/glare.xml", 12}, "<pass name=\"blur\">", "unknown attribute 'blnd'"};
    EXPECT_EQ(d.format(), "fx/glare.xml:12: error: <pass name=\"blur\">: unknown attribute 'blnd'");
}

TEST(Diagnostic, OmitsMissingLineAndElement) {
    Diagnostic d{Diagnostic::Severity::Warning, {"a.xml", 0}, "", "nothing to draw"};
    EXPECT_EQ(d.format(), "a.xml: warning: nothing to draw");
    EXPECT_FALSE(hasErrors({d}));
    d.severity = Diagnostic::Severity::Error;
    EXPECT_TRUE(hasErrors({d}));
}

}  // namespace rmfx
