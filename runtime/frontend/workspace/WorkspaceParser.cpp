#include "frontend/workspace/WorkspaceParser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "model/BuiltinMeshNames.h"
#include "io/xml/XmlElementReader.h"
#include "model/EffectSelection.h"

namespace rmfx {
namespace {

using xml::ElementReader;
using xml::XMLElement;

class Parser {
public:
    Parser(std::string file, Diagnostics& diagnostics) : file_(std::move(file)), diagnostics_(diagnostics) {}

    void parseWorkspace(const XMLElement* root, Workspace& ws) {
        ElementReader r(root, file_, diagnostics_, {"version", "name", "size", "include-root", "profile"});
        auto version = r.string("version", true);
        if (version && *version != "1")
            r.error("unsupported version '" + *version + "': this rmfx reads version 1");
        ws.profile = r.choice<GlProfile>("profile", {{"core", GlProfile::Core}, {"compatibility", GlProfile::Compatibility}})
                         .value_or(GlProfile::Core);
        ws.name = r.string("name").value_or(ws.path.stem().string());
        if (auto wh = r.size("size")) {
            ws.width = wh->first;
            ws.height = wh->second;
        }
        if (auto root = r.string("include-root")) {
            // An ancestor of the workspace folder ("..", "../.."), so that workspaces in subfolders of
            // a shader library can include its shared files; nothing sideways or absolute.
            std::filesystem::path relative(*root);
            bool upOnly = !relative.empty() && relative.is_relative();
            for (const auto& part : relative) upOnly = upOnly && (part == ".." || part.empty());  // "../" too
            if (!upOnly)
                r.error("include-root '" + *root + "' must be an ancestor of the workspace folder: \"..\", \"../..\", ...");
            else {
                ws.includeRoot = (ws.folder / relative).lexically_normal();
                ws.includeRootWhere = r.where();
                if (!ws.includeRoot.has_filename()) ws.includeRoot = ws.includeRoot.parent_path();  // "a/b/.." is "a/"
            }
        }
        for (const XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
            std::string_view tag = e->Name();
            if (tag == "description") {
                ElementReader d(e, file_, diagnostics_, {});
                ws.description = e->GetText() ? e->GetText() : "";
            } else if (tag == "camera") {
                parseCamera(e, ws.camera);
            } else if (valueTypeFromElement(tag)) {
                if (auto v = parseVariable(e)) ws.variables.push_back(std::move(*v));
            } else if (tag == "code") {
                if (auto c = parseSnippet(e)) ws.snippets.push_back(std::move(*c));
            } else if (tag == "texture" || tag == "cubemap") {
                if (auto t = parseTexture(e)) ws.textures.push_back(std::move(*t));
            } else if (tag == "target") {
                if (auto t = parseTarget(e)) ws.targets.push_back(std::move(*t));
            } else if (tag == "pass") {
                ws.passes.push_back(parsePass(e));
            } else if (tag == "effect") {
                if (auto effect = parseEffect(e)) ws.effects.push_back(std::move(*effect));
            } else if (tag == "output") {
                if (ws.output.where.line > 0) {
                    ElementReader(e, file_, diagnostics_, {"target", "format", "transform", "effects"})
                        .error("a second <output> (the first is at line " + std::to_string(ws.output.where.line) +
                               "): a workspace has one");
                    continue;
                }
                parseOutput(e, ws.output);
            } else {
                unexpected(e, "unknown element <" + std::string(tag) +
                                  "> in <workspace> (expected description, camera, code, float, int, bool, vec2, vec3, "
                                  "vec4, color, mat4, texture, cubemap, target, pass, effect, output)");
            }
        }
        if (ws.passes.empty()) r.error("no <pass>: nothing to render");
    }

private:
    void unexpected(const XMLElement* e, const std::string& message) { xml::errorAt(e, file_, diagnostics_, message); }

    // "1/4", "0.25" → 0.25
    static std::optional<double> parseFraction(const std::string& text) {
        auto slash = text.find('/');
        if (slash == std::string::npos) {
            auto f = parseFloat(text);
            if (!f) return std::nullopt;
            return static_cast<double>(*f);
        }
        auto n = parseFloat(text.substr(0, slash)), d = parseFloat(text.substr(slash + 1));
        if (!n || !d || *d == 0.0f) return std::nullopt;
        return static_cast<double>(*n) / static_cast<double>(*d);
    }

