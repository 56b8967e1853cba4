#pragma once
// What the ReshadeParser*Test files share: an effect written to a scratch folder, preprocessed and
// parsed, with every problem of both steps formatted.

#include <string>
#include <vector>

#include "frontend/Test/ReshadePreprocessorTestSupport.h"
#include "frontend/reshade/ReshadeParser.h"

namespace rmfx::test {

struct ReshadeParse {
    ReshadeRun pre;
    ReshadeEffect effect;
    std::string folder;

    // Every diagnostic of the preprocessor and the parser, formatted, the scratch folder cut.
    std::vector<std::string> problems() const { return pre.problems(folder); }
    // Only the errors.
    std::vector<std::string> errors() const {
        std::vector<std::string> out;
        for (const std::string& p : problems())
            if (p.find(": error: ") != std::string::npos) out.push_back(p);
        return out;
    }
    // The text of the preprocessed code in a span.
    std::string text(const ReshadeSpan& span) const { return pre.out.code.substr(span.begin, span.end - span.begin); }
};

inline ReshadeParse parseText(const ScratchDir& dir, const std::string& code, ReshadeSettings settings = {}) {
    ReshadeParse parse;
    parse.folder = dir.path().string();
    parse.pre = preprocessText(dir, code, std::move(settings));
    parse.effect = parseReshadeEffect(parse.pre.out, parse.pre.diagnostics);
    return parse;
}

// A vertex and pixel shader pair, for techniques that need entry points.
inline std::string shaderPair() {
    return "void VS(uint id : SV_VertexID, out float4 pos : SV_Position, out float2 uv : TEXCOORD) { pos = 0; uv = 0; }\n"
           "float4 PS(float4 pos : SV_Position, float2 uv : TEXCOORD) : SV_Target { return 1; }\n";
}

}  // namespace rmfx::test
