#include "frontend/rfx/detail/RfxSamplerStates.h"

#include "core/Value.h"
#include "frontend/rfx/detail/RfxPackedColor.h"
#include "frontend/rfx/detail/RfxRenderStates.h"

namespace rmfx::rfx {
namespace {

constexpr long long kUInt32Max = 4294967295LL;

void badValue(const RfxElement& state, long long value, const char* what) {
    state.error("VALUE " + std::to_string(value) + " is not " + what);
}

}  // namespace

SamplerStates::SamplerStates(bool direct3d, bool hasMipmaps) : hasMipmaps_(hasMipmaps) {
    default_ = direct3d ? Filter::Nearest : Filter::Linear;
    mip_ = !direct3d && hasMipmaps ? MipmapMode::Linear : MipmapMode::None;
}

void SamplerStates::wrap(const RfxElement& state, int axis, long long value, bool direct3d) {
    std::optional<Wrap> w;
    if (direct3d) {
        switch (value) {
            case 1: w = Wrap::Repeat; break;
            case 2: w = Wrap::Mirror; break;
            case 3: w = Wrap::Clamp; break;
            case 4: w = Wrap::Border; break;
            case 5:
                state.warning("D3DTADDRESS_MIRRORONCE is sampled as mirrored repeat (rmfx has no mirror-once)");
                w = Wrap::Mirror;
                break;
            default: return badValue(state, value, "a D3DTEXTUREADDRESS (1 wrap … 5 mirror once)");
        }
    } else {
        switch (value) {
            case 1:  // GL_CLAMP mixes in the border colour at the edge; clamp-to-edge is the near thing
            case 2: w = Wrap::Clamp; break;
            case 3: w = Wrap::Repeat; break;
            case 4: w = Wrap::Border; break;
            case 5: w = Wrap::Mirror; break;
            default: return badValue(state, value, "a texture wrap (1 GL_CLAMP … 5 GL_MIRRORED_REPEAT)");
        }
    }
    wrap_[axis] = *w;
}

void SamplerStates::applyGl(const RfxElement& state) {
    std::string name = state.name();
    auto value = stateValue(state, name == "GL_TextureMaxAnisotropyEXT" || name == "GL_TextureLODBias");
    if (!value) return;
    long long v = *value;
    if (name == "GL_TextureWrapS") return wrap(state, 0, v, false);
    if (name == "GL_TextureWrapT") return wrap(state, 1, v, false);
    if (name == "GL_TextureWrapR") return wrap(state, 2, v, false);
    if (name == "GL_TextureMagnify") {
        if (v == 0 || v == 1) mag_ = v == 0 ? Filter::Nearest : Filter::Linear;
        else badValue(state, v, "a magnify filter (0 GL_NEAREST, 1 GL_LINEAR)");
        return;
    }
    if (name == "GL_TextureMinify") {
        switch (v) {
            case 0: min_ = Filter::Nearest; mip_ = MipmapMode::None; break;
            case 1: min_ = Filter::Linear; mip_ = MipmapMode::None; break;
            case 3: min_ = Filter::Nearest; mip_ = MipmapMode::Nearest; mipExplicit_ = true; break;
            case 4: min_ = Filter::Nearest; mip_ = MipmapMode::Linear; mipExplicit_ = true; break;
            case 5: min_ = Filter::Linear; mip_ = MipmapMode::Nearest; mipExplicit_ = true; break;
            case 6: min_ = Filter::Linear; mip_ = MipmapMode::Linear; mipExplicit_ = true; break;
            default: badValue(state, v, "a minify filter (0, 1, 3…6)");
        }
        return;
    }
    if (name == "GL_TextureBorderColor") {
        border_ = unpackArgb(v);
        return;
    }
    if (name == "GL_TextureMaxAnisotropyEXT" || name == "GL_TextureLODBias") {
        state.warning("sampler state " + name + " = " + formatValue(Value::ofFloat(floatFromBits(v))) +
                      " has no equivalent in rmfx's sampler model; ignored");
        return;
    }
    state.warning("unknown OpenGL sampler state '" + name + "'; ignored");
}

void SamplerStates::applyD3d(const RfxElement& state) {
    auto number = state.integer("STATE", 0, kUInt32Max);
    if (!number) return;
    auto value = stateValue(state, *number == 8);  // D3DSAMP_MIPMAPLODBIAS holds a float
    if (!value) return;
    long long v = *value;
    auto filter = [&](std::optional<Filter>& into) {
        switch (v) {
            case 1: into = Filter::Nearest; break;
            case 2: into = Filter::Linear; break;
            case 3:
                state.warning("D3DTEXF_ANISOTROPIC is sampled as linear (rmfx samplers have no anisotropy)");
                into = Filter::Linear;
                break;
            default: badValue(state, v, "a D3DTEXTUREFILTERTYPE rmfx supports (1 point, 2 linear, 3 anisotropic)");
        }
    };
    switch (*number) {
        case 1: return wrap(state, 0, v, true);  // D3DSAMP_ADDRESSU
        case 2: return wrap(state, 1, v, true);  // D3DSAMP_ADDRESSV
        case 3: return wrap(state, 2, v, true);  // D3DSAMP_ADDRESSW
        case 4: border_ = unpackArgb(v); return;  // D3DSAMP_BORDERCOLOR
        case 5: return filter(mag_);              // D3DSAMP_MAGFILTER
        case 6: return filter(min_);              // D3DSAMP_MINFILTER
        case 7:                                   // D3DSAMP_MIPFILTER
            if (v == 0) mip_ = MipmapMode::None;
            else if (v == 1) mip_ = MipmapMode::Nearest, mipExplicit_ = true;
            else if (v == 2) mip_ = MipmapMode::Linear, mipExplicit_ = true;
            else if (v == 3) {
                state.warning("D3DTEXF_ANISOTROPIC as the mip filter is sampled as linear (rmfx samplers have no anisotropy)");
                mip_ = MipmapMode::Linear, mipExplicit_ = true;
            } else badValue(state, v, "a mip filter (0 none, 1 point, 2 linear, 3 anisotropic)");
            return;
        case 8:  // D3DSAMP_MIPMAPLODBIAS, a float
            state.warning("sampler state D3DSAMP_MIPMAPLODBIAS = " + formatValue(Value::ofFloat(floatFromBits(v))) +
                          " has no equivalent in rmfx's sampler model; ignored");
            return;
        default:
            state.warning("sampler state " + std::to_string(*number) + " = " + std::to_string(v) +
                          " has no equivalent in rmfx's sampler model; ignored");
    }
}

void SamplerStates::finish(const RfxElement& textureObject, Sampler& sampler) const {
    sampler.wrapS = wrap_[0];
    sampler.wrapT = wrap_[1];
    sampler.wrapR = wrap_[2];
    sampler.border = border_;
    sampler.filter = mag_ ? *mag_ : min_ ? *min_ : default_;
    if (min_ && mag_ && *min_ != *mag_)
        textureObject.warning("minify and magnify filters differ; rmfx samplers have one filter: the magnify one is used");
    sampler.mipmap = hasMipmaps_ ? mip_ : MipmapMode::None;
    if (!hasMipmaps_ && mipExplicit_ && mip_ != MipmapMode::None)
        textureObject.warning("it asks for mipmap filtering of a render target without GENERATE_MIPMAPS; sampled without mipmaps");
}

}  // namespace rmfx::rfx
