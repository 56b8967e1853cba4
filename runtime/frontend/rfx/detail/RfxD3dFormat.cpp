#include "frontend/rfx/detail/RfxD3dFormat.h"

namespace rmfx::rfx {
namespace {

// Formats without alpha or with fewer channels land on the nearest format holding every channel
// they have; luminance formats become red-only ones (shaders then read .r, not .rgb).
constexpr D3dFormat formats[] = {
    {20, "D3DFMT_R8G8B8", TargetFormat::RGBA8},
    {21, "D3DFMT_A8R8G8B8", TargetFormat::RGBA8},
    {22, "D3DFMT_X8R8G8B8", TargetFormat::RGBA8},
    {31, "D3DFMT_A2B10G10R10", TargetFormat::RGB10A2},
    {32, "D3DFMT_A8B8G8R8", TargetFormat::RGBA8},
    {33, "D3DFMT_X8B8G8R8", TargetFormat::RGBA8},
    {34, "D3DFMT_G16R16", TargetFormat::RG16},
    {35, "D3DFMT_A2R10G10B10", TargetFormat::RGB10A2},
    {36, "D3DFMT_A16B16G16R16", TargetFormat::RGBA16},
    {50, "D3DFMT_L8", TargetFormat::R8},
    {51, "D3DFMT_A8L8", TargetFormat::RG8},
    {111, "D3DFMT_R16F", TargetFormat::R16F},
    {112, "D3DFMT_G16R16F", TargetFormat::RG16F},
    {113, "D3DFMT_A16B16G16R16F", TargetFormat::RGBA16F},
    {114, "D3DFMT_R32F", TargetFormat::R32F},
    {115, "D3DFMT_G32R32F", TargetFormat::RG32F},
    {116, "D3DFMT_A32B32G32R32F", TargetFormat::RGBA32F},
};

}  // namespace

std::optional<D3dFormat> d3dFormat(long long number) {
    for (const D3dFormat& f : formats)
        if (f.number == number) return f;
    return std::nullopt;
}

}  // namespace rmfx::rfx
