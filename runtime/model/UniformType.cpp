#include "model/UniformType.h"

namespace rmfx {

namespace {
// The GL type enums (Khronos registry numbers) that glslang's reflection and glGetActiveUniform
// report: the model layer reads them without a GL header.
constexpr int kBool = 0x8B56;  // GL_BOOL
constexpr int kBoolVec2 = 0x8B57;  // GL_BOOL_VEC2
constexpr int kBoolVec3 = 0x8B58;  // GL_BOOL_VEC3
constexpr int kBoolVec4 = 0x8B59;  // GL_BOOL_VEC4
constexpr int kFloat = 0x1406;  // GL_FLOAT
constexpr int kFloatMat2 = 0x8B5A;  // GL_FLOAT_MAT2
constexpr int kFloatMat3 = 0x8B5B;  // GL_FLOAT_MAT3
constexpr int kFloatMat4 = 0x8B5C;  // GL_FLOAT_MAT4
constexpr int kFloatVec2 = 0x8B50;  // GL_FLOAT_VEC2
constexpr int kFloatVec3 = 0x8B51;  // GL_FLOAT_VEC3
constexpr int kFloatVec4 = 0x8B52;  // GL_FLOAT_VEC4
constexpr int kInt = 0x1404;  // GL_INT
constexpr int kIntSampler2d = 0x8DCA;  // GL_INT_SAMPLER_2D
constexpr int kIntSamplerCube = 0x8DCC;  // GL_INT_SAMPLER_CUBE
constexpr int kIntVec2 = 0x8B53;  // GL_INT_VEC2
constexpr int kIntVec3 = 0x8B54;  // GL_INT_VEC3
constexpr int kIntVec4 = 0x8B55;  // GL_INT_VEC4
constexpr int kSampler1d = 0x8B5D;  // GL_SAMPLER_1D
constexpr int kSampler2d = 0x8B5E;  // GL_SAMPLER_2D
constexpr int kSampler2dArray = 0x8DC1;  // GL_SAMPLER_2D_ARRAY
constexpr int kSampler2dMultisample = 0x9108;  // GL_SAMPLER_2D_MULTISAMPLE
constexpr int kSampler2dShadow = 0x8B62;  // GL_SAMPLER_2D_SHADOW
constexpr int kSampler3d = 0x8B5F;  // GL_SAMPLER_3D
constexpr int kSamplerBuffer = 0x8DC2;  // GL_SAMPLER_BUFFER
constexpr int kSamplerCube = 0x8B60;  // GL_SAMPLER_CUBE
constexpr int kSamplerCubeMapArray = 0x900C;  // GL_SAMPLER_CUBE_MAP_ARRAY
constexpr int kSamplerCubeShadow = 0x8DC5;  // GL_SAMPLER_CUBE_SHADOW
constexpr int kUnsignedInt = 0x1405;  // GL_UNSIGNED_INT
constexpr int kUnsignedIntSampler2d = 0x8DD2;  // GL_UNSIGNED_INT_SAMPLER_2D
constexpr int kUnsignedIntSamplerCube = 0x8DD4;  // GL_UNSIGNED_INT_SAMPLER_CUBE
}  // namespace

UniformType uniformTypeFromGl(int glType) {
    switch (glType) {
        case kFloat: return UniformType::Float;
        case kInt: return UniformType::Int;
        case kUnsignedInt: return UniformType::UInt;
        case kBool: return UniformType::Bool;
        case kFloatVec2: return UniformType::Vec2;
        case kFloatVec3: return UniformType::Vec3;
        case kFloatVec4: return UniformType::Vec4;
        case kIntVec2: return UniformType::IVec2;
        case kIntVec3: return UniformType::IVec3;
        case kIntVec4: return UniformType::IVec4;
        case kBoolVec2: return UniformType::BVec2;
        case kBoolVec3: return UniformType::BVec3;
        case kBoolVec4: return UniformType::BVec4;
        case kFloatMat2: return UniformType::Mat2;
        case kFloatMat3: return UniformType::Mat3;
        case kFloatMat4: return UniformType::Mat4;
        case kSampler2d: return UniformType::Sampler2D;
        case kSamplerCube: return UniformType::SamplerCube;
        case kSampler3d: return UniformType::Sampler3D;
        case kSampler1d: case kSampler2dShadow: case kSampler2dArray:
        case kSamplerCubeShadow: case kIntSampler2d: case kUnsignedIntSampler2d:
        case kSampler2dMultisample: case kSamplerBuffer: case kSamplerCubeMapArray:
        case kIntSamplerCube: case kUnsignedIntSamplerCube:
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
        case UniformType::Sampler3D: return "sampler3D";
        case UniformType::OtherSampler: return "a sampler type rmfx does not bind";
        case UniformType::Other: return "a type rmfx does not bind";
    }
    return "?";
}

bool isSampler(UniformType type) {
    return type == UniformType::Sampler2D || type == UniformType::SamplerCube || type == UniformType::Sampler3D ||
           type == UniformType::OtherSampler;
}

int floatVectorWidth(UniformType type) {
    switch (type) {
        case UniformType::Float: return 1;
        case UniformType::Vec2: return 2;
        case UniformType::Vec3: return 3;
        case UniformType::Vec4: return 4;
        default: return 0;
    }
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
