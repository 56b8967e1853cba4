#include "frontend/workspace/detail/PassChildParser.h"

#include "model/BuiltinMeshNames.h"

namespace rmfx::workspace_detail {

using xml::ElementReader;

PassChildParser::PassChildParser(const std::string& file, Diagnostics& diagnostics) : file_(file), diagnostics_(diagnostics) {}

void PassChildParser::noChildren(const XMLElement* e) { xml::noChildren(e, file_, diagnostics_); }

void PassChildParser::parseClear(const XMLElement* e, ClearState& c) {
    ElementReader r(e, file_, diagnostics_, {"color", "depth"});
    if (auto color = r.numbers<4>("color")) c.color = glm::vec4((*color)[0], (*color)[1], (*color)[2], (*color)[3]);
    c.depth = r.number("depth");
    if (c.depth && (*c.depth < 0 || *c.depth > 1)) r.error("attribute 'depth' must lie in [0, 1]");
    if (!r.has("color") && !r.has("depth")) r.error("<clear> needs 'color', 'depth' or both");
    noChildren(e);
}

namespace {

std::initializer_list<std::pair<const char*, BlendFactor>> blendFactors() {
    static const std::initializer_list<std::pair<const char*, BlendFactor>> list = {
        {"zero", BlendFactor::Zero}, {"one", BlendFactor::One}, {"src-color", BlendFactor::SrcColor},
        {"one-minus-src-color", BlendFactor::OneMinusSrcColor}, {"dst-color", BlendFactor::DstColor},
        {"one-minus-dst-color", BlendFactor::OneMinusDstColor}, {"src-alpha", BlendFactor::SrcAlpha},
        {"one-minus-src-alpha", BlendFactor::OneMinusSrcAlpha}, {"dst-alpha", BlendFactor::DstAlpha},
        {"one-minus-dst-alpha", BlendFactor::OneMinusDstAlpha}, {"constant", BlendFactor::ConstantColor},
        {"one-minus-constant", BlendFactor::OneMinusConstantColor}, {"src-alpha-saturate", BlendFactor::SrcAlphaSaturate}};
    return list;
}

}  // namespace

void PassChildParser::parseBlend(const XMLElement* e, BlendState& b) {
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

void PassChildParser::parseDepth(const XMLElement* e, DepthState& d) {
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

void PassChildParser::parsePolygonMode(const XMLElement* e, RasterState& s) {
    ElementReader r(e, file_, diagnostics_, {"front", "back", "line-width"});
    std::initializer_list<std::pair<const char*, PolygonMode>> modes = {
        {"fill", PolygonMode::Fill}, {"line", PolygonMode::Line}, {"point", PolygonMode::Point}};
    s.frontMode = r.choice<PolygonMode>("front", modes).value_or(PolygonMode::Fill);
    s.backMode = r.choice<PolygonMode>("back", modes).value_or(s.frontMode);
    if (auto width = r.number("line-width")) {
        if (*width >= 1.0f && *width <= 64.0f) s.lineWidth = *width;
        else r.error("line-width must be from 1 to 64 pixels");
    }
    s.polygonModeWhere = r.where();
    noChildren(e);
}

void PassChildParser::parseCull(const XMLElement* e, RasterState& s) {
    ElementReader r(e, file_, diagnostics_, {"face", "front"});
    s.cull = r.choice<CullFace>("face", {{"none", CullFace::None}, {"back", CullFace::Back},
                                         {"front", CullFace::Front}})
                 .value_or(CullFace::Back);
    s.frontCounterClockwise = r.choice<bool>("front", {{"ccw", true}, {"cw", false}}).value_or(true);
    noChildren(e);
}

std::optional<ShaderSource> PassChildParser::parseShader(const XMLElement* e) {
    ElementReader r(e, file_, diagnostics_, {"stage", "file", "dialect", "entry", "profile", "matrices"});
    ShaderSource s;
    s.where = r.where();
    s.dialect = r.choice<ShaderDialect>("dialect", {{"glsl450", ShaderDialect::Glsl},
                                                    {"glsl110", ShaderDialect::GlslLegacy},
                                                    {"glsles100", ShaderDialect::GlslEs100},
                                                    {"hlsl", ShaderDialect::Hlsl}})
                    .value_or(ShaderDialect::Glsl);
    s.entryPoint = r.string("entry").value_or("");
    s.profile = r.string("profile").value_or("");
    s.matrixOrder = r.choice<HlslMatrixOrder>("matrices", {{hlslMatrixOrderName(HlslMatrixOrder::RowVector), HlslMatrixOrder::RowVector},
                                                           {hlslMatrixOrderName(HlslMatrixOrder::ColumnVector), HlslMatrixOrder::ColumnVector}})
                        .value_or(HlslMatrixOrder::RowVector);
    if (s.dialect != ShaderDialect::Hlsl && (r.has("entry") || r.has("profile")))
        r.error("attributes 'entry' and 'profile' apply to dialect=\"hlsl\"");
    if (s.dialect != ShaderDialect::Hlsl && r.has("matrices")) r.error("attribute 'matrices' applies to dialect=\"hlsl\"");
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
std::optional<VertexStream> PassChildParser::parseStream(const XMLElement* e) {
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

std::optional<Sampler> PassChildParser::parseSampler(const XMLElement* e) {
    ElementReader r(e, file_, diagnostics_,
                    {"name", "texture", "target", "frame", "filter", "mipmap", "wrap", "wrap-s", "wrap-t", "wrap-r", "border"});
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
    s.wrapR = r.choice<Wrap>("wrap-r", wraps).value_or(both);
    if (auto b = r.numbers<4>("border")) s.border = {(*b)[0], (*b)[1], (*b)[2], (*b)[3]};
    noChildren(e);
    if (!name || (!texture && !target)) return std::nullopt;
    s.uniform = *name;
    return s;
}

void PassChildParser::parseDraw(const XMLElement* e, DrawCall& d) {
    ElementReader r(e, file_, diagnostics_, {"mesh", "file", "translate", "rotate", "scale"});
    d.where = r.where();
    auto mesh = r.string("mesh");
    auto file = r.string("file");
    if (mesh && file) r.error("give either 'mesh' (built-in) or 'file' (a model), not both");
    if (!mesh && !file) r.error("missing attribute 'mesh' (fullscreen, cube, sphere, plane, teapot) or 'file'");
    if (mesh) {
        d.mesh = builtinMeshFromName(*mesh);
        if (!d.mesh)
            r.error("attribute 'mesh': unknown mesh '" + *mesh + "' (expected " + builtinMeshNameList() + ")");
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

}  // namespace rmfx::workspace_detail
