#include "frontend/rfx/detail/RfxDeclarations.h"

#include <string_view>

#include "frontend/rfx/detail/RfxD3dFormat.h"

namespace rmfx::rfx {
namespace {

using tinyxml2::XMLElement;

// NAME, VARIABLE_SEMANTIC and ARTIST_EDITABLE, common to every variable element.
Variable variableHead(const RfxElement& e) {
    Variable v;
    v.name = e.text("NAME").value_or("");
    v.semantic = e.text("VARIABLE_SEMANTIC", false).value_or("");
    v.editable = e.flag("ARTIST_EDITABLE", false).value_or(false);
    v.where = e.where();
    return v;
}

void readRange(const RfxElement& e, Variable& v) {
    if (e.has("MIN")) v.min = e.number("MIN");
    if (e.has("MAX")) v.max = e.number("MAX");
}

// VALUE_0 … VALUE_{count-1}.
bool readIndexedValues(const RfxElement& e, Value& value, int count) {
    bool ok = true;
    for (int i = 0; i < count; ++i) {
        std::string attribute = "VALUE_" + std::to_string(i);
        auto n = e.number(attribute.c_str());
        if (n) value.data[i] = *n;
        ok = ok && n.has_value();
    }
    return ok;
}

std::optional<Variable> readDynamic(const RfxElement& e) {
    Variable v = variableHead(e);
    readRange(e, v);
    auto kind = e.text("VARIABLE_TYPE");
    auto rows = e.integer("ROWS", 1, 4);
    auto columns = e.integer("COLUMNS", 1, 4);
    if (!kind || !rows || !columns) return std::nullopt;
    int r = static_cast<int>(*rows), c = static_cast<int>(*columns);
    std::optional<ValueType> type;
    if (*kind == "FLOAT") {
        int n = r * c;
        if (r == 1 || c == 1) type = n == 1 ? ValueType::Float : n == 2 ? ValueType::Vec2 : n == 3 ? ValueType::Vec3 : ValueType::Vec4;
        else if (r == 2 && c == 2) type = ValueType::Mat2;
        else if (r == 3 && c == 3) type = ValueType::Mat3;
        else if (r == 4 && c == 4) type = ValueType::Mat4;
    } else if (*kind == "INTEGER" || *kind == "BOOLEAN") {
        if (r == 1 && c == 1) type = *kind == "INTEGER" ? ValueType::Int : ValueType::Bool;
    } else {
        e.error("VARIABLE_TYPE '" + *kind + "' is not FLOAT, INTEGER or BOOLEAN");
        return std::nullopt;
    }
    if (!type) {
        e.error(*kind + " " + std::to_string(r) + "x" + std::to_string(c) +
                " has no rmfx type (floats: 1xN vectors, 2x2, 3x3, 4x4 matrices; integers and booleans: 1x1)");
        return std::nullopt;
    }
    v.value.type = *type;
    const XMLElement* container = e.xml()->FirstChildElement("RmDynamicVariableValueContainer");
    bool ok = true;
    for (const XMLElement* x = container ? container->FirstChildElement("RmDynamicVariableValue") : nullptr; x;
         x = x->NextSiblingElement("RmDynamicVariableValue")) {
        RfxElement item(x, e.file(), e.diagnostics());
        auto row = item.integer("ROW_INDEX", 0, r - 1);
        auto column = item.integer("COLUMN_INDEX", 0, c - 1);
        auto n = item.number("VALUE");
        if (!row || !column || !n) {
            ok = false;
            continue;
        }
        // Column-major, as GL uploads matrices; vectors are a single row or column either way.
        v.value.data[*column * r + *row] = *n;
    }
    if (!ok) return std::nullopt;
    return v;
}

std::optional<Variable> readVariable(const RfxElement& e, std::string_view tag) {
    Variable v = variableHead(e);
    if (tag == "RmFloatVariable") {
        auto n = e.number("VALUE");
        if (!n) return std::nullopt;
        v.value = Value::ofFloat(*n);
        readRange(e, v);
    } else if (tag == "RmIntegerVariable") {
        auto n = e.integer("VALUE", -(1 << 24), 1 << 24);
        if (!n) return std::nullopt;
        v.value = Value::ofInt(static_cast<int>(*n));
        readRange(e, v);
    } else if (tag == "RmBooleanVariable") {
        auto b = e.flag("VALUE");
        if (!b) return std::nullopt;
        v.value = Value::ofBool(*b);
    } else if (tag == "RmVectorVariable" || tag == "RmColorVariable") {
        v.value.type = tag == "RmVectorVariable" ? ValueType::Vec4 : ValueType::Color4;
        if (!readIndexedValues(e, v.value, 4)) return std::nullopt;
        if (tag == "RmVectorVariable") readRange(e, v);
    } else if (tag == "RmMatrixVariable") {
        // VALUE_0…15 in file order; VALUE_0…3 become the first column of the GLSL mat4.
        v.value.type = ValueType::Mat4;
        if (!readIndexedValues(e, v.value, 16)) return std::nullopt;
    } else {
        return readDynamic(e);
    }
    return v;
}

std::optional<RenderTarget> readRenderableTexture(const RfxElement& e) {
    RenderTarget t;
    t.name = e.text("NAME").value_or("");
    t.where = e.where();
    auto number = e.integer("FORMAT", -2147483648LL, 4294967295LL);
    if (!number) return std::nullopt;
    auto format = d3dFormat(*number);
    if (!format) {
        e.error("FORMAT " + std::to_string(*number) +
                " is not a Direct3D 9 format rmfx can render to (21 A8R8G8B8, 34 G16R16, 36 A16B16G16R16, 111 R16F, "
                "112 G16R16F, 113 A16B16G16R16F, 114 R32F, 115 G32R32F, 116 A32B32G32R32F, …)");
        return std::nullopt;
    }
    t.format = format->format;
    auto viewport = e.flag("USE_VIEWPORT_DIMENSIONS", false).value_or(false);
    if (viewport) {
        auto wr = e.number("WIDTH_RATIO"), hr = e.number("HEIGHT_RATIO");
        if (!wr || !hr) return std::nullopt;
        if (*wr <= 0 || *hr <= 0 || *wr > 16 || *hr > 16) {
            e.error("WIDTH_RATIO and HEIGHT_RATIO must be in (0, 16]");
            return std::nullopt;
        }
        t.size.relative = true;
        t.size.scaleX = *wr;
        t.size.scaleY = *hr;
    } else {
        auto w = e.integer("WIDTH", 1, 16384), h = e.integer("HEIGHT", 1, 16384);
        if (!w || !h) return std::nullopt;
        t.size.relative = false;
        t.size.width = static_cast<int>(*w);
        t.size.height = static_cast<int>(*h);
    }
    t.mipmaps = e.flag("GENERATE_MIPMAPS", false).value_or(false);
    return t;
}

std::optional<VertexUsage> streamUsage(long long d3dUsage) {
    switch (d3dUsage) {  // D3DDECLUSAGE
        case 0: return VertexUsage::Position;
        case 3: return VertexUsage::Normal;
        case 5: return VertexUsage::TexCoord;
        case 6: return VertexUsage::Tangent;
        case 7: return VertexUsage::Binormal;
        case 10: return VertexUsage::Color;
        default: return std::nullopt;
    }
}

StreamMapDeclaration readStreamMap(const RfxElement& e) {
    StreamMapDeclaration map;
    map.name = e.name();
    map.where = e.where();
    for (const XMLElement* s = e.xml()->FirstChildElement("RmStream"); s; s = s->NextSiblingElement("RmStream"))
        for (const XMLElement* c = s->FirstChildElement("RmStreamChannel"); c; c = c->NextSiblingElement("RmStreamChannel")) {
            RfxElement channel(c, e.file(), e.diagnostics());
            auto usage = channel.integer("USAGE", 0, 13);
            auto index = channel.integer("USAGE_INDEX", 0, 15);
            if (!usage || !index) continue;
            auto u = streamUsage(*usage);
            if (!u) {
                channel.warning("USAGE " + std::to_string(*usage) +
                                " (blend weights, indices, point size…) has no vertex data in rmfx's meshes; the channel is left out");
                continue;
            }
            map.streams.push_back({*u, static_cast<int>(*index), channel.text("ATTRIBUTE_NAME", false).value_or(""),
                                   true, channel.where()});
            map.registers.push_back(static_cast<int>(channel.integer("REGISTER", 0, 255, false).value_or(-1)));
        }
    return map;
}

}  // namespace

bool readDeclaration(const RfxElement& e, Declarations& into) {
    std::string tag = e.tag();
    if (tag == "RmFloatVariable" || tag == "RmIntegerVariable" || tag == "RmBooleanVariable" ||
        tag == "RmVectorVariable" || tag == "RmColorVariable" || tag == "RmMatrixVariable" ||
        tag == "RmDynamicVariable") {
        if (auto v = readVariable(e, tag)) into.variables.push_back(std::move(*v));
        return true;
    }
    if (tag == "Rm2DTextureVariable" || tag == "RmCubemapVariable" || tag == "Rm3DTextureVariable") {
        Texture t;
        t.name = e.text("NAME").value_or("");
        t.kind = tag == "RmCubemapVariable"     ? TextureKind::Cube
                 : tag == "Rm3DTextureVariable" ? TextureKind::Volume
                                                : TextureKind::Texture2D;
        // ORIGIN: the 41 textures of the 12 public files that have it (2026-11) all hold 0, read as
        // every image file is, its first row at the top; what another value did is not known.
        if (auto origin = e.integer("ORIGIN", -2147483648LL, 2147483647LL, false); origin && *origin != 0)
            e.warning("ORIGIN " + std::to_string(*origin) + " is not applied: the image is read with its first row at the "
                      "top, as for ORIGIN 0, the only value public RenderMonkey files hold");
        // One file: a cube map comes as one DDS holding the six faces, a volume as a DDS volume.
        if (auto file = e.text("FILE_NAME")) {
            t.files.push_back(*file);
            t.fileLocations.push_back(e.where());
        }
        t.where = e.where();
        into.textures.push_back(std::move(t));
        return true;
    }
    if (tag == "RmRenderableTexture") {
        if (auto t = readRenderableTexture(e)) into.targets.push_back(std::move(*t));
        return true;
    }
    if (tag == "RmStreamMap") {
        into.streamMaps.push_back(readStreamMap(e));
        return true;
    }
    if (tag == "RmModelData") {
        into.models.push_back({e.name(), e.text("FILE_NAME").value_or(""), e.where()});
        if (auto orientation = e.integer("ORIENTATION", -2147483648LL, 2147483647LL, false); orientation && *orientation != 0)
            e.warning("ORIENTATION " + std::to_string(*orientation) +
                      " is not applied: the model is drawn as the file holds it (RenderMonkey does not document the values)");
        return true;
    }
    if (tag == "RmLightVariable" || tag == "RmMaterialVariable") {
        e.warning("rmfx has no " + std::string(tag == "RmLightVariable" ? "light variables" : "material variables") +
                  "; a pass that uses it cannot be imported");
        into.unsupported.push_back({e.name(), tag == "RmLightVariable" ? "a light variable" : "a material variable", e.where()});
        return true;
    }
    return tag == "RmStringVariable";  // notes and metadata: nothing to run
}

}  // namespace rmfx::rfx
