#include "editor/EditorOptions.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli/ArgumentParser.h"
#include "io/media/MediaArguments.h"

namespace rmfx::editor {

std::optional<EditorOptions> parseEditorOptions(const std::vector<std::string>& args, std::string* error) {
    EditorOptions o;
    bool haveWorkspace = false, dtGiven = false;
    auto fail = [&](const std::string& message) -> std::optional<EditorOptions> {
        *error = message;
        return std::nullopt;
    };
    using Empty = cli::ArgumentParser::EmptyValue;
    cli::ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, o.media); })
        .option({"--size"}, [&](const std::string& value) -> std::string {
            int w = 0, h = 0;
            char x = 0, extra = 0;
            if (std::sscanf(value.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
                w > 16384 || h > 16384)
                return "--size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, got '" + value + "'";
            o.size = {w, h};
            return "";
        }, Empty::Allowed)
        .option({"--set"}, [&](const std::string& value) -> std::string {
            auto eq = value.find('=');
            if (eq == std::string::npos || eq == 0) return "--set: expected NAME=VALUE, got '" + value + "'";
            o.overrides.emplace_back(value.substr(0, eq), value.substr(eq + 1));
            return "";
        }, Empty::Allowed)
        .option({"--frames"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            long n = std::strtol(value.c_str(), &end, 10);
            if (value.empty() || *end || n < 1 || n > 1000000)
                return "--frames: expected a count from 1 to 1000000, got '" + value + "'";
            o.frames = static_cast<int>(n);
            return "";
        }, Empty::Allowed)
        .option({"--dt"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            double dt = std::strtod(value.c_str(), &end);
            if (value.empty() || *end || !std::isfinite(dt) || dt < 0) return "--dt: expected seconds >= 0, got '" + value + "'";
            o.deltaTime = static_cast<float>(dt);
            dtGiven = true;
            return "";
        }, Empty::Allowed)
        .option({"--effect"}, [&](const std::string& value) { o.effect = value; return ""; }, Empty::Allowed)
        .option({"--view"}, [&](const std::string& value) { o.viewTargets.push_back(value); return ""; }, Empty::Allowed)
        .option({"--screenshot"}, [&](const std::string& value) { o.screenshot = value; return ""; }, Empty::Allowed)
        .option({"--output-screenshot"}, [&](const std::string& value) { o.outputScreenshot = value; return ""; },
                Empty::Allowed)
        .positional([&](const std::string& arg) -> std::string {
            if (haveWorkspace) return "one workspace at a time; got '" + o.workspace.string() + "' and '" + arg + "'";
            o.workspace = arg;
            haveWorkspace = true;
            return "";
        });
    if (std::string message = parser.parse(args); !message.empty()) return fail(message);
    if (!haveWorkspace) return fail("which workspace? usage: rmfx edit WORKSPACE [options]");
    if ((o.screenshot || o.outputScreenshot) && !o.frames)
        return fail("--screenshot and --output-screenshot need --frames N (the frames to render first)");
    if (dtGiven && !o.frames) return fail("--dt sets the step of --frames runs; interactive runs follow the clock");
    return o;
}

}  // namespace rmfx::editor
