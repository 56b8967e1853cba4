#pragma once
// Which value feeds a uniform of a pass: a sampler of the pass, a pass constant, a workspace
// variable or a predefined value, looked up in that order. A constant or variable with a known
// semantic (Variable::semantic) is fed the semantic's value every frame.

#include <string>
#include <variant>

#include "model/PredefinedVariables.h"
#include "model/SemanticValues.h"
#include "model/Workspace.h"

namespace rmfx {

struct BoundSampler { const Sampler* sampler; int index; };
struct BoundConstant { const Variable* constant; };
struct BoundVariable { const Variable* variable; };
struct BoundPredefined { PredefinedInfo info; };
struct BoundSemantic { const Variable* variable; SemanticInfo info; };  // a pass constant or a variable
struct Unbound {};

using UniformSource = std::variant<Unbound, BoundSampler, BoundConstant, BoundVariable, BoundPredefined, BoundSemantic>;

UniformSource resolveUniform(const Workspace& ws, const Pass& pass, const std::string& name);

// Whether a uniform nothing feeds is left at zero rather than an error: in passes of HLSL shaders
// (RenderMonkey's Direct3D effects), as Direct3D ran a shader whatever its constant table held
// and a register nothing set was zero. Samplers are never left so.
bool unboundUniformIsZero(const Pass& pass, const UniformSource& source, UniformType type);

// Empty when the source can feed a uniform of that type; else why not, as a sentence naming both.
// In a pass of HLSL shaders a variable feeds a constant as RenderMonkey set Direct3D's registers:
// a float vector wider than the constant gives its first components (a float4 variable into a
// float2 constant: .xy), and an array constant takes the variable in its first element (the
// others stay zero).
std::string bindingMismatch(const Workspace& ws, const Pass& pass, const UniformSource& source, const std::string& uniform,
                            UniformType type, int arraySize);

}  // namespace rmfx
