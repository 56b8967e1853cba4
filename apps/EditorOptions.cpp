#include "apps/EditorOptions.h"

#include <cstdlib>

#include "apps/ArgumentParser.h"
#include "apps/OptionValues.h"
#include "io/image/ImageOutputPath.h"
#include "io/media/MediaArguments.h"

namespace rmfx::apps {

std::optional<EditorOptions> parseEditorOptions(const std::vector<std::string>& args, std::string* error,
                                                 std::vector<std::string>* names) {
    EditorOptions o;
    bool haveWorkspace = false, dtGiven = false;
    auto fail = [&](const std::string& message) -> std::optional<EditorOptions> {
        *error = message;
        return std::nullopt;
    };
    using Empty = ArgumentParser::EmptyValue;
    ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, o.media); }, kMediaOptionNames)
        .option({"--size"}, sizeValue(o.size), Empty::Allowed)
        .option({"--set"}, overrideValue(o.overrides), Empty::Allowed)
        .option({"--frames"}, frameCountValue(o.frames), Empty::Allowed)
        .option({"--dt"}, secondsValue(o.deltaTime, &dtGiven), Empty::Allowed)
        .option({"--effect"}, [&](const std::string& value) { o.effect = value; return ""; }, Empty::Allowed)
        .option({"--rfx-matrices"}, rfxMatricesValue(o.rfxMatrices))
        .option({"--input"}, inputValue(o.inputs))
        .option({"--texture"}, textureValue(o.textures))
        .option({"--split"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            const double f = std::strtod(value.c_str(), &end);
            if (value.empty() || *end || !(f >= 0.0 && f <= 1.0))
                return "--split: expected the fraction of the width the input shows, 0 to 1, got '" + value + "'";
            o.split = static_cast<float>(f);
            return "";
        })
        .flag({"--check"}, [&] { o.checkHealth = true; })
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
    if (names) {
        *names = parser.names();
        return std::nullopt;
    }
    if (std::string message = parser.parse(args); !message.empty()) return fail(message);
    if (!haveWorkspace) return fail("which workspace? usage: rmfx edit WORKSPACE [options]");
    if ((o.screenshot || o.outputScreenshot) && !o.frames)
        return fail("--screenshot and --output-screenshot need --frames N (the frames to render first)");
    if (o.split && o.inputs.empty())
        return fail("--split shows the input image beside the output: give the image with --input FILE");
    if (dtGiven && !o.frames) return fail("--dt sets the step of --frames runs; interactive runs follow the clock");
    for (auto [option, file] : {std::pair{"--screenshot", o.screenshot}, std::pair{"--output-screenshot", o.outputScreenshot}})
        if (file)
            if (Result<void> usable = checkImageOutputPath(*file); !usable) return fail(std::string(option) + ": " + usable.error());
    return o;
}

}  // namespace rmfx::apps