    void parseCamera(const XMLElement* e, OrbitCameraSettings& c) {
        ElementReader r(e, file_, diagnostics_, {"target", "distance", "yaw", "pitch", "fov", "near", "far"});
        c.where = r.where();
        if (auto t = r.numbers<3>("target")) c.target = {(*t)[0], (*t)[1], (*t)[2]};
        c.distance = r.number("distance").value_or(c.distance);
        c.yawDegrees = r.number("yaw").value_or(c.yawDegrees);
        c.pitchDegrees = r.number("pitch").value_or(c.pitchDegrees);
        c.fovYDegrees = r.number("fov").value_or(c.fovYDegrees);
        c.nearPlane = r.number("near").value_or(c.nearPlane);
        c.farPlane = r.number("far").value_or(c.farPlane);
        if (c.distance <= 0) r.error("attribute 'distance' must be greater than 0");
        if (c.fovYDegrees <= 0 || c.fovYDegrees >= 180) r.error("attribute 'fov' must lie between 0 and 180 degrees");
        if (c.nearPlane <= 0 || c.farPlane <= c.nearPlane) r.error("need 0 < near < far");
        noChildren(e);
    }

    void noChildren(const XMLElement* e) { xml::noChildren(e, file_, diagnostics_); }

    std::optional<Variable> parseVariable(const XMLElement* e) {
        ValueType type = *valueTypeFromElement(e->Name());
        ElementReader r(e, file_, diagnostics_,
                        {"name", "value", "min", "max", "step", "ui", "options", "hdr", "description", "semantic"});
        Variable v;
        v.where = r.where();
        auto name = r.identifier("name");
        // A semantic variable gets its value every frame; the stored one (default zeros) is what
        // an unknown semantic leaves.
        v.semantic = r.string("semantic").value_or("");
        auto text = r.string("value", v.semantic.empty());
        if (!name || (!text && v.semantic.empty())) return std::nullopt;
        v.name = *name;
        if (v.name.rfind("rm_", 0) == 0) {
            r.error("the prefix rm_ is reserved for predefined variables");
            return std::nullopt;
        }
        std::string why;
        auto value = text ? parseValue(type, *text, &why) : Value{type, {}};
        if (!value) {
            r.error("attribute 'value': " + why);
            return std::nullopt;
        }
        v.value = *value;
        bool numeric = type != ValueType::Bool && type != ValueType::Mat2 && type != ValueType::Mat3 && type != ValueType::Mat4;
        if (numeric) {
            v.min = r.number("min");
            v.max = r.number("max");
            v.step = r.number("step");
        } else {
            for (const char* a : {"min", "max", "step"})
                if (r.has(a)) r.error("attribute '" + std::string(a) + "' does not apply to a " + valueTypeName(type));
        }
        if (v.step && *v.step <= 0) r.error("attribute 'step' must be greater than 0");
        bool inverted = v.min && v.max && *v.min > *v.max;
        if (inverted) r.error("min (" + formatValue(Value::ofFloat(*v.min)) + ") is greater than max (" +
                              formatValue(Value::ofFloat(*v.max)) + ")");
        if ((v.min || v.max) && !inverted) {  // no value lies in an inverted range: one error is enough
            for (int i = 0; i < componentCount(v.value.type); ++i) {
                float c = v.value.data[i];
                if ((v.min && c < *v.min) || (v.max && c > *v.max)) {
                    r.error("value " + formatValue(v.value) + " lies outside [" +
                            (v.min ? formatValue(Value::ofFloat(*v.min)) : "-inf") + ", " +
                            (v.max ? formatValue(Value::ofFloat(*v.max)) : "inf") + "]");
                    break;
                }
            }
        }
        if (auto ui = r.choice<WidgetHint>("ui", {{"auto", WidgetHint::Auto}, {"slider", WidgetHint::Slider},
                                                  {"drag", WidgetHint::Drag}, {"color", WidgetHint::Color},
                                                  {"checkbox", WidgetHint::Checkbox}, {"combo", WidgetHint::Combo}}))
            v.widget = *ui;
        if (v.widget == WidgetHint::Slider && (!v.min || !v.max)) r.error("ui=\"slider\" needs both min and max");
        if (v.widget == WidgetHint::Combo && type != ValueType::Int) r.error("ui=\"combo\" applies to int variables");
        if (v.widget == WidgetHint::Checkbox && type != ValueType::Bool) r.error("ui=\"checkbox\" applies to bool variables");
        if (v.widget == WidgetHint::Color && type != ValueType::Color3 && type != ValueType::Color4 &&
            type != ValueType::Vec3 && type != ValueType::Vec4)
            r.error("ui=\"color\" applies to color, vec3 and vec4 variables");
        if (auto options = r.string("options")) {
            std::stringstream ss(*options);
            for (std::string item; std::getline(ss, item, ',');) {
                while (!item.empty() && item.front() == ' ') item.erase(item.begin());
                while (!item.empty() && item.back() == ' ') item.pop_back();
                v.options.push_back(item);
            }
            if (type != ValueType::Int) r.error("attribute 'options' applies to int variables");
            else if (v.value.asInt() < 0 || v.value.asInt() >= static_cast<int>(v.options.size()))
                r.error("value " + formatValue(v.value) + " does not select one of the " +
                        std::to_string(v.options.size()) + " options");
            if (v.widget == WidgetHint::Auto) v.widget = WidgetHint::Combo;
        } else if (v.widget == WidgetHint::Combo) {
            r.error("ui=\"combo\" needs attribute 'options'");
        }
        v.hdr = r.boolean("hdr").value_or(false);
        v.description = r.string("description").value_or("");
        noChildren(e);
        return v;
    }

