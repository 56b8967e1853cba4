#pragma once
// A benchmark's whole-number option: the text read whole, within [min, max]; nothing otherwise.
// And a size option, WxH, each side such a number.

#include <charconv>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

namespace rmfx::bench {

inline std::optional<int> wholeNumberArgument(const std::string& text, int min, int max) {
    int value = 0;
    const char* end = text.data() + text.size();
    auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc{} || stop != end || value < min || value > max) return std::nullopt;
    return value;
}

inline std::optional<glm::ivec2> sizeArgument(const std::string& text, int min, int max) {
    const size_t x = text.find('x');
    if (x == std::string::npos) return std::nullopt;
    std::optional<int> w = wholeNumberArgument(text.substr(0, x), min, max);
    std::optional<int> h = wholeNumberArgument(text.substr(x + 1), min, max);
    if (!w || !h) return std::nullopt;
    return glm::ivec2(*w, *h);
}

}  // namespace rmfx::bench
