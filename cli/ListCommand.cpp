// rmfx list FILE.rfx: what a RenderMonkey workspace holds and what each effect needs to run.

#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "apps/ArgumentParser.h"
#include "cli/Commands.h"
#include "apps/OptionValues.h"
#include "core/IdentifierSearch.h"
#include "frontend/rfx/RfxImporter.h"
#include "io/media/MediaArguments.h"
#include "io/media/MediaResolver.h"
#include "model/BuiltinMeshNames.h"
#include "model/VertexUsageName.h"
#include "validation/Validation.h"

namespace rmfx::cli {

using namespace rmfx::apps;  // the shared argument loop and option values
namespace {

const char* dialectName(ShaderDialect d) {
    switch (d) {
        case ShaderDialect::Glsl: return "GLSL 4.50";
        case ShaderDialect::GlslLegacy: return "GLSL (compatibility)";
        case ShaderDialect::GlslEs100: return "GLSL ES 1.00";
        case ShaderDialect::Hlsl: return "HLSL";
    }
    return "?";
}

std::string statesText(const Pass& p) {
    static const char* compare[] = {"never", "less", "equal", "less-equal", "greater", "not-equal", "greater-equal", "always"};
    static const char* factor[] = {"zero", "one", "src-color", "one-minus-src-color", "dst-color", "one-minus-dst-color",
                                   "src-alpha", "one-minus-src-alpha", "dst-alpha", "one-minus-dst-alpha",
                                   "constant-color", "one-minus-constant-color"};
    static const char* op[] = {"add", "subtract", "reverse-subtract", "min", "max"};
    static const char* cull[] = {"none", "back", "front"};
    std::ostringstream out;
    out << "depth test " << (p.depth.test ? std::string("on (") + compare[static_cast<int>(p.depth.func)] + ")" : "off")
        << ", write " << (p.depth.write ? "on" : "off") << "; blend ";
    if (p.blend.enabled)
        out << factor[static_cast<int>(p.blend.srcColor)] << " " << op[static_cast<int>(p.blend.colorOp)] << " "
            << factor[static_cast<int>(p.blend.dstColor)] << " (alpha " << factor[static_cast<int>(p.blend.srcAlpha)] << " "
            << op[static_cast<int>(p.blend.alphaOp)] << " " << factor[static_cast<int>(p.blend.dstAlpha)] << ")";
    else
        out << "off";
    out << "; cull " << cull[static_cast<int>(p.raster.cull)] << (p.raster.frontCounterClockwise ? "" : ", front clockwise");
    static const char* mode[] = {"fill", "line", "point"};
    if (p.raster.frontMode != PolygonMode::Fill || p.raster.backMode != PolygonMode::Fill)
        out << "; polygons: front " << mode[static_cast<int>(p.raster.frontMode)] << ", back "
            << mode[static_cast<int>(p.raster.backMode)];
    if (p.raster.lineWidth != 1.0f) out << "; lines " << formatValue(Value::ofFloat(p.raster.lineWidth)) << " pixels wide";
    return out.str();
}

std::string sizeText(const TargetSize& s) {
    std::ostringstream out;
    if (s.relative) out << s.scaleX << "x" << s.scaleY << " of the viewport";
    else out << s.width << "x" << s.height;
    return out.str();
}

bool mentions(const Pass& pass, const std::string& name) {
    for (const ShaderSource& s : pass.shaders)
        if (mentionsIdentifier(s.code, name)) return true;
    return false;
}

void describeVariable(std::ostream& out, const Variable& v, const char* scope) {
    out << "        " << v.name << " (" << valueTypeName(v.value.type);
    if (!v.semantic.empty()) out << ", semantic " << v.semantic;
    if (v.editable) out << ", editable";
    out << scope << ")\n";
}

void describePass(std::ostream& out, const Workspace& ws, const Pass& pass, const Pass* previous) {
    out << "    pass '" << pass.name << "'" << (pass.enabled ? "" : " (disabled)") << ", line " << pass.where.line
        << " → " << (pass.target.empty() ? "the output" : "target '" + pass.target + "'");
    if (pass.clear.color) {
        const auto& c = *pass.clear.color;
        out << ", clears colour to " << c.r << " " << c.g << " " << c.b << " " << c.a;
    }
    if (pass.clear.depth) out << ", clears depth to " << *pass.clear.depth;
    out << "\n";
    bool borrowed = previous && !pass.shaders.empty() && pass.shaders.front().where.line < pass.where.line &&
                    previous->shaders.size() == pass.shaders.size();
    for (const ShaderSource& s : pass.shaders) {
        out << "      " << (s.stage == ShaderStage::Vertex ? "vertex" : "fragment") << " shader: " << dialectName(s.dialect);
        if (s.dialect == ShaderDialect::Hlsl) out << ", entry " << s.entryPoint << ", target " << s.profile;
        out << ", code at line " << s.codeLine << (borrowed ? " (the program of the pass before)" : "") << "\n";
    }
    out << "      states: " << statesText(pass) << "\n";
    out << "      model: " << (pass.draw.file.empty() ? "none (rmfx's full-screen triangle)" : pass.draw.file) << "\n";
    if (!pass.streams.empty()) {
        out << "      streams:";
        for (const VertexStream& s : pass.streams)
            out << " " << vertexUsageName(s.usage) << s.usageIndex << "→" << (s.attribute.empty() ? "built-in" : s.attribute);
        out << "\n";
    }
    for (const Sampler& s : pass.samplers) {
        out << "      sampler " << s.uniform << " → ";
        if (!s.target.empty()) {
            out << "target '" << s.target << "'";
        } else {
            out << "texture '" << s.texture << "'";
            if (const Texture* t = ws.findTexture(s.texture); t && !t->files.empty()) out << " (" << t->files.front() << ")";
        }
        out << "\n";
    }
    out << "      variables it needs:\n";
    std::set<std::string> shown;
    for (const Variable& v : pass.constants)
        if (shown.insert(v.name).second) describeVariable(out, v, ", pass-level");
    for (const Variable& v : ws.variables)
        if (mentions(pass, v.name) && shown.insert(v.name).second) describeVariable(out, v, "");
    if (shown.empty()) out << "        (none)\n";
}

// Each texture and model file as written, and where it is found, or that it is missing and what
// stands in for it.
void describeMedia(std::ostream& out, const Workspace& ws, const MediaOptions& options) {
    std::map<std::string, std::string> standIns;  // reference → what stands in when it is missing
    const bool placeholders = options.missing == MissingMedia::Placeholder;
    for (const Texture& t : ws.textures)
        for (const std::string& file : t.files)
            standIns.emplace(file, placeholders ? "a magenta and grey checker stands in" : "");
    for (const Pass& p : ws.passes) {
        if (p.draw.file.empty()) continue;
        if (std::optional<BuiltinMesh> stock = stockModelStandIn(p.draw.file))
            standIns.emplace(p.draw.file, std::string("rmfx's built-in '") + builtinMeshName(*stock) + "' stands in");
        else
            standIns.emplace(p.draw.file, placeholders ? std::string("rmfx's built-in '") +
                                                             builtinMeshName(placeholderMeshFor(p.draw.file)) + "' stands in"
                                                       : "");
    }
    MediaResolver resolver(ws.folder, options);
    std::ostringstream lines;
    int missing = 0;
    for (const auto& [reference, standIn] : standIns) {
        MediaResolver::Found found = resolver.resolve(reference, "file");
        lines << "      " << reference;
        if (found.file) {
            if (found.file->generic_string() != reference) lines << " → " << found.file->generic_string();
        } else if (found.missing) {
            ++missing;
            lines << ": missing" << (standIn.empty() ? " (an error; --missing-media placeholder renders with a stand-in)" : "; " + standIn);
        } else {
            lines << ": " << found.error;
        }
        lines << "\n";
    }
    out << "    media files:" << (standIns.empty() ? " none" : "");
    if (missing) out << " " << missing << " of " << standIns.size() << " missing";
    out << "\n" << lines.str();
}

void describeWorkspace(std::ostream& out, const Workspace& ws, const MediaOptions& media) {
    for (size_t i = 0; i < ws.passes.size(); ++i)
        describePass(out, ws, ws.passes[i], i ? &ws.passes[i - 1] : nullptr);
    for (const RenderTarget& t : ws.targets)
        out << "    target '" << t.name << "': " << targetFormatName(t.format) << ", " << sizeText(t.size)
            << (t.mipmaps ? ", mipmaps" : "") << "\n";
    describeMedia(out, ws, media);
}

}  // namespace

ArgumentParser listParser(std::vector<std::string>& files, MediaOptions& media) {
    ArgumentParser parser;
    parser.positional([&](const std::string& file) { files.push_back(file); return ""; });
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, media); },
               kMediaOptionNames);
    return parser;
}

