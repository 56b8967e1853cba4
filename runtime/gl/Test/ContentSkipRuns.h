#pragma once
// What the content-skip GL tests share: an executor with content skip on or off, one frame of each
// compared byte for byte, and the dim and bright images hdr_lighting runs on.

#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {

using Skipped = std::map<std::string, std::string>;
using Decision = ExecutorOptions::ContentSkipDecision;

inline const char* decisionName(Decision d) {
    switch (d) {
        case Decision::CpuWhenKnown: return "CpuWhenKnown";
        case Decision::GpuOnly: return "GpuOnly";
        case Decision::CpuWaits: return "CpuWaits";
    }
    return "?";
}

inline std::unique_ptr<GlExecutor> executorFor(const Workspace& ws, glm::ivec2 size, const std::set<std::string>& given, bool skip,
                                        Decision decision = Decision::CpuWhenKnown) {
    ExecutorOptions options;
    options.outputs = {"output"};
    options.givenInputs = given;
    options.contentSkip = skip;
    options.contentSkipDecision = decision;
    auto created = GlExecutor::create(std::make_shared<const Workspace>(ws), size, options);
    EXPECT_TRUE(created) << formatAll(created.diagnostics());
    return created ? std::move(*created) : nullptr;
}

// Renders one frame with each executor and checks that the outputs hold the same bytes.
inline void expectSameFrame(GlExecutor& on, GlExecutor& off, float time, const std::string& what) {
    for (GlExecutor* e : {&on, &off}) {
        Diagnostics frame = e->renderFrame({time, 1.0f / 24.0f}).takeDiagnostics();
        ASSERT_FALSE(hasErrors(frame)) << formatAll(frame);
    }
    Image a = readBack(on, "output"), b = readBack(off, "output");
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    ASSERT_FALSE(a.pixels.empty());
    EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0)
        << what << ": the output with content skip differs from the output without it";
    EXPECT_TRUE(off.contentSkippedEffects().empty()) << what << ": --content-skip off skips nothing";
}

// A dim image (nothing passes the bright pass) and one with a light far above 1.
struct DimAndBright {
    Image dim, bright;
};
inline DimAndBright dimAndBright(int w, int h) {
    DimAndBright out{blankHdrImage(w, h), blankHdrImage(w, h)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) {
                const float base = c == 3 ? 1.0f : 0.02f + 0.01f * c;
                out.dim.at(x, y, c) = base;
                out.bright.at(x, y, c) = (c < 3 && x >= 40 && x < 48 && y >= 10 && y < 18) ? 200.0f : base;
            }
    return out;
}

}  // namespace rmfx::test
