#pragma once
// The initial values HLSL globals are declared with (`float4 Tint = float4(1, 0.5, 0, 1);`, also
// inside a cbuffer). In Direct3D 9 they are the constants' defaults, which hold until the
// application sets the constant; glslang's HLSL front end drops them, so the translator reads
// them from the source and gives them back as GLSL uniform initializers.

#include <string>
#include <vector>

#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {

struct HlslGlobalInitializer {
    std::string name;
    std::string declaredType;    // as written: "float4", "half", "float4x4"…
    bool array = false;          // declared with [N]
    bool constant = false;       // the initializer is made of numbers: arithmetic fxc folded, constructors, brace lists
    std::vector<double> values;  // its values, flattened: float4(1, 2, 3, 4), {1, 2, 3, 4} and {2 * 0.5, …} alike
    int line = 0;                // 1-based line of the name in the scanned code
};

// Every non-static, non-const variable declared with an initializer at global scope or directly
// in a cbuffer/tbuffer. Comments, strings and preprocessor lines are skipped; function bodies and
// struct declarations are not looked into.
std::vector<HlslGlobalInitializer> findHlslGlobalInitializers(const std::string& code);
// The same over code already blanked (the lines are those of the code it was blanked from).
std::vector<HlslGlobalInitializer> findHlslGlobalInitializers(const BlankedHlsl& code);

}  // namespace rmfx
