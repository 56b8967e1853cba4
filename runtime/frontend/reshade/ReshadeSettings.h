#pragma once
// What a ReShade FX effect is preprocessed for: the macros ReShade defines before an effect's first
// line, the user's own definitions (`--define NAME=VALUE`, a preset's PreprocessorDefinitions) and
// where `#include` looks. ReshadePreprocessor.h takes them.
//
//   ReshadeSettings s;  s.width = 1280;  s.height = 720;  s.defines = {"MY_QUALITY=2", "MY_FLAG"};
//   predefinedMacros(s) → {"__RESHADE__", "60000"}, …, {"BUFFER_WIDTH", "1280"},
//                         {"BUFFER_RCP_WIDTH", "(1.0 / BUFFER_WIDTH)"}, …

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace rmfx {

struct ReshadeSettings {
    // __RESHADE__: MAJOR * 10000 + MINOR * 100 + REVISION (REFERENCE.md), 60000 for ReShade 6.0.0.
    int version = 60000;
    bool performanceMode = false;  // __RESHADE_PERFORMANCE_MODE__
    uint32_t vendor = 0;           // __VENDOR__ (0x10de NVIDIA, 0x1002 AMD, …); 0 when unknown
    uint32_t device = 0;           // __DEVICE__
    // __RENDERER__: OpenGL is 0x10000 | major << 12 | minor << 8 (0x14300 for 4.3); rmfx renders
    // with OpenGL 4.5.
    uint32_t renderer = 0x14500;
    uint32_t application = 0;      // __APPLICATION__: a hash of the game's executable name; none here
    int width = 1920;              // BUFFER_WIDTH
    int height = 1080;             // BUFFER_HEIGHT
    int colorBitDepth = 8;         // BUFFER_COLOR_BIT_DEPTH (8 or 10)
    int colorSpace = 1;            // BUFFER_COLOR_SPACE: 0 unknown, 1 sRGB, 2 scRGB, 3 HDR10 ST2084, 4 HDR10 HLG
    // The macros ReShade's runtime adds for effects written for older versions (tex2Doffset,
    // tex2Dgather(s, t, c), tex2Dgather0…3).
    bool compatibilityMacros = true;
    // "NAME=VALUE", or "NAME" (ReShade gives an empty value 1). A name ReShade predefines is kept
    // with ReShade's value, as ReShade does, and a warning says so.
    std::vector<std::string> defines;
    // Searched for `#include` after the including file's own folder, in this order.
    std::vector<std::filesystem::path> includePaths;
};

// The object-like macros ReShade defines from the settings, in ReShade's order: __RESHADE__,
// __RESHADE_PERFORMANCE_MODE__, __VENDOR__, __DEVICE__, __RENDERER__, __APPLICATION__,
// BUFFER_WIDTH, BUFFER_HEIGHT, BUFFER_RCP_WIDTH, BUFFER_RCP_HEIGHT, BUFFER_COLOR_SPACE,
// BUFFER_COLOR_BIT_DEPTH. Numbers are decimal, as ReShade writes them.
std::vector<std::pair<std::string, std::string>> predefinedMacros(const ReshadeSettings& settings);

// The `#define` lines of compatibilityMacros, one a line.
const char* reshadeCompatibilityMacros();

// "NAME=VALUE" → {NAME, VALUE}; "NAME" and "NAME=" → {NAME, "1"}. Blanks around either part go.
std::pair<std::string, std::string> splitDefine(const std::string& define);

}  // namespace rmfx
