#include "editor/EditorOptions.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "io/media/MediaArguments.h"

namespace rmfx::editor {

std::optional<EditorOptions> parseEditorOptions(const std::vector<std::string>& args, std::string* error) {
    EditorOptions o;
    bool haveWorkspace = false, dtGiven = false;
    auto fail = [&](const std::string& message) -> std::optional<EditorOptions> {
        *error = message;
        return std::nullopt;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (auto media = takeMediaArgument(args, i, o.media)) {
            if (!media->empty()) return fail(*media);
        } else if (arg == "--size" || arg == "--set" || arg == "--frames" || arg == "--screenshot" || arg == "--output-screenshot" ||
            arg == "--view" || arg == "--dt" || arg == "--effect") {
            if (i + 1 >= args.size()) return fail(arg + " needs a value");
            const std::string& value = args[++i];
            if (arg == "--size") {
                int w = 0, h = 0;
                char x = 0, extra = 0;
                if (std::sscanf(value.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
                    w > 16384 || h > 16384)
                    return fail("--size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, got '" + value + "'");
                o.size = {w, h};
            } else if (arg == "--set") {
                auto eq = value.find('=');
                if (eq == std::string::npos || eq == 0) return fail("--set: expected NAME=VALUE, got '" + value + "'");
                o.overrides.emplace_back(value.substr(0, eq), value.substr(eq + 1));
            } else if (arg == "--frames") {
                char* end = nullptr;
                long n = std::strtol(value.c_str(), &end, 10);
                if (value.empty() || *end || n < 1 || n > 1000000)
                    return fail("--frames: expected a count from 1 to 1000000, got '" + value + "'");
                o.frames = static_cast<int>(n);
            } else if (arg == "--dt") {
                char* end = nullptr;
                double dt = std::strtod(value.c_str(), &end);
                if (value.empty() || *end || !std::isfinite(dt) || dt < 0)
                    return fail("--dt: expected seconds >= 0, got '" + value + "'");
                o.deltaTime = static_cast<float>(dt);
                dtGiven = true;
            } else if (arg == "--effect") {
                o.effect = value;
            } else if (arg == "--view") {
                o.viewTargets.push_back(value);
            } else if (arg == "--screenshot") {
                o.screenshot = value;
            } else {
                o.outputScreenshot = value;
            }
        } else if (!arg.empty() && arg[0] == '-') {
            return fail("unknown option '" + arg + "' (see rmfx --help)");
        } else if (haveWorkspace) {
            return fail("one workspace at a time; got '" + o.workspace.string() + "' and '" + arg + "'");
        } else {
            o.workspace = arg;
            haveWorkspace = true;
        }
    }
    if (!haveWorkspace) return fail("which workspace? usage: rmfx edit WORKSPACE [options]");
    if ((o.screenshot || o.outputScreenshot) && !o.frames)
        return fail("--screenshot and --output-screenshot need --frames N (the frames to render first)");
    if (dtGiven && !o.frames) return fail("--dt sets the step of --frames runs; interactive runs follow the clock");
    return o;
}

}  // namespace rmfx::editor
