#pragma once
// GLSL uniform types as shader reflection (glslang or the GL driver) reports them.

#include <string>

#include "core/Value.h"

namespace rmfx {

enum class UniformType {
    Float, Int, UInt, Bool, Vec2, Vec3, Vec4, IVec2, IVec3, IVec4, BVec2, BVec3, BVec4,
    Mat2, Mat3, Mat4, Sampler2D, SamplerCube, Sampler3D, OtherSampler, Other
};

// From a GL type enum (GL_FLOAT_VEC3 …), which both glslang's reflection and glGetActiveUniform give.
UniformType uniformTypeFromGl(int glType);
const char* uniformTypeName(UniformType type);
bool isSampler(UniformType type);
// The floats of a float scalar or vector (1 to 4); 0 for any other type.
int floatVectorWidth(UniformType type);
// Whether a variable of this type may feed a uniform of that type.
bool uniformAccepts(UniformType uniform, ValueType variable);

}  // namespace rmfx
