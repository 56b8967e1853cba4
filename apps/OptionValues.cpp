#include "apps/OptionValues.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace rmfx::apps {

ArgumentParser::TakeValue sizeValue(glm::ivec2& size) {
    return [&size](const std::string& value) -> std::string {
        int w = 0, h = 0;
        char x = 0, extra = 0;
        if (std::sscanf(value.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
            w > 16384 || h > 16384)
            return "--size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, got '" + value + "'";
        size = {w, h};
        return "";
    };
}

ArgumentParser::TakeValue frameCountValue(int& frames) {
    return [&frames](const std::string& value) -> std::string {
        char* end = nullptr;
        long n = std::strtol(value.c_str(), &end, 10);
        if (value.empty() || *end || n < 1 || n > 1000000)
            return "--frames: expected a count from 1 to 1000000, got '" + value + "'";
        frames = static_cast<int>(n);
        return "";
    };
}

ArgumentParser::TakeValue frameCountValue(std::optional<int>& frames) {
    return [&frames](const std::string& value) -> std::string {
        int n = 0;
        std::string problem = frameCountValue(n)(value);
        if (problem.empty()) frames = n;
        return problem;
    };
}

ArgumentParser::TakeValue secondsValue(float& seconds, bool* given) {
    return [&seconds, given](const std::string& value) -> std::string {
        char* end = nullptr;
        double s = std::strtod(value.c_str(), &end);
        if (value.empty() || *end || !std::isfinite(s) || s < 0) return "--dt: expected seconds ≥ 0, got '" + value + "'";
        seconds = static_cast<float>(s);
        if (given) *given = true;
        return "";
    };
}

ArgumentParser::TakeValue overrideValue(std::vector<std::pair<std::string, std::string>>& overrides) {
    return [&overrides](const std::string& value) -> std::string {
        auto eq = value.find('=');
        if (eq == std::string::npos || eq == 0) return "--set: expected NAME=VALUE, got '" + value + "'";
        overrides.emplace_back(value.substr(0, eq), value.substr(eq + 1));
        return "";
    };
}

ArgumentParser::TakeValue inputValue(std::vector<InputArgument>& inputs) {
    return [&inputs](const std::string& value) -> std::string {
        if (value.empty()) return "--input: expected [NAME=]FILE";
        inputs.push_back(parseInputArgument(value));
        return "";
    };
}

ArgumentParser::TakeValue textureValue(std::vector<TextureArgument>& textures) {
    return [&textures](const std::string& value) -> std::string {
        Result<TextureArgument> texture = parseTextureArgument(value);
        if (!texture) return texture.error();
        textures.push_back(std::move(*texture));
        return "";
    };
}

ArgumentParser::TakeValue rfxMatricesValue(std::optional<HlslMatrixOrder>& order) {
    return [&order](const std::string& value) -> std::string {
        std::optional<HlslMatrixOrder> parsed = parseHlslMatrixOrder(value);
        if (!parsed) return "--rfx-matrices: expected row-vector (the HLSL writes mul(v, M)) or column-vector (mul(M, v)), got '" + value + "'";
        order = *parsed;
        return "";
    };
}

}  // namespace rmfx::apps
