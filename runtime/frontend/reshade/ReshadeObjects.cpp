// ReshadeParserRun's textures, samplers and storages: a semantic or annotations, then a block of
// properties, each value a name from its enumeration or a constant.
#include "frontend/reshade/ReshadeParserRun.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace rmfx {
namespace {

using DK = ReshadeDeclaration::Kind;

std::string upper(std::string text) {
    for (char& ch : text) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return text;
}

int clampToInt(double v) {
    if (std::isnan(v)) return 0;
    return static_cast<int>(std::max(-2147483648.0, std::min(2147483647.0, std::trunc(v))));
}

}  // namespace

template <class F>
void ReshadeParserRun::parseProperties(const std::string& element, F property) {
    if (!c_.expect("{", element)) return;
    while (!c_.atEnd() && !c_.is("}")) {
        const size_t before = c_.position();
        const SourceLocation where = c_.here();
        std::optional<std::string> name = c_.expectIdentifier(element, "a property name");
        if (name && c_.expect("=", element) && property(*name, where)) {
            if (c_.accept(";")) {
                // the next property
            } else if (c_.is("}") || (c_.isKind(ReshadeToken::Kind::Identifier) && c_.is("=", 1))) {
                c_.expect(";", element);  // a missing ';': read on
            } else if (c_.isKind(ReshadeToken::Kind::Identifier) && startsDeclaration(c_.peekText()) &&
                       c_.peek().line != c_.previous().line) {
                c_.expect(";", element);  // the block ends unclosed before the next declaration
                return;
            } else {
                c_.error(c_.here(), element, *name + ": unexpected " + c_.describe(c_.peek()) + " after the value");
                skipUntil(";");
                c_.accept(";");
            }
        } else {
            skipUntil(";");
            c_.accept(";");
        }
        if (c_.position() == before) c_.next();
    }
    c_.expect("}", element);
}

void ReshadeParserRun::parseTexture(ReshadeType type, const std::string& name, const SourceLocation& where) {
    ReshadeTexture t;
    t.name = name;
    t.where = where;
    const std::string element = "texture " + name;
    parseArraySize(type, element);
    if (type.arrayLength != 0) c_.error(where, element, "a texture cannot be an array");
    t.type = type;
    if (c_.accept(":")) {
        if (std::optional<std::string> semantic = c_.expectIdentifier(element, "a semantic (COLOR or DEPTH)")) t.semantic = upper(*semantic);
    } else {
        t.annotations = parseAnnotations(element);
        if (c_.is("{")) {
            auto size = [&](const std::string& property, int& into) {
                const SourceLocation at = c_.here();
                std::optional<ReshadeValue> v = readStateValue(nullptr, property, element);
                if (!v) return;
                into = clampToInt(v->at());
                if (into < 1) {
                    c_.warning(at, element, property + " is " + std::to_string(into) + "; 1 is used");
                    into = 1;
                }
            };
            parseProperties(element, [&](const std::string& property, const SourceLocation& at) {
                if (property == "Width") size(property, t.width);
                else if (property == "Height") size(property, t.height);
                else if (property == "Depth") size(property, t.depth);
                else if (property == "MipLevels") size(property, t.mipLevels);
                else if (property == "Format") {
                    if (std::optional<ReshadeValue> v = readStateValue(&reshadeTextureFormats(), property, element))
                        t.format = static_cast<ReshadeTextureFormat>(static_cast<int>(v->at()));
                } else {
                    c_.error(at, element, "unknown texture property '" + property + "' (expected Width, Height, Depth, MipLevels, Format)");
                    return false;
                }
                return true;
            });
        }
    }
    const size_t index = effect_.textures.size();
    if (!declare(name, {DK::Texture, index, where}, element)) return;
    effect_.textures.push_back(std::move(t));
    addDeclaration(DK::Texture, index);
}

bool ReshadeParserRun::openBoundObject(ReshadeType& type, const std::string& kind, const SourceLocation& where,
                                       const std::string& element, ReshadeAnnotations& annotations) {
    parseArraySize(type, element);
    if (type.arrayLength != 0) c_.error(where, element, "a " + kind + " cannot be an array");
    annotations = parseAnnotations(element);
    if (!c_.is("{")) {
        c_.error(c_.here(), element, "expected '{' and the " + kind + "'s properties, found " + c_.describe(c_.peek()));
        return false;
    }
    return true;
}

