#pragma once
// The option values more than one command reads (render and edit): each returns a handler for
// ArgumentParser::option that stores the value, or says what was expected.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "apps/ArgumentParser.h"
#include "model/Workspace.h"
#include "validation/ImageInputs.h"
#include "validation/TextureArguments.h"

namespace rmfx::apps {

// The names takeMediaArgument (io/media/MediaArguments.h) takes, for ArgumentParser::own.
inline const std::initializer_list<const char*> kMediaOptionNames{"--media", "--sandbox", "--no-sandbox", "--missing-media",
                                                                  "--max-image-memory"};

// --size WIDTHxHEIGHT, each side from 1 to 16384.
ArgumentParser::TakeValue sizeValue(glm::ivec2& size);
// --frames N, from 1 to 1000000.
ArgumentParser::TakeValue frameCountValue(int& frames);
ArgumentParser::TakeValue frameCountValue(std::optional<int>& frames);
// --dt SECONDS, finite and ≥ 0; `given` (if any) becomes true.
ArgumentParser::TakeValue secondsValue(float& seconds, bool* given = nullptr);
// --set NAME=VALUE, appended in order.
ArgumentParser::TakeValue overrideValue(std::vector<std::pair<std::string, std::string>>& overrides);
// --input [NAME=]FILE[:layer], appended in order (parseInputArgument).
ArgumentParser::TakeValue inputValue(std::vector<InputArgument>& inputs);
// --texture NAME=FILE[,FILE…] (parseTextureArgument), appended in order.
ArgumentParser::TakeValue textureValue(std::vector<TextureArgument>& textures);
// --rfx-matrices row-vector|column-vector: how a RenderMonkey file's HLSL multiplies its matrices.
ArgumentParser::TakeValue rfxMatricesValue(std::optional<HlslMatrixOrder>& order);

}  // namespace rmfx::apps