    std::optional<CodeSnippet> parseSnippet(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"name"});
        CodeSnippet c;
        c.where = r.where();
        auto name = r.string("name", true);
        noChildren(e);
        const char* text = e->GetText();
        if (!name) return std::nullopt;
        c.name = *name;
        c.code = text ? text : "";
        c.codeLine = e->FirstChild() ? e->FirstChild()->GetLineNum() : e->GetLineNum();
        return c;
    }

    std::optional<Texture> parseTexture(const XMLElement* e) {
        bool cube = std::string_view(e->Name()) == "cubemap";
        ElementReader r(e, file_, diagnostics_,
                        cube ? std::initializer_list<const char*>{"name", "file", "layout", "colorspace", "mipmaps", "face-size"}
                             : std::initializer_list<const char*>{"name", "file", "colorspace", "mipmaps"});
        Texture t;
        t.where = r.where();
        t.kind = cube ? TextureKind::Cube : TextureKind::Texture2D;
        auto name = r.identifier("name");
        if (auto cs = r.choice<ColorSpace>("colorspace", {{"linear", ColorSpace::Linear}, {"srgb", ColorSpace::Srgb}}))
            t.colorSpace = *cs;
        t.mipmaps = r.boolean("mipmaps").value_or(true);
        if (!cube) {
            auto file = r.string("file", true);
            noChildren(e);
            if (!name || !file) return std::nullopt;
            t.name = *name;
            t.files = {*file};
            t.fileLocations = {r.where()};
            return t;
        }
        if (auto size = r.integer("face-size", 1)) t.faceSize = *size;
        auto layout = r.choice<CubeLayout>("layout", {{"cross", CubeLayout::Cross}, {"equirect", CubeLayout::Equirect},
                                                       {"faces", CubeLayout::Faces}});
        auto file = r.string("file");
        static constexpr const char* sides[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
        std::array<std::optional<std::string>, 6> faces;
        std::array<SourceLocation, 6> faceWhere;
        bool anyFace = false;
        for (const XMLElement* f = e->FirstChildElement(); f; f = f->NextSiblingElement()) {
            if (std::string_view(f->Name()) != "face") {
                unexpected(f, "unknown element <" + std::string(f->Name()) + "> in <cubemap> (expected face)");
                continue;
            }
            anyFace = true;
            ElementReader fr(f, file_, diagnostics_, {"side", "file"});
            auto side = fr.choice<int>("side", {{"+x", 0}, {"-x", 1}, {"+y", 2}, {"-y", 3}, {"+z", 4}, {"-z", 5}});
            auto ff = fr.string("file", true);
            if (!fr.has("side")) fr.error("missing attribute 'side'");
            if (!side || !ff) continue;
            if (faces[*side]) fr.error("face " + std::string(sides[*side]) + " is given twice");
            faces[*side] = *ff;
            faceWhere[*side] = fr.where();
            noChildren(f);
        }
        if (!name) return std::nullopt;
        t.name = *name;
        if (anyFace) {
            if (file) r.error("give either attribute 'file' or six <face> elements, not both");
            if (layout && *layout != CubeLayout::Faces) r.error("<face> elements need layout=\"faces\"");
            t.layout = CubeLayout::Faces;
            for (int i = 0; i < 6; ++i) {
                if (!faces[i]) {
                    r.error("face " + std::string(sides[i]) + " is missing (a cubemap takes +x -x +y -y +z -z)");
                    return std::nullopt;
                }
                t.files.push_back(*faces[i]);
                t.fileLocations.push_back(faceWhere[i]);
            }
            return t;
        }
        if (!file) {
            r.error("a cubemap needs attribute 'file' (with layout cross or equirect) or six <face> elements");
            return std::nullopt;
        }
        t.layout = layout.value_or(CubeLayout::Cross);
        if (t.layout == CubeLayout::Faces) {
            r.error("layout=\"faces\" needs six <face> elements");
            return std::nullopt;
        }
        if (t.faceSize && t.layout != CubeLayout::Equirect) r.error("attribute 'face-size' applies to layout=\"equirect\"");
        t.files = {*file};
        t.fileLocations = {r.where()};
        return t;
    }

    std::optional<RenderTarget> parseTarget(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"name", "format", "format-by", "size", "scale", "scale-by", "mipmaps", "initial"});
        RenderTarget t;
        t.where = r.where();
        auto name = r.identifier("name");
        if (auto by = r.identifier("format-by", false)) t.formatVariable = *by;
        if (auto format = r.string("format", true)) {
            std::string spaced = *format;
            std::replace(spaced.begin(), spaced.end(), ',', ' ');
            std::vector<std::string> words;
            std::stringstream list(spaced);
            for (std::string w; list >> w;) words.push_back(w);
            for (const std::string& w : words) {
                if (auto f = targetFormatFromName(w)) t.formats.push_back(*f);
                else r.error("attribute 'format': unknown format '" + w +
                             "' (expected rgba8, rgba16f, rgba32f, r16f, r32f, rg16f, rg32f, rgba16, r11g11b10f, "
                             "rgb10a2, r8, rg8)");
            }
            if (words.size() > 1 && t.formatVariable.empty())
                r.error("attribute 'format': a list of formats needs format-by=\"VARIABLE\", the int variable whose "
                        "value picks one");
            if (words.empty()) r.error("attribute 'format' is empty");
            if (!t.formats.empty()) t.format = t.formats[0];
            if (t.formatVariable.empty()) t.formats.clear();
        }
        auto scale = r.string("scale");
        if (r.has("size") && scale) r.error("give either 'size' (absolute) or 'scale' (relative to the viewport), not both");
        if (r.has("size")) {
            if (auto wh = r.size("size", "64x64")) {
                t.size.relative = false;
                t.size.width = wh->first;
                t.size.height = wh->second;
            }
        } else if (scale) {
            std::string spaced = *scale;
            std::replace(spaced.begin(), spaced.end(), ',', ' ');
            auto parts = std::stringstream(spaced);
            std::vector<std::string> words;
            for (std::string w; parts >> w;) words.push_back(w);
            auto inRange = [](std::optional<double> f) { return f && *f > 0 && *f <= 16; };
            if (auto by = r.identifier("scale-by", false)) {
                // A list of choices, each one fraction for both axes.
                t.scaleVariable = *by;
                for (const std::string& w : words) {
                    auto f = parseFraction(w);
                    if (!inRange(f)) {
                        r.error("attribute 'scale': expected fractions of the viewport in (0, 16] such as \"1/2 1/4 1/8\" "
                                "(one per value of '" + *by + "'), got '" + w + "'");
                        continue;
                    }
                    TargetSize choice;
                    choice.scaleX = choice.scaleY = *f;
                    t.scales.push_back(choice);
                }
                if (words.empty()) r.error("attribute 'scale' is empty");
                if (!t.scales.empty()) t.size = t.scales[0];
            } else {
                std::optional<double> sx, sy;
                if (words.size() == 1 || words.size() == 2) {
                    sx = parseFraction(words[0]);
                    sy = words.size() == 2 ? parseFraction(words[1]) : sx;
                }
                if (!inRange(sx) || !inRange(sy))
                    r.error("attribute 'scale': expected one or two fractions of the viewport in (0, 16] such as 1/4 or "
                            "\"1/2 1/4\" (x and y; a list of choices needs scale-by=\"VARIABLE\"), got '" + *scale + "'");
                else {
                    t.size.scaleX = *sx;
                    t.size.scaleY = *sy;
                }
            }
        }
        if (r.has("scale-by") && !scale) r.error("attribute 'scale-by' needs 'scale' with one fraction per value");
        t.mipmaps = r.boolean("mipmaps").value_or(false);
        if (auto initial = r.numbers<4>("initial")) t.initial = {(*initial)[0], (*initial)[1], (*initial)[2], (*initial)[3]};
        noChildren(e);
        if (!name) return std::nullopt;
        t.name = *name;
        return t;
    }

    Pass parsePass(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"name", "target", "enabled"});
        Pass p;
        p.where = r.where();
        p.name = r.identifier("name").value_or("");
        p.target = r.string("target").value_or("");
        p.enabled = r.boolean("enabled").value_or(true);
        bool drawSeen = false, clearSeen = false, blendSeen = false, depthSeen = false, cullSeen = false;
        auto once = [&](const XMLElement* c, bool& seen) {
            if (seen) unexpected(c, "<" + std::string(c->Name()) + "> is given twice in " + r.label());
            seen = true;
        };
        for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
            std::string_view tag = c->Name();
            if (tag == "clear") {
                once(c, clearSeen);
                parseClear(c, p.clear);
            } else if (tag == "blend") {
                once(c, blendSeen);
                parseBlend(c, p.blend);
            } else if (tag == "depth") {
                once(c, depthSeen);
                parseDepth(c, p.depth);
            } else if (tag == "cull") {
                once(c, cullSeen);
                parseCull(c, p.raster);
            } else if (tag == "shader") {
                if (auto s = parseShader(c)) {
                    for (const ShaderSource& other : p.shaders)
                        if (other.stage == s->stage)
                            unexpected(c, std::string("a second ") +
                                              (s->stage == ShaderStage::Vertex ? "vertex" : "fragment") +
                                              " shader in " + r.label() + " (first at line " +
                                              std::to_string(other.where.line) + ")");
                    p.shaders.push_back(std::move(*s));
                }
            } else if (tag == "sampler") {
                if (auto s = parseSampler(c)) p.samplers.push_back(std::move(*s));
            } else if (tag == "draw") {
                once(c, drawSeen);
                parseDraw(c, p.draw);
            } else if (tag == "stream") {
                if (auto stream = parseStream(c)) p.streams.push_back(std::move(*stream));
            } else if (valueTypeFromElement(tag)) {
                if (auto v = parseVariable(c)) p.constants.push_back(std::move(*v));
            } else {
                unexpected(c, "unknown element <" + std::string(tag) + "> in " + r.label() +
                                  " (expected clear, blend, depth, cull, shader, sampler, draw, stream, or a value "
                                  "element such as float)");
            }
        }
        if (!drawSeen) {
            p.draw.mesh = BuiltinMesh::FullscreenTriangle;
            p.draw.where = p.where;
        }
        return p;
    }

    void parseClear(const XMLElement* e, ClearState& c) {
        ElementReader r(e, file_, diagnostics_, {"color", "depth"});
        if (auto color = r.numbers<4>("color")) c.color = glm::vec4((*color)[0], (*color)[1], (*color)[2], (*color)[3]);
        c.depth = r.number("depth");
        if (c.depth && (*c.depth < 0 || *c.depth > 1)) r.error("attribute 'depth' must lie in [0, 1]");
        if (!r.has("color") && !r.has("depth")) r.error("<clear> needs 'color', 'depth' or both");
        noChildren(e);
    }

    static std::initializer_list<std::pair<const char*, BlendFactor>> blendFactors() {
        static const std::initializer_list<std::pair<const char*, BlendFactor>> list = {
            {"zero", BlendFactor::Zero}, {"one", BlendFactor::One}, {"src-color", BlendFactor::SrcColor},
            {"one-minus-src-color", BlendFactor::OneMinusSrcColor}, {"dst-color", BlendFactor::DstColor},
            {"one-minus-dst-color", BlendFactor::OneMinusDstColor}, {"src-alpha", BlendFactor::SrcAlpha},
            {"one-minus-src-alpha", BlendFactor::OneMinusSrcAlpha}, {"dst-alpha", BlendFactor::DstAlpha},
            {"one-minus-dst-alpha", BlendFactor::OneMinusDstAlpha}, {"constant", BlendFactor::ConstantColor},
            {"one-minus-constant", BlendFactor::OneMinusConstantColor}};
        return list;
    }

    void parseBlend(const XMLElement* e, BlendState& b) {
        ElementReader r(e, file_, diagnostics_,
                        {"mode", "src", "dst", "op", "src-alpha", "dst-alpha", "op-alpha", "constant"});
        enum class Mode { None, Add, Alpha, Premultiplied, Multiply, Custom };
        auto mode = r.choice<Mode>("mode", {{"none", Mode::None}, {"add", Mode::Add}, {"alpha", Mode::Alpha},
                                            {"premultiplied", Mode::Premultiplied}, {"multiply", Mode::Multiply},
                                            {"custom", Mode::Custom}});
        bool explicitFactors = r.has("src") || r.has("dst") || r.has("op") || r.has("src-alpha") ||
                               r.has("dst-alpha") || r.has("op-alpha");
        Mode m = mode.value_or(explicitFactors ? Mode::Custom : Mode::None);
        if (explicitFactors && m != Mode::Custom)
            r.error("'src', 'dst' and 'op' need mode=\"custom\" (or no mode)");
        b.enabled = m != Mode::None;
        switch (m) {
            case Mode::Add: b.srcColor = b.dstColor = b.srcAlpha = b.dstAlpha = BlendFactor::One; break;
            case Mode::Alpha:
                b.srcColor = b.srcAlpha = BlendFactor::SrcAlpha;
                b.dstColor = b.dstAlpha = BlendFactor::OneMinusSrcAlpha;
                break;
            case Mode::Premultiplied:
                b.srcColor = b.srcAlpha = BlendFactor::One;
                b.dstColor = b.dstAlpha = BlendFactor::OneMinusSrcAlpha;
                break;
            case Mode::Multiply:
                b.srcColor = b.srcAlpha = BlendFactor::DstColor;
                b.dstColor = b.dstAlpha = BlendFactor::Zero;
                break;
            default: break;
        }
        if (m == Mode::Custom) {
            auto ops = std::initializer_list<std::pair<const char*, BlendOp>>{
                {"add", BlendOp::Add}, {"subtract", BlendOp::Subtract},
                {"reverse-subtract", BlendOp::ReverseSubtract}, {"min", BlendOp::Min}, {"max", BlendOp::Max}};
            b.srcColor = r.choice<BlendFactor>("src", blendFactors()).value_or(BlendFactor::One);
            b.dstColor = r.choice<BlendFactor>("dst", blendFactors()).value_or(BlendFactor::Zero);
            b.colorOp = r.choice<BlendOp>("op", ops).value_or(BlendOp::Add);
            b.srcAlpha = r.choice<BlendFactor>("src-alpha", blendFactors()).value_or(b.srcColor);
            b.dstAlpha = r.choice<BlendFactor>("dst-alpha", blendFactors()).value_or(b.dstColor);
            b.alphaOp = r.choice<BlendOp>("op-alpha", ops).value_or(b.colorOp);
        }
        if (auto c = r.numbers<4>("constant")) b.constant = {(*c)[0], (*c)[1], (*c)[2], (*c)[3]};
        noChildren(e);
    }

    void parseDepth(const XMLElement* e, DepthState& d) {
        ElementReader r(e, file_, diagnostics_, {"test", "write"});
        auto func = r.choice<CompareFunc>(
            "test", {{"never", CompareFunc::Never}, {"less", CompareFunc::Less}, {"equal", CompareFunc::Equal},
                     {"lequal", CompareFunc::LessEqual}, {"greater", CompareFunc::Greater},
                     {"notequal", CompareFunc::NotEqual}, {"gequal", CompareFunc::GreaterEqual},
                     {"always", CompareFunc::Always}, {"off", CompareFunc::Always}});
        d.test = func.has_value() && r.string("test") != "off";
        if (func) d.func = *func;
        d.write = r.boolean("write").value_or(d.test);
        noChildren(e);
    }

    void parseCull(const XMLElement* e, RasterState& s) {
        ElementReader r(e, file_, diagnostics_, {"face", "front"});
        s.cull = r.choice<CullFace>("face", {{"none", CullFace::None}, {"back", CullFace::Back},
                                             {"front", CullFace::Front}})
                     .value_or(CullFace::Back);
        s.frontCounterClockwise = r.choice<bool>("front", {{"ccw", true}, {"cw", false}}).value_or(true);
        noChildren(e);
    }

    std::optional<ShaderSource> parseShader(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"stage", "file", "dialect", "entry", "profile"});
        ShaderSource s;
        s.where = r.where();
        s.dialect = r.choice<ShaderDialect>("dialect", {{"glsl450", ShaderDialect::Glsl},
                                                        {"glsl110", ShaderDialect::GlslLegacy},
                                                        {"glsles100", ShaderDialect::GlslEs100},
                                                        {"hlsl", ShaderDialect::Hlsl}})
                        .value_or(ShaderDialect::Glsl);
        s.entryPoint = r.string("entry").value_or("");
        s.profile = r.string("profile").value_or("");
        if (s.dialect != ShaderDialect::Hlsl && (r.has("entry") || r.has("profile")))
            r.error("attributes 'entry' and 'profile' apply to dialect=\"hlsl\"");
        auto stage = r.choice<ShaderStage>("stage", {{"vertex", ShaderStage::Vertex}, {"fragment", ShaderStage::Fragment}});
        if (!r.has("stage")) r.error("missing attribute 'stage' (vertex or fragment)");
        auto file = r.string("file");
        const char* text = e->GetText();
        bool hasCode = text && std::string_view(text).find_first_not_of(" \t\r\n") != std::string_view::npos;
        noChildren(e);
        if (file && hasCode) {
            r.error("give either attribute 'file' or inline code, not both");
            return std::nullopt;
        }
        if (!file && !hasCode) {
            r.error("no code: give attribute 'file' or the code inside the element");
            return std::nullopt;
        }
        if (!stage) return std::nullopt;
        s.stage = *stage;
        if (file) {
            s.file = *file;
        } else {
            s.code = text;
            // The text node's line is where the code begins; tinyxml2 keeps it on the first child node.
            s.codeLine = e->FirstChild() ? e->FirstChild()->GetLineNum() : e->GetLineNum();
        }
        return s;
    }

    // <stream usage="texcoord" index="0" attribute="rm_TexCoord0"/>: no attribute feeds the
    // compatibility built-in (gl_MultiTexCoord0).
    std::optional<VertexStream> parseStream(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"usage", "index", "attribute"});
        VertexStream s;
        s.where = r.where();
        auto usage = r.choice<VertexUsage>("usage", {{"position", VertexUsage::Position}, {"normal", VertexUsage::Normal},
                                                     {"texcoord", VertexUsage::TexCoord}, {"tangent", VertexUsage::Tangent},
                                                     {"binormal", VertexUsage::Binormal}, {"color", VertexUsage::Color}});
        if (!r.has("usage")) r.error("missing attribute 'usage' (position, normal, texcoord, tangent, binormal or color)");
        s.usageIndex = r.integer("index", 0).value_or(0);
        if (s.usageIndex > 7) r.error("attribute 'index': texture coordinate sets go from 0 to 7");
        if (usage && *usage != VertexUsage::TexCoord && s.usageIndex != 0)
            r.error("attribute 'index' applies to usage=\"texcoord\" (the mesh has one of each other stream)");
        if (r.has("attribute")) s.attribute = r.identifier("attribute").value_or("");
        noChildren(e);
        if (!usage) return std::nullopt;
        s.usage = *usage;
        return s;
    }

    std::optional<Sampler> parseSampler(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_,
                        {"name", "texture", "target", "frame", "filter", "mipmap", "wrap", "wrap-s", "wrap-t", "border"});
        Sampler s;
        s.where = r.where();
        auto name = r.identifier("name");
        auto texture = r.string("texture");
        auto target = r.string("target");
        if (texture && target) r.error("give either 'texture' or 'target', not both");
        if (!texture && !target) r.error("missing attribute 'texture' or 'target'");
        s.texture = texture.value_or("");
        s.target = target.value_or("");
        if (auto frame = r.choice<bool>("frame", {{"current", false}, {"previous", true}})) {
            s.previousFrame = *frame;
            if (*frame && !target) r.error("frame=\"previous\" applies to render targets");
        }
        s.filter = r.choice<Filter>("filter", {{"nearest", Filter::Nearest}, {"linear", Filter::Linear}}).value_or(Filter::Linear);
        s.mipmap = r.choice<MipmapMode>("mipmap", {{"none", MipmapMode::None}, {"nearest", MipmapMode::Nearest},
                                                   {"linear", MipmapMode::Linear}})
                       .value_or(MipmapMode::None);
        std::initializer_list<std::pair<const char*, Wrap>> wraps = {
            {"repeat", Wrap::Repeat}, {"clamp", Wrap::Clamp}, {"mirror", Wrap::Mirror}, {"border", Wrap::Border}};
        Wrap both = r.choice<Wrap>("wrap", wraps).value_or(Wrap::Clamp);
        s.wrapS = r.choice<Wrap>("wrap-s", wraps).value_or(both);
        s.wrapT = r.choice<Wrap>("wrap-t", wraps).value_or(both);
        if (auto b = r.numbers<4>("border")) s.border = {(*b)[0], (*b)[1], (*b)[2], (*b)[3]};
        noChildren(e);
        if (!name || (!texture && !target)) return std::nullopt;
        s.uniform = *name;
        return s;
    }

    void parseDraw(const XMLElement* e, DrawCall& d) {
        ElementReader r(e, file_, diagnostics_, {"mesh", "file", "translate", "rotate", "scale"});
        d.where = r.where();
        auto mesh = r.string("mesh");
        auto file = r.string("file");
        if (mesh && file) r.error("give either 'mesh' (built-in) or 'file' (a model), not both");
        if (!mesh && !file) r.error("missing attribute 'mesh' (fullscreen, cube, sphere, plane, teapot) or 'file'");
        if (mesh) {
            d.mesh = builtinMeshFromName(*mesh);
            if (!d.mesh)
                r.error("attribute 'mesh': unknown mesh '" + *mesh + "' (expected fullscreen, cube, sphere, plane, teapot)");
        }
        if (file) d.file = *file;
        if (auto t = r.numbers<3>("translate")) d.translate = {(*t)[0], (*t)[1], (*t)[2]};
        if (auto t = r.numbers<3>("rotate")) d.rotateDegrees = {(*t)[0], (*t)[1], (*t)[2]};
        if (auto s = r.string("scale")) {
            auto list = parseFloatList(*s);
            if (list && list->size() == 1) d.scale = glm::vec3((*list)[0]);
            else if (list && list->size() == 3) d.scale = {(*list)[0], (*list)[1], (*list)[2]};
            else r.error("attribute 'scale': expected 1 or 3 numbers, got '" + *s + "'");
        }
        noChildren(e);
    }

    // Names separated by spaces or commas; each must be an identifier.
    std::optional<std::vector<std::string>> nameList(const ElementReader& r, const char* attribute) {
        auto text = r.string(attribute);
        if (!text) return std::nullopt;
        std::vector<std::string> names = splitNameList(*text);
        bool ok = true;
        for (const std::string& name : names) {
            bool identifier = !std::isdigit(static_cast<unsigned char>(name[0]));
            for (char c : name) identifier = identifier && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
            if (!identifier) {
                r.error("attribute '" + std::string(attribute) + "': '" + name + "' is not a name");
                ok = false;
            }
        }
        if (!ok) return std::nullopt;
        return names;
    }

    std::optional<Effect> parseEffect(const XMLElement* e) {
        ElementReader r(e, file_, diagnostics_, {"name", "passes", "switch", "description"});
        auto name = r.identifier("name");
        if (!name) return std::nullopt;
        Effect effect;
        effect.name = *name;
        effect.where = r.where();
        effect.description = r.string("description").value_or("");
        auto passes = nameList(r, "passes");
        if (!passes || passes->empty()) {
            if (!r.has("passes")) r.error("attribute 'passes' is required: the passes of the effect, in any order");
            else if (passes) r.error("attribute 'passes' names no pass");
            return std::nullopt;
        }
        effect.passes = std::move(*passes);
        effect.switches = nameList(r, "switch").value_or(std::vector<std::string>{});
        noChildren(e);
        return effect;
    }

    void parseOutput(const XMLElement* e, Output& o) {
        ElementReader r(e, file_, diagnostics_, {"target", "format", "transform", "effects"});
        if (r.has("effects")) o.effects = nameList(r, "effects").value_or(std::vector<std::string>{});
        o.where = r.where();
        o.target = r.string("target").value_or("");
        if (auto format = r.string("format")) {
            if (!o.target.empty()) r.error("attribute 'format' applies to the implicit output; target '" + o.target +
                                           "' has its own format");
            if (auto f = targetFormatFromName(*format)) o.format = *f;
            else r.error("attribute 'format': unknown format '" + *format + "'");
        }
        o.transform = r.choice<DisplayTransform>("transform", {{"none", DisplayTransform::None},
                                                               {"srgb", DisplayTransform::Srgb}})
                          .value_or(DisplayTransform::Srgb);
        noChildren(e);
    }

    std::string file_;
    Diagnostics& diagnostics_;
};

}  // namespace

ParsedWorkspace parseWorkspaceText(const std::string& text, const std::filesystem::path& path,
                                   const std::filesystem::path& folder) {
    ParsedWorkspace result;
    std::string file = path.string();
    tinyxml2::XMLDocument doc;
    const XMLElement* root = xml::parseDocument(doc, text, file, "workspace", result.diagnostics);
    if (!root) return result;
    Workspace ws;
    ws.path = path;
    ws.folder = folder;
    Parser(file, result.diagnostics).parseWorkspace(root, ws);
    if (!hasErrors(result.diagnostics)) result.workspace = std::move(ws);
    return result;
}

ParsedWorkspace parseWorkspaceFile(const std::filesystem::path& path) {
    ParsedWorkspace result;
    auto text = xml::readTextFile(path, result.diagnostics);
    if (!text) return result;
    return parseWorkspaceText(*text, path, path.parent_path().empty() ? "." : path.parent_path());
}

}  // namespace rmfx
