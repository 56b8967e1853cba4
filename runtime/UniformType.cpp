#include "runtime/UniformType.h"

#include <epoxy/gl.h>  // enum values only: nothing here calls GL

namespace rmfx {

UniformType uniformTypeFromGl(int glType) {
    switch (glType) {
        case GL_FLOAT: return UniformType::Float;
        case GL_INT: return UniformType::Int;
        case GL_UNSIGNED_INT: return UniformType::UInt;
        case GL_BOOL: return UniformType::Bool;
        case GL_FLOAT_VEC2: return UniformType::Vec2;
        case GL_FLOAT_VEC3: return UniformType::Vec3;
        case GL_FLOAT_VEC4: return UniformType::Vec4;
        case GL_INT_VEC2: return UniformType::IVec2;
        case GL_INT_VEC3: return UniformType::IVec3;
        case GL_INT_VEC4: return UniformType::IVec4;
        case GL_BOOL_VEC2: return UniformType::BVec2;
        case GL_BOOL_VEC3: return UniformType::BVec3;
        case GL_BOOL_VEC4: return UniformType::BVec4;
        case GL_FLOAT_MAT2: return UniformType::Mat2;
        case GL_FLOAT_MAT3: return UniformType::Mat3;
        case GL_FLOAT_MAT4: return UniformType::Mat4;
        case GL_SAMPLER_2D: return UniformType::Sampler2D;
        case GL_SAMPLER_CUBE: return UniformType::SamplerCube;
        case GL_SAMPLER_1D: case GL_SAMPLER_3D: case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_2D_ARRAY:
        case GL_SAMPLER_CUBE_SHADOW: case GL_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D:
        case GL_SAMPLER_2D_MULTISAMPLE: case GL_SAMPLER_BUFFER: case GL_SAMPLER_CUBE_MAP_ARRAY:
        case GL_INT_SAMPLER_CUBE: case GL_UNSIGNED_INT_SAMPLER_CUBE:
            return UniformType::OtherSampler;
        default: return UniformType::Other;
    }
}

const char* uniformTypeName(UniformType type) {
    switch (type) {
        case UniformType::Float: return "float";
        case UniformType::Int: return "int";
        case UniformType::UInt: return "uint";
        case UniformType::Bool: return "bool";
        case UniformType::Vec2: return "vec2";
        case UniformType::Vec3: return "vec3";
        case UniformType::Vec4: return "vec4";
        case UniformType::IVec2: return "ivec2";
        case UniformType::IVec3: return "ivec3";
        case UniformType::IVec4: return "ivec4";
        case UniformType::BVec2: return "bvec2";
        case UniformType::BVec3: return "bvec3";
        case UniformType::BVec4: return "bvec4";
        case UniformType::Mat2: return "mat2";
        case UniformType::Mat3: return "mat3";
        case UniformType::Mat4: return "mat4";
        case UniformType::Sampler2D: return "sampler2D";
        case UniformType::SamplerCube: return "samplerCube";
        case UniformType::OtherSampler: return "a sampler type rmfx does not bind";
        case UniformType::Other: return "a type rmfx does not bind";
    }
    return "?";
}

bool isSampler(UniformType type) {
    return type == UniformType::Sampler2D || type == UniformType::SamplerCube || type == UniformType::OtherSampler;
}

bool uniformAccepts(UniformType uniform, ValueType variable) {
    switch (variable) {
        case ValueType::Float: return uniform == UniformType::Float;
        case ValueType::Int: return uniform == UniformType::Int;
        case ValueType::Bool: return uniform == UniformType::Bool;
        case ValueType::Vec2: return uniform == UniformType::Vec2;
        case ValueType::Vec3:
        case ValueType::Color3: return uniform == UniformType::Vec3;
        case ValueType::Vec4:
        case ValueType::Color4: return uniform == UniformType::Vec4;
        case ValueType::Mat2: return uniform == UniformType::Mat2;
        case ValueType::Mat3: return uniform == UniformType::Mat3;
        case ValueType::Mat4: return uniform == UniformType::Mat4;
    }
    return false;
}

}  // namespace rmfx
