#pragma once
// `rmfx edit` arguments.

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "io/media/MediaResolver.h"
#include "model/Workspace.h"
#include "validation/ImageInputs.h"
#include "validation/TextureArguments.h"

namespace rmfx::apps {

struct EditorOptions {
    std::filesystem::path workspace;
    std::string effect;  // --effect NAME: the effect of a RenderMonkey .rfx file
    std::optional<HlslMatrixOrder> rfxMatrices;  // --rfx-matrices: its HLSL's matrix order
    glm::ivec2 size{0};  // 0: the workspace's size
    std::vector<std::pair<std::string, std::string>> overrides;  // --set NAME=VALUE, as rmfx render
    std::vector<std::string> viewTargets;  // --view TARGET: viewer windows open from the start
    // --frames N: render N frames at a fixed step (--dt), write the screenshots asked for, exit.
    std::optional<int> frames;
    float deltaTime = 1.0f / 60.0f;  // --dt: the step of those frames
    std::optional<std::filesystem::path> screenshot;        // the whole window, PNG
    std::optional<std::filesystem::path> outputScreenshot;  // the effect's output, as rmfx render writes it
    MediaOptions media{};  // --media DIR, --sandbox (runtime/MediaArguments.h)
    std::vector<InputArgument> inputs;      // --input [NAME=]FILE, as rmfx render
    std::vector<TextureArgument> textures;  // --texture NAME=FILE, as rmfx render
    // --split F: open with the before/after view, the input left of F·width, the output right.
    std::optional<float> split;
    bool checkHealth = false;  // --check: the numeric health check from the start (rmfx render --check)
};

// On an error returns nullopt and sets *error to a sentence naming the option.
// With `names`, fills it with the parser's option names and parses nothing.
std::optional<EditorOptions> parseEditorOptions(const std::vector<std::string>& args, std::string* error,
                                                std::vector<std::string>* names = nullptr);

}  // namespace rmfx::apps
