#pragma once
// The workspace parser's readers of a <pass>'s state and resource children: <clear>, <blend>,
// <depth>, <cull>, <shader>, <stream>, <sampler>, <draw> (docs/workspace-format.md).

#include <optional>
#include <string>

#include "core/Diagnostic.h"
#include "io/xml/XmlElementReader.h"
#include "model/Workspace.h"

namespace rmfx::workspace_detail {

using xml::XMLElement;

class PassChildParser {
public:
    PassChildParser(const std::string& file, Diagnostics& diagnostics);

    void parseClear(const XMLElement* e, ClearState& c);
    void parseBlend(const XMLElement* e, BlendState& b);
    void parseDepth(const XMLElement* e, DepthState& d);
    void parseCull(const XMLElement* e, RasterState& s);
    void parsePolygonMode(const XMLElement* e, RasterState& s);
    std::optional<ShaderSource> parseShader(const XMLElement* e);
    std::optional<VertexStream> parseStream(const XMLElement* e);
    std::optional<Sampler> parseSampler(const XMLElement* e);
    void parseDraw(const XMLElement* e, DrawCall& d);

private:
    void noChildren(const XMLElement* e);

    const std::string& file_;
    Diagnostics& diagnostics_;
};

}  // namespace rmfx::workspace_detail