std::vector<std::string> listOptionNames() {
    std::vector<std::string> files;
    MediaOptions media;
    return listParser(files, media).names();
}

int listCommand(const std::vector<std::string>& args) {
    std::vector<std::string> files;
    MediaOptions media;
    ArgumentParser parser = listParser(files, media);
    if (std::string error = parser.parse(args); !error.empty() || files.size() != 1) {
        std::cerr << "rmfx list: " << (error.empty() ? "" : error + "; ")
                  << "usage: rmfx list FILE.rfx [--media DIR ...] [--missing-media error|placeholder]\n";
        return 1;
    }
    const std::string& path = files[0];
    if (!isRfxPath(path)) {
        std::cerr << "rmfx list: '" << path << "' is not a RenderMonkey .rfx file\n";
        return 1;
    }
    Result<std::vector<RfxEffectSummary>> list = listRfxEffects(path);
    std::cerr << formatAll(list.diagnostics());
    if (!list) return 1;
    std::cout << path << ": " << list->size() << (list->size() == 1 ? " effect" : " effects") << "\n";
    int status = 0;
    for (const RfxEffectSummary& e : *list) {
        std::cout << "  effect '" << e.path << "' (" << e.api << (e.active ? ", active" : "") << "), line " << e.line << "\n";
        Result<Workspace> parsed = importRfxFile(path, {e.path});
        // Warnings about the file as a whole come once, with the list above; per-effect ones here.
        for (const Diagnostic& d : parsed.diagnostics()) std::cout << "    " << d.format() << "\n";
        if (!parsed) {
            status = 1;
            continue;
        }
        describeWorkspace(std::cout, *parsed, media);
    }
    return status;
}

}  // namespace rmfx::cli
