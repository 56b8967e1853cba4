#include "frontend/reshade/ReshadeStates.h"

#include <array>
#include <cctype>

namespace rmfx {
namespace {

bool sameWithoutCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

template <class E>
constexpr ReshadeEnumName entry(std::string_view name, E value) {
    return {name, static_cast<int>(value), false};
}
template <class E>
constexpr ReshadeEnumName alias(std::string_view name, E value) {
    return {name, static_cast<int>(value), true};
}

using F = ReshadeTextureFormat;
constexpr std::array kFormats{
    entry("R8", F::R8), entry("R16", F::R16), entry("R16F", F::R16F), entry("R32I", F::R32I), entry("R32U", F::R32U),
    entry("R32F", F::R32F), entry("RG8", F::RG8), entry("RG16", F::RG16), entry("RG16F", F::RG16F),
    entry("RG32F", F::RG32F), entry("RGBA8", F::RGBA8), entry("RGBA16", F::RGBA16), entry("RGBA16F", F::RGBA16F),
    entry("RGBA32F", F::RGBA32F), entry("RGB10A2", F::RGB10A2),
    // ReShade's longer spellings
    alias("R8G8", F::RG8), alias("R16G16", F::RG16), alias("R16G16F", F::RG16F), alias("R32G32F", F::RG32F),
    alias("R8G8B8A8", F::RGBA8), alias("R16G16B16A16", F::RGBA16), alias("R16G16B16A16F", F::RGBA16F),
    alias("R32G32B32A32F", F::RGBA32F), alias("R10G10B10A2", F::RGB10A2)};

using A = ReshadeAddressMode;
constexpr std::array kAddress{entry("CLAMP", A::Clamp), entry("WRAP", A::Wrap), alias("REPEAT", A::Wrap),
                              entry("MIRROR", A::Mirror), entry("BORDER", A::Border)};

using Fi = ReshadeFilter;
constexpr std::array kFilters{entry("POINT", Fi::Point), entry("LINEAR", Fi::Linear), entry("ANISOTROPIC", Fi::Anisotropic),
                              alias("NONE", Fi::Point)};

using B = ReshadeBlendOp;
constexpr std::array kBlendOps{entry("ADD", B::Add), entry("SUBTRACT", B::Subtract), entry("REVSUBTRACT", B::RevSubtract),
                               entry("MIN", B::Min), entry("MAX", B::Max)};

using Bf = ReshadeBlendFactor;
constexpr std::array kBlendFactors{
    entry("ZERO", Bf::Zero), entry("ONE", Bf::One), entry("SRCCOLOR", Bf::SrcColor), entry("INVSRCCOLOR", Bf::InvSrcColor),
    entry("SRCALPHA", Bf::SrcAlpha), entry("INVSRCALPHA", Bf::InvSrcAlpha), entry("DESTALPHA", Bf::DestAlpha),
    entry("INVDESTALPHA", Bf::InvDestAlpha), entry("DESTCOLOR", Bf::DestColor), entry("INVDESTCOLOR", Bf::InvDestColor)};

using S = ReshadeStencilOp;
constexpr std::array kStencilOps{entry("KEEP", S::Keep),       entry("ZERO", S::Zero),       entry("REPLACE", S::Replace),
                                 entry("INCRSAT", S::IncrSat), entry("DECRSAT", S::DecrSat), entry("INVERT", S::Invert),
                                 entry("INCR", S::Incr),       entry("DECR", S::Decr)};

using C = ReshadeCompareFunc;
constexpr std::array kCompare{entry("NEVER", C::Never),         entry("LESS", C::Less),       entry("EQUAL", C::Equal),
                              entry("LEQUAL", C::LessEqual),    entry("GREATER", C::Greater), entry("NEQUAL", C::NotEqual),
                              entry("GEQUAL", C::GreaterEqual), entry("ALWAYS", C::Always),   alias("LESSEQUAL", C::LessEqual),
                              alias("NOTEQUAL", C::NotEqual),   alias("GREATEREQUAL", C::GreaterEqual)};

using T = ReshadePrimitiveTopology;
constexpr std::array kTopologies{entry("POINTLIST", T::PointList),       entry("LINELIST", T::LineList),
                                 entry("LINESTRIP", T::LineStrip),       entry("TRIANGLELIST", T::TriangleList),
                                 entry("TRIANGLESTRIP", T::TriangleStrip), alias("POINTS", T::PointList),
                                 alias("LINES", T::LineList),            alias("TRIANGLES", T::TriangleList)};

}  // namespace

std::optional<int> ReshadeEnum::find(std::string_view name) const {
    for (const ReshadeEnumName& n : names_)
        if (sameWithoutCase(n.name, name)) return n.value;
    return std::nullopt;
}

std::string_view ReshadeEnum::nameOf(int value) const {
    for (const ReshadeEnumName& n : names_)
        if (n.value == value) return n.name;
    return {};
}

std::string ReshadeEnum::list() const {
    std::string text;
    for (const ReshadeEnumName& n : names_) {
        if (n.alias) continue;
        if (!text.empty()) text += ", ";
        text += n.name;
    }
    return text;
}

const ReshadeEnum& reshadeTextureFormats() {
    static const ReshadeEnum table("texture format", kFormats);
    return table;
}
const ReshadeEnum& reshadeAddressModes() {
    static const ReshadeEnum table("address mode", kAddress);
    return table;
}
const ReshadeEnum& reshadeFilters() {
    static const ReshadeEnum table("filter", kFilters);
    return table;
}
const ReshadeEnum& reshadeBlendOps() {
    static const ReshadeEnum table("blend operation", kBlendOps);
    return table;
}
const ReshadeEnum& reshadeBlendFactors() {
    static const ReshadeEnum table("blend factor", kBlendFactors);
    return table;
}
const ReshadeEnum& reshadeStencilOps() {
    static const ReshadeEnum table("stencil operation", kStencilOps);
    return table;
}
const ReshadeEnum& reshadeCompareFuncs() {
    static const ReshadeEnum table("comparison function", kCompare);
    return table;
}
const ReshadeEnum& reshadePrimitiveTopologies() {
    static const ReshadeEnum table("primitive topology", kTopologies);
    return table;
}

}  // namespace rmfx
