#include "core/DiagnosticRepeats.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

TEST(DiagnosticRepeats, WhatWasShownAlreadyIsDropped) {
    const Diagnostic shown{Diagnostic::Severity::Warning, {"a.xml", 4}, "<pass name=\"p\">", "compiled as GLSL 1.20"};
    Diagnostic sameTextAnError = shown, otherLine = shown;
    sameTextAnError.severity = Diagnostic::Severity::Error;
    otherLine.where.line = 5;
    const Diagnostics left = withoutRepeats({shown, sameTextAnError, otherLine, shown}, {shown});
    ASSERT_EQ(left.size(), 2u);
    EXPECT_EQ(left[0].format(), sameTextAnError.format());
    EXPECT_EQ(left[1].format(), otherLine.format());
    EXPECT_EQ(withoutRepeats({shown}, {}).size(), 1u);
}

}  // namespace
}  // namespace rmfx
