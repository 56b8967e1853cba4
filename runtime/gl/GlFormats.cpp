#include "gl/GlFormats.h"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>

namespace rmfx::gl {

unsigned internalFormat(TargetFormat format) {
    switch (format) {
        case TargetFormat::RGBA8: return GL_RGBA8;
        case TargetFormat::RGBA16F: return GL_RGBA16F;
        case TargetFormat::RGBA32F: return GL_RGBA32F;
        case TargetFormat::R16F: return GL_R16F;
        case TargetFormat::R32F: return GL_R32F;
        case TargetFormat::RG16F: return GL_RG16F;
        case TargetFormat::RG32F: return GL_RG32F;
        case TargetFormat::RGBA16: return GL_RGBA16;
        case TargetFormat::R11G11B10F: return GL_R11F_G11F_B10F;
        case TargetFormat::RGB10A2: return GL_RGB10_A2;
        case TargetFormat::R8: return GL_R8;
        case TargetFormat::RG8: return GL_RG8;
        case TargetFormat::RG16: return GL_RG16;
    }
    return GL_RGBA16F;
}

int channelCount(TargetFormat format) {
    switch (format) {
        case TargetFormat::R16F:
        case TargetFormat::R32F:
        case TargetFormat::R8: return 1;
        case TargetFormat::RG16F:
        case TargetFormat::RG32F:
        case TargetFormat::RG8:
        case TargetFormat::RG16: return 2;
        case TargetFormat::R11G11B10F: return 3;
        default: return 4;
    }
}

unsigned blendFactor(BlendFactor factor) {
    switch (factor) {
        case BlendFactor::Zero: return GL_ZERO;
        case BlendFactor::One: return GL_ONE;
        case BlendFactor::SrcColor: return GL_SRC_COLOR;
        case BlendFactor::OneMinusSrcColor: return GL_ONE_MINUS_SRC_COLOR;
        case BlendFactor::DstColor: return GL_DST_COLOR;
        case BlendFactor::OneMinusDstColor: return GL_ONE_MINUS_DST_COLOR;
        case BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
        case BlendFactor::OneMinusSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstAlpha: return GL_DST_ALPHA;
        case BlendFactor::OneMinusDstAlpha: return GL_ONE_MINUS_DST_ALPHA;
        case BlendFactor::ConstantColor: return GL_CONSTANT_COLOR;
        case BlendFactor::OneMinusConstantColor: return GL_ONE_MINUS_CONSTANT_COLOR;
        case BlendFactor::SrcAlphaSaturate: return GL_SRC_ALPHA_SATURATE;
    }
    return GL_ONE;
}

unsigned blendEquation(BlendOp op) {
    switch (op) {
        case BlendOp::Add: return GL_FUNC_ADD;
        case BlendOp::Subtract: return GL_FUNC_SUBTRACT;
        case BlendOp::ReverseSubtract: return GL_FUNC_REVERSE_SUBTRACT;
        case BlendOp::Min: return GL_MIN;
        case BlendOp::Max: return GL_MAX;
    }
    return GL_FUNC_ADD;
}

unsigned compareFunc(CompareFunc func) {
    switch (func) {
        case CompareFunc::Never: return GL_NEVER;
        case CompareFunc::Less: return GL_LESS;
        case CompareFunc::Equal: return GL_EQUAL;
        case CompareFunc::LessEqual: return GL_LEQUAL;
        case CompareFunc::Greater: return GL_GREATER;
        case CompareFunc::NotEqual: return GL_NOTEQUAL;
        case CompareFunc::GreaterEqual: return GL_GEQUAL;
        case CompareFunc::Always: return GL_ALWAYS;
    }
    return GL_LESS;
}

unsigned wrapMode(Wrap wrap) {
    switch (wrap) {
        case Wrap::Repeat: return GL_REPEAT;
        case Wrap::Clamp: return GL_CLAMP_TO_EDGE;
        case Wrap::Mirror: return GL_MIRRORED_REPEAT;
        case Wrap::Border: return GL_CLAMP_TO_BORDER;
    }
    return GL_CLAMP_TO_EDGE;
}

unsigned minFilter(Filter filter, MipmapMode mipmap) {
    bool linear = filter == Filter::Linear;
    switch (mipmap) {
        case MipmapMode::None: return linear ? GL_LINEAR : GL_NEAREST;
        case MipmapMode::Nearest: return linear ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
        case MipmapMode::Linear: return linear ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
    }
    return GL_LINEAR;
}

unsigned magFilter(Filter filter) { return filter == Filter::Linear ? GL_LINEAR : GL_NEAREST; }

int mipLevels(int width, int height) {
    return 1 + static_cast<int>(std::floor(std::log2(std::max(width, height))));
}

}  // namespace rmfx::gl
