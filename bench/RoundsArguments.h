#pragma once
// The options of the benchmarks that compare executors of one workspace in interleaved rounds
// (rmfx_bench_content_skip, rmfx_bench_health_check):
//   PROGRAM [--size WxH] [--rounds N] [--frames N] [--pairs N] [--workspace FILE]
// Errors go to stderr with the usage line.

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "bench/WholeNumberArgument.h"

namespace rmfx::bench {

struct RoundsArguments {
    glm::ivec2 size{512, 512};
    int rounds = 10;
    int frames = 8;  // per executor and round
    int pairs = 150;  // of adjacent frames per compared ratio (bench/PairedFrames.h); 0: none
    std::filesystem::path workspace = std::filesystem::path(RMFX_SOURCE_DIR) / "effects" / "hdr_lighting.xml";
};

// `defaults` holds each option's value when it is not given.
inline std::optional<RoundsArguments> parseRoundsArguments(int argc, char** argv, const char* program,
                                                           RoundsArguments defaults) {
    RoundsArguments a = defaults;
    auto fail = [&](const std::string& message) -> std::optional<RoundsArguments> {
        std::fprintf(stderr, "%s: %s\nusage: %s [--size WxH] [--rounds N] [--frames N] [--pairs N] [--workspace FILE]\n", program,
                     message.c_str(), program);
        return std::nullopt;
    };
    for (int i = 1; i < argc; ++i) {
        const std::string option = argv[i];
        if (option != "--size" && option != "--rounds" && option != "--frames" && option != "--pairs" && option != "--workspace")
            return fail("unknown argument '" + option + "'");
        if (i + 1 >= argc) return fail(option + ": expected a value");
        const std::string value = argv[++i];
        if (option == "--size") {
            std::optional<glm::ivec2> size = sizeArgument(value, 16, 8192);
            if (!size) return fail("--size: expected WxH, each from 16 to 8192, got '" + value + "'");
            a.size = *size;
        } else if (option == "--rounds" || option == "--frames") {
            std::optional<int> n = wholeNumberArgument(value, 1, 1000);
            if (!n) return fail(option + ": expected a whole number from 1 to 1000, got '" + value + "'");
            (option == "--rounds" ? a.rounds : a.frames) = *n;
        } else if (option == "--pairs") {
            std::optional<int> n = wholeNumberArgument(value, 0, 10000);
            if (!n) return fail("--pairs: expected a whole number from 0 to 10000, got '" + value + "'");
            a.pairs = *n;
        } else {
            a.workspace = value;
        }
    }
    return a;
}

}  // namespace rmfx::bench
