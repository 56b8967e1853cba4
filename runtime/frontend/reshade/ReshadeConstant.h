#pragma once
// Constant expressions of ReShade FX, computed as the parser reads them: texture sizes after macro
// expansion (`BUFFER_WIDTH / 2`, `1920 * 0.5`), annotation values (`"a" "b"`, `-1.0`,
// `float3(1, 0, 0)`), uniform initial values (`{1, 2, 3}`), pass states (`1 << 2`), and names of
// `static const` values.
//
//   readReshadeConstant(cursor over "(1920 / 2) * 1.0 + float2(1, 2).y", lookup, error)
//     → Float {962}
//
// What it computes: literals (decimal, hex, octal, float with suffixes, true / false (and TRUE /
// FALSE, as ReShade reads them), strings with
// their escapes, adjacent strings joined), `( )` (with the comma operator: `(1.5, 2)` is 2), `{ a, b }` (an array's elements in turn),
// constructors (`float3(…)`, `int(…)`), casts (`(int)x`), swizzles (`.xy`, `.rgba`), unary
// + - ! ~, binary * / % + - << >> < > <= >= == != & ^ | && ||, ?:, a few intrinsics (min, max,
// abs, clamp, saturate, floor, ceil, round, trunc, frac, sqrt, rcp, pow, exp, exp2, log, log2,
// sin, cos, tan, lerp, sign), and names through `lookup`. Ints are 32-bit, as in ReShade.
// Nesting is bounded (an error, never a deep recursion).

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "frontend/reshade/ReshadeCursor.h"
#include "frontend/reshade/ReshadeSyntax.h"

namespace rmfx {

// The value of a name as written ("Ns::Size", "Size"), or nullopt when it names no constant.
using ReshadeNameLookup = std::function<std::optional<ReshadeValue>(const std::string& name)>;

// Reads one constant expression at the cursor. Stops before a token that cannot continue it (';',
// ',', ')', …; with `stopAtGreater` also before '>' and '>=', for `CS<8, 8>` and annotations). On
// failure returns nullopt with `error` set ("'x' is not a constant", "division by zero", …).
std::optional<ReshadeValue> readReshadeConstant(ReshadeCursor& cursor, const ReshadeNameLookup& lookup, std::string& error,
                                                bool stopAtGreater = false);

// A numeric type's name: float, float3, float4x4, int2, uint, bool, half3, double, dword, … → its
// type (base, rows, cols); nullopt for any other name.
std::optional<ReshadeType> reshadeNumericType(std::string_view name);

// A string literal's text ("a\"b\0" with quotes) with its escapes resolved.
std::string decodeReshadeString(std::string_view literal);

// `value` as `kind`: floats truncate toward zero to ints, anything not zero is true.
ReshadeValue convertReshadeValue(const ReshadeValue& value, ReshadeValue::Kind kind);

}  // namespace rmfx
