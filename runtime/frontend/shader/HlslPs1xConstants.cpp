#include "frontend/shader/HlslPs1xConstants.h"

#include <cctype>
#include <regex>
#include <vector>

#include "core/IdentifierSearch.h"

namespace rmfx {

std::string clampPs1xConstants(std::string glsl, const std::string& profile) {
    std::string lower = profile;
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.rfind("ps_1_", 0) != 0) return glsl;
    // SpirvToGlsl writes each such constant as `uniform vec4 NAME;` (or `= …;` with an initial value).
    static const std::regex declaration(R"((^|\n)uniform (float|vec2|vec3|vec4) (\w+)( =[^;]*)?;)");
    std::vector<std::string> names;
    for (std::sregex_iterator it(glsl.begin(), glsl.end(), declaration), end; it != end; ++it) names.push_back((*it)[3].str());
    for (const std::string& name : names) {
        // The declaration keeps the name; every other mention reads it clamped.
        const std::string marker = "rm_ps1x_constant_" + name;
        replaceIdentifier(glsl, name, marker);
        for (const char* type : {"float ", "vec2 ", "vec3 ", "vec4 "}) {
            const std::string declared = std::string("uniform ") + type + marker;
            if (size_t at = glsl.find(declared); at != std::string::npos)
                glsl.replace(at, declared.size(), std::string("uniform ") + type + name);
        }
        replaceIdentifier(glsl, marker, "clamp(" + name + ", -1.0, 1.0)");
    }
    return glsl;
}

}  // namespace rmfx
