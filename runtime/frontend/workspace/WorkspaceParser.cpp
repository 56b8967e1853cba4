#include "frontend/workspace/WorkspaceParser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "frontend/workspace/detail/PassChildParser.h"
#include "io/xml/XmlDocumentParser.h"
#include "io/xml/XmlElementReader.h"
#include "model/EffectSelection.h"

namespace rmfx {
namespace {

using xml::ElementReader;
using xml::XMLElement;

class Parser {
public:
    Parser(std::string file, Diagnostics& diagnostics)
        : file_(std::move(file)), diagnostics_(diagnostics), passChildren_(file_, diagnostics_) {}

    void parseWorkspace(const XMLElement* root, Workspace& ws) {
        ElementReader r(root, file_, diagnostics_, {"version", "name", "size", "include-root", "profile", "texture-space"});
        auto version = r.string("version", true);
        if (version && *version != "1")
            r.error("unsupported version '" + *version + "': this rmfx reads version 1");
        ws.profile = r.choice<GlProfile>("profile", {{"core", GlProfile::Core}, {"compatibility", GlProfile::Compatibility}})
                         .value_or(GlProfile::Core);
        ws.textureSpace = r.choice<TextureSpace>("texture-space", {{"opengl", TextureSpace::OpenGL},
                                                                    {"direct3d9", TextureSpace::Direct3D9},
                                                                    {"direct3d10", TextureSpace::Direct3D10}})
                              .value_or(TextureSpace::OpenGL);
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
                if (e->Attribute("name")) {
                    NamedCamera named;
                    named.name = e->Attribute("name");
                    parseCamera(e, named.settings);
                    if (ws.findCamera(named.name))
                        unexpected(e, "a second <camera name=\"" + named.name + "\">: camera names are unique");
                    else
                        ws.cameras.push_back(std::move(named));
                } else {
                    parseCamera(e, ws.camera);
                }
            } else if (valueTypeFromElement(tag)) {
                if (auto v = parseVariable(e)) ws.variables.push_back(std::move(*v));
            } else if (tag == "code") {
                if (auto c = parseSnippet(e)) ws.snippets.push_back(std::move(*c));
            } else if (tag == "texture" || tag == "cubemap" || tag == "volume") {
                if (auto t = parseTexture(e)) ws.textures.push_back(std::move(*t));
            } else if (tag == "input") {
                parseInput(e, ws);
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
                                  "vec4, color, mat4, texture, cubemap, volume, input, target, pass, effect, output)");
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
        ElementReader r(e, file_, diagnostics_, {"name", "target", "distance", "yaw", "pitch", "roll", "fov", "near", "far",
                                                        "convention"});
        c.where = r.where();
        if (e->Attribute("name")) (void)r.identifier("name");
        c.rollDegrees = r.number("roll").value_or(c.rollDegrees);
        if (auto t = r.numbers<3>("target")) c.target = {(*t)[0], (*t)[1], (*t)[2]};
        c.distance = r.number("distance").value_or(c.distance);
        c.yawDegrees = r.number("yaw").value_or(c.yawDegrees);
        c.pitchDegrees = r.number("pitch").value_or(c.pitchDegrees);
        c.fovYDegrees = r.number("fov").value_or(c.fovYDegrees);
        c.nearPlane = r.number("near").value_or(c.nearPlane);
        c.farPlane = r.number("far").value_or(c.farPlane);
        c.convention = r.choice<CameraConvention>("convention", {{"opengl", CameraConvention::OpenGL},
                                                                 {"direct3d", CameraConvention::Direct3D}})
                           .value_or(c.convention);
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
        Result<Value> value = text ? parseValue(type, *text) : Result<Value>(Value{type, {}});
        if (!value) {
            r.error("attribute 'value': " + value.error());
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

    // <input name="photo" replaces="scene"/>: an ImageInput and the 2D texture that holds its image.
    void parseInput(const XMLElement* e, Workspace& ws) {
        ElementReader r(e, file_, diagnostics_, {"name", "replaces", "file", "viewport", "colorspace", "mipmaps", "description"});
        auto name = r.identifier("name");
        ImageInput input;
        input.where = r.where();
        input.replaces = r.string("replaces").value_or("");
        input.description = r.string("description").value_or("");
        input.sizesViewport = r.choice<bool>("viewport", {{"image", true}, {"workspace", false}})
                                  .value_or(!input.replaces.empty());
        Texture t;
        t.where = input.where;
        t.mipmaps = r.boolean("mipmaps").value_or(false);
        if (auto cs = r.choice<ColorSpace>("colorspace", {{"linear", ColorSpace::Linear}, {"srgb", ColorSpace::Srgb}}))
            t.colorSpace = *cs;
        if (auto file = r.string("file")) {
            if (file->empty()) r.error("attribute 'file' is empty");
            if (!input.replaces.empty())
                r.error("an input that replaces a target has no default file: without an image given, the "
                        "workspace draws '" + input.replaces + "' itself");
            t.files = {*file};
            t.fileLocations = {r.where()};
        }
        noChildren(e);
        if (!name) return;
        input.name = t.name = *name;
        ws.inputs.push_back(std::move(input));
        ws.textures.push_back(std::move(t));
    }

    std::optional<Texture> parseTexture(const XMLElement* e) {
        bool cube = std::string_view(e->Name()) == "cubemap";
        ElementReader r(e, file_, diagnostics_,
                        cube ? std::initializer_list<const char*>{"name", "file", "layout", "colorspace", "mipmaps", "face-size", "read-when"}
                             : std::initializer_list<const char*>{"name", "file", "colorspace", "mipmaps", "read-when"});
        Texture t;
        t.where = r.where();
        t.kind = cube ? TextureKind::Cube : std::string_view(e->Name()) == "volume" ? TextureKind::Volume : TextureKind::Texture2D;
        auto name = r.identifier("name");
        if (auto cs = r.choice<ColorSpace>("colorspace", {{"linear", ColorSpace::Linear}, {"srgb", ColorSpace::Srgb}}))
            t.colorSpace = *cs;
        t.mipmaps = r.boolean("mipmaps").value_or(true);
        if (auto when = r.string("read-when")) {
            const size_t equals = when->find('=');
            if (equals == std::string::npos || equals == 0 || equals + 1 == when->size())
                r.error("attribute 'read-when' is VARIABLE=VALUE (read-when=\"Environment_Format=1\"), got '" + *when + "'");
            else {
                t.readWhenVariable = when->substr(0, equals);
                t.readWhenValue = when->substr(equals + 1);
            }
        }
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
        ElementReader r(e, file_, diagnostics_, {"name", "target", "enabled", "camera"});
        Pass p;
        p.where = r.where();
        p.name = r.identifier("name").value_or("");
        p.target = r.string("target").value_or("");
        if (auto camera = r.identifier("camera", false)) {
            p.camera = *camera;
            p.cameraWhere = r.where();
        }
        p.enabled = r.boolean("enabled").value_or(true);
        bool drawSeen = false, clearSeen = false, blendSeen = false, depthSeen = false, cullSeen = false,
             polygonModeSeen = false;
        auto once = [&](const XMLElement* c, bool& seen) {
            if (seen) unexpected(c, "<" + std::string(c->Name()) + "> is given twice in " + r.label());
            seen = true;
        };
        for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
            std::string_view tag = c->Name();
            if (tag == "clear") {
                once(c, clearSeen);
                passChildren_.parseClear(c, p.clear);
            } else if (tag == "blend") {
                once(c, blendSeen);
                passChildren_.parseBlend(c, p.blend);
            } else if (tag == "depth") {
                once(c, depthSeen);
                passChildren_.parseDepth(c, p.depth);
            } else if (tag == "cull") {
                once(c, cullSeen);
                passChildren_.parseCull(c, p.raster);
            } else if (tag == "polygon-mode") {
                once(c, polygonModeSeen);
                passChildren_.parsePolygonMode(c, p.raster);
            } else if (tag == "shader") {
                if (auto s = passChildren_.parseShader(c)) {
                    for (const ShaderSource& other : p.shaders)
                        if (other.stage == s->stage)
                            unexpected(c, std::string("a second ") +
                                              (s->stage == ShaderStage::Vertex ? "vertex" : "fragment") +
                                              " shader in " + r.label() + " (first at line " +
                                              std::to_string(other.where.line) + ")");
                    p.shaders.push_back(std::move(*s));
                }
            } else if (tag == "sampler") {
                if (auto s = passChildren_.parseSampler(c)) p.samplers.push_back(std::move(*s));
            } else if (tag == "draw") {
                once(c, drawSeen);
                passChildren_.parseDraw(c, p.draw);
            } else if (tag == "stream") {
                if (auto stream = passChildren_.parseStream(c)) p.streams.push_back(std::move(*stream));
            } else if (valueTypeFromElement(tag)) {
                if (auto v = parseVariable(c)) p.constants.push_back(std::move(*v));
            } else {
                unexpected(c, "unknown element <" + std::string(tag) + "> in " + r.label() +
                                  " (expected clear, blend, depth, cull, polygon-mode, shader, sampler, draw, stream, or a value "
                                  "element such as float)");
            }
        }
        if (!drawSeen) {
            p.draw.mesh = BuiltinMesh::FullscreenTriangle;
            p.draw.where = p.where;
        }
        return p;
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
        ElementReader r(e, file_, diagnostics_, {"name", "passes", "switch", "source", "source-channels", "gate", "gate-channels", "description"});
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
        effect.source = r.string("source").value_or("");
        if (r.has("source") && effect.source.empty()) r.error("attribute 'source' names no target");
        auto channelsOf = [&](const char* attribute) {
            return r.choice<glm::bvec4>(attribute, {{"r", {true, false, false, false}},
                                                    {"rg", {true, true, false, false}},
                                                    {"rgb", {true, true, true, false}},
                                                    {"rgba", {true, true, true, true}},
                                                    {"a", {false, false, false, true}}});
        };
        if (auto channels = channelsOf("source-channels")) {
            if (effect.source.empty()) r.error("attribute 'source-channels' applies with 'source'");
            effect.sourceChannels = *channels;
        }
        effect.gate = r.string("gate").value_or("");
        if (r.has("gate") && effect.gate.empty()) r.error("attribute 'gate' names no target");
        if (!effect.gate.empty() && effect.source.empty()) r.error("attribute 'gate' applies with 'source': it is a cheaper test of the source");
        if (auto channels = channelsOf("gate-channels")) {
            if (effect.gate.empty()) r.error("attribute 'gate-channels' applies with 'gate'");
            effect.gateChannels = *channels;
        }
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
    workspace_detail::PassChildParser passChildren_;
};

}  // namespace

Result<Workspace> parseWorkspaceText(const std::string& text, const std::filesystem::path& path,
                                     const std::filesystem::path& folder) {
    std::string file = path.string();
    return xml::parseXmlText(text, file, "workspace", [&](const XMLElement* root, Diagnostics& diagnostics) {
        Workspace ws;
        ws.path = path;
        ws.folder = folder;
        Parser(file, diagnostics).parseWorkspace(root, ws);
        return ws;
    });
}

Result<Workspace> parseWorkspaceFile(const std::filesystem::path& path) {
    return xml::parseXmlFile(path, [&](const std::string& text) { return parseWorkspaceText(text, path, xml::folderOf(path)); });
}

}  // namespace rmfx
