#pragma once
// RmState elements of an RmTextureObject → the sampler's wrap, filter and border colour.
//
// OpenGL effects name the states (GL_TextureWrapS/T/R, GL_TextureMinify, GL_TextureMagnify,
// GL_TextureBorderColor, GL_TextureMaxAnisotropyEXT, GL_TextureLODBias) with RenderMonkey's
// enumerations: wraps 1 GL_CLAMP, 2 GL_CLAMP_TO_EDGE, 3 GL_REPEAT, 4 GL_CLAMP_TO_BORDER,
// 5 GL_MIRRORED_REPEAT; filters 0 NEAREST, 1 LINEAR, 3 NEAREST_MIPMAP_NEAREST,
// 4 NEAREST_MIPMAP_LINEAR, 5 LINEAR_MIPMAP_NEAREST, 6 LINEAR_MIPMAP_LINEAR. Direct3D effects use
// D3DSAMPLERSTATETYPE numbers in STATE with D3DTEXTUREADDRESS / D3DTEXTUREFILTERTYPE values.

#include <optional>
#include <vector>

#include "frontend/rfx/detail/RfxElement.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

// The states of one texture object, gathered before they are resolved: rmfx samplers have one
// filter for minifying and magnifying, so the two are reconciled at the end.
class SamplerStates {
public:
    // Defaults before any state: the API's own (OpenGL: repeat, linear with linear mipmaps when
    // the texture has mipmaps; Direct3D 9: wrap, point, no mipmaps).
    SamplerStates(bool direct3d, bool hasMipmaps);

    void applyGl(const RfxElement& state);
    void applyD3d(const RfxElement& state);
    // Writes the gathered states into the sampler; `where` is the texture object (for warnings).
    void finish(const RfxElement& textureObject, Sampler& sampler) const;

private:
    void wrap(const RfxElement& state, int axis, long long value, bool direct3d);
    Wrap wrap_[3] = {Wrap::Repeat, Wrap::Repeat, Wrap::Repeat};
    std::optional<Filter> min_, mag_;
    MipmapMode mip_ = MipmapMode::None;
    bool mipExplicit_ = false;  // set by a state, not a default
    glm::vec4 border_{0.0f};
    Filter default_ = Filter::Linear;
    bool hasMipmaps_ = true;
};

}  // namespace rmfx::rfx