template <class T>
void ReshadeParserRun::declareBoundObject(std::vector<T>& list, T object, DK kind, bool hasTexture, const std::string& element) {
    const std::string noun = kind == DK::Sampler ? "sampler" : "storage";
    if (!hasTexture) c_.error(object.where, element, "the " + noun + " has no 'Texture' property");
    const size_t index = list.size();
    const std::string name = object.name;
    if (!declare(name, {kind, index, object.where}, element)) return;
    list.push_back(std::move(object));
    addDeclaration(kind, index);
}

void ReshadeParserRun::parseSampler(ReshadeType type, const std::string& name, const SourceLocation& where) {
    ReshadeSampler s;
    s.name = name;
    s.where = where;
    const std::string element = "sampler " + name;
    if (!openBoundObject(type, "sampler", where, element, s.annotations)) return;
    s.type = type;
    bool hasTexture = false;
    auto number = [&](const std::string& property, float& into) {
        if (std::optional<ReshadeValue> v = readStateValue(nullptr, property, element)) into = static_cast<float>(v->at());
    };
    auto filter = [&](const std::string& property, ReshadeFilter& into) {
        if (std::optional<ReshadeValue> v = readStateValue(&reshadeFilters(), property, element))
            into = static_cast<ReshadeFilter>(static_cast<int>(v->at()));
    };
    parseProperties(element, [&](const std::string& property, const SourceLocation& at) {
        if (property == "Texture") {
            hasTexture = true;
            if (std::optional<std::string> texture = readTextureName(element)) s.texture = *texture;
        } else if (property == "AddressU" || property == "AddressV" || property == "AddressW") {
            if (std::optional<ReshadeValue> v = readStateValue(&reshadeAddressModes(), property, element))
                s.address[static_cast<size_t>(property.back() - 'U')] = static_cast<ReshadeAddressMode>(static_cast<int>(v->at()));
        } else if (property == "MagFilter") filter(property, s.magFilter);
        else if (property == "MinFilter") filter(property, s.minFilter);
        else if (property == "MipFilter") filter(property, s.mipFilter);
        else if (property == "MinLOD" || property == "MaxMipLevel") number(property, s.minLod);
        else if (property == "MaxLOD") number(property, s.maxLod);
        else if (property == "MipLODBias" || property == "MipMapLodBias") number(property, s.mipLodBias);
        else if (property == "SRGBTexture" || property == "SRGBReadEnable") {
            if (std::optional<ReshadeValue> v = readStateValue(nullptr, property, element)) s.srgb = v->at() != 0;
        } else {
            c_.error(at, element,
                     "unknown sampler property '" + property +
                         "' (expected Texture, AddressU, AddressV, AddressW, MagFilter, MinFilter, MipFilter, MinLOD, MaxLOD, "
                         "MipLODBias, SRGBTexture)");
            return false;
        }
        return true;
    });
    declareBoundObject(effect_.samplers, std::move(s), DK::Sampler, hasTexture, element);
}

void ReshadeParserRun::parseStorage(ReshadeType type, const std::string& name, const SourceLocation& where) {
    ReshadeStorage s;
    s.name = name;
    s.where = where;
    const std::string element = "storage " + name;
    ReshadeAnnotations ignored;  // a storage has no use for them
    if (!openBoundObject(type, "storage", where, element, ignored)) return;
    s.type = type;
    bool hasTexture = false;
    parseProperties(element, [&](const std::string& property, const SourceLocation& at) {
        if (property == "Texture") {
            hasTexture = true;
            if (std::optional<std::string> texture = readTextureName(element)) s.texture = *texture;
        } else if (property == "MipLevel" || property == "MipLOD") {
            if (std::optional<ReshadeValue> v = readStateValue(nullptr, property, element)) s.mipLevel = std::max(0, clampToInt(v->at()));
        } else {
            c_.error(at, element, "unknown storage property '" + property + "' (expected Texture, MipLevel)");
            return false;
        }
        return true;
    });
    declareBoundObject(effect_.storages, std::move(s), DK::Storage, hasTexture, element);
}

}  // namespace rmfx
