#pragma once
// A benchmark's whole-number option: the text read whole, within [min, max]; nothing otherwise.

#include <charconv>
#include <optional>
#include <string>

namespace rmfx::bench {

inline std::optional<int> wholeNumberArgument(const std::string& text, int min, int max) {
    int value = 0;
    const char* end = text.data() + text.size();
    auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc{} || stop != end || value < min || value > max) return std::nullopt;
    return value;
}

}  // namespace rmfx::bench
