#pragma once
// The enumerations of ReShade FX's texture, sampler and pass states, and one table per enumeration
// that both reads a name (case-insensitively, as ReShade does) and lists the valid names for a
// message.
//
//   reshadeTextureFormats().find("rgba16f") → int(ReshadeTextureFormat::RGBA16F)
//   reshadeBlendOps().list() → "ADD, SUBTRACT, REVSUBTRACT, MIN, MAX"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace rmfx {

enum class ReshadeTextureFormat { R8, R16, R16F, R32I, R32U, R32F, RG8, RG16, RG16F, RG32F, RGBA8, RGBA16, RGBA16F, RGBA32F, RGB10A2 };
enum class ReshadeAddressMode { Clamp, Wrap, Mirror, Border };
enum class ReshadeFilter { Point, Linear, Anisotropic };
enum class ReshadeBlendOp { Add, Subtract, RevSubtract, Min, Max };
enum class ReshadeBlendFactor {
    Zero, One, SrcColor, InvSrcColor, SrcAlpha, InvSrcAlpha, DestAlpha, InvDestAlpha, DestColor, InvDestColor
};
enum class ReshadeStencilOp { Keep, Zero, Replace, IncrSat, DecrSat, Invert, Incr, Decr };
enum class ReshadeCompareFunc { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };
enum class ReshadePrimitiveTopology { PointList, LineList, LineStrip, TriangleList, TriangleStrip };

struct ReshadeEnumName {
    std::string_view name;  // upper case
    int value;
    bool alias = false;     // another spelling: read, not listed
};

class ReshadeEnum {
public:
    constexpr ReshadeEnum(std::string_view what, std::span<const ReshadeEnumName> names) : what_(what), names_(names) {}
    // The value of `name`, compared without case; nullopt when it names none.
    std::optional<int> find(std::string_view name) const;
    // The first name of `value` ("" when none).
    std::string_view nameOf(int value) const;
    // Every name but the aliases, ", " between them.
    std::string list() const;
    std::string_view what() const { return what_; }  // "texture format", "blend operation", …

private:
    std::string_view what_;
    std::span<const ReshadeEnumName> names_;
};

const ReshadeEnum& reshadeTextureFormats();
const ReshadeEnum& reshadeAddressModes();
const ReshadeEnum& reshadeFilters();
const ReshadeEnum& reshadeBlendOps();
const ReshadeEnum& reshadeBlendFactors();
const ReshadeEnum& reshadeStencilOps();
const ReshadeEnum& reshadeCompareFuncs();
const ReshadeEnum& reshadePrimitiveTopologies();

}  // namespace rmfx
