#include "model/Workspace.h"

#include <cmath>

#include <glm/vec2.hpp>

namespace rmfx {

template <class T>
static auto* findByName(T& items, std::string_view name) {
    for (auto& item : items)
        if (item.name == name) return &item;
    return static_cast<decltype(&items[0])>(nullptr);
}

const char* hlslMatrixOrderName(HlslMatrixOrder order) {
    return order == HlslMatrixOrder::ColumnVector ? "column-vector" : "row-vector";
}

std::optional<HlslMatrixOrder> parseHlslMatrixOrder(std::string_view name) {
    for (HlslMatrixOrder order : {HlslMatrixOrder::RowVector, HlslMatrixOrder::ColumnVector})
        if (name == hlslMatrixOrderName(order)) return order;
    return std::nullopt;
}

const char* textureSpaceName(TextureSpace space) {
    switch (space) {
        case TextureSpace::Direct3D9: return "direct3d9";
        case TextureSpace::Direct3D10: return "direct3d10";
        case TextureSpace::OpenGL: break;
    }
    return "opengl";
}

std::optional<TextureSpace> parseTextureSpace(std::string_view name) {
    for (TextureSpace space : {TextureSpace::OpenGL, TextureSpace::Direct3D9, TextureSpace::Direct3D10})
        if (name == textureSpaceName(space)) return space;
    return std::nullopt;
}

const Variable* Workspace::findVariable(std::string_view name) const { return findByName(variables, name); }
Variable* Workspace::findVariable(std::string_view name) { return findByName(variables, name); }
const Texture* Workspace::findTexture(std::string_view name) const { return findByName(textures, name); }
Texture* Workspace::findTexture(std::string_view name) { return findByName(textures, name); }
const ImageInput* Workspace::findInput(std::string_view name) const { return findByName(inputs, name); }
const RenderTarget* Workspace::findTarget(std::string_view name) const { return findByName(targets, name); }
const Pass* Workspace::findPass(std::string_view name) const { return findByName(passes, name); }

const Effect* Workspace::findEffect(std::string_view name) const {
    for (const Effect& e : effects)
        if (e.name == name) return &e;
    return nullptr;
}

bool Effect::hasPass(std::string_view passName) const {
    for (const std::string& p : passes)
        if (p == passName) return true;
    return false;
}

const Effect* Workspace::effectOfPass(std::string_view passName) const {
    for (const Effect& e : effects)
        if (e.hasPass(passName)) return &e;
    return nullptr;
}

std::string Workspace::outputTargetName() const {
    return output.target.empty() ? std::string(implicitOutputName) : output.target;
}

std::string Workspace::passTargetName(const Pass& pass) const {
    return pass.target.empty() ? outputTargetName() : pass.target;
}

bool Workspace::canReadTarget(std::string_view name) const { return findTarget(name) || name == outputTargetName(); }

std::string Workspace::describeTargets() const {
    std::string known;
    for (const RenderTarget& t : targets) known += (known.empty() ? "" : ", ") + t.name;
    return "it has: " + (known.empty() ? std::string("none") : known) + "; the output is '" + outputTargetName() + "'";
}

namespace {
struct FormatInfo {
    TargetFormat format;
    const char* name;
    int bytes;
};
constexpr FormatInfo formats[] = {
    {TargetFormat::RGBA8, "rgba8", 4},         {TargetFormat::RGBA16F, "rgba16f", 8},
    {TargetFormat::RGBA32F, "rgba32f", 16},    {TargetFormat::R16F, "r16f", 2},
    {TargetFormat::R32F, "r32f", 4},           {TargetFormat::RG16F, "rg16f", 4},
    {TargetFormat::RG32F, "rg32f", 8},         {TargetFormat::RGBA16, "rgba16", 8},
    {TargetFormat::R11G11B10F, "r11g11b10f", 4}, {TargetFormat::RGB10A2, "rgb10a2", 4},
    {TargetFormat::R8, "r8", 1},               {TargetFormat::RG8, "rg8", 2},
    {TargetFormat::RG16, "rg16", 4},
};
}  // namespace

const char* targetFormatName(TargetFormat format) {
    for (const auto& f : formats)
        if (f.format == format) return f.name;
    return "?";
}

std::optional<TargetFormat> targetFormatFromName(std::string_view name) {
    for (const auto& f : formats)
        if (name == f.name) return f.format;
    return std::nullopt;
}

int targetFormatBytesPerPixel(TargetFormat format) {
    for (const auto& f : formats)
        if (f.format == format) return f.bytes;
    return 0;
}

namespace {

// format-by / scale-by: without a variable, the fixed choice; else the choice the variable's int
// value indexes, or nullopt when it indexes none.
template <typename T>
std::optional<T> pickChoice(const std::string& variable, const T& fixed, const std::vector<T>& choices,
                            const Value* value) {
    if (variable.empty()) return fixed;
    if (!value || value->type != ValueType::Int) return std::nullopt;
    int index = value->asInt();
    if (index < 0 || index >= static_cast<int>(choices.size())) return std::nullopt;
    return choices[static_cast<size_t>(index)];
}

std::string choiceError(const std::string& variable, const Value* value, size_t choices, const std::string& noun,
                        const std::string& target) {
    return "variable '" + variable + "' = " + (value ? std::to_string(value->asInt()) : "?") + " picks none of the " +
           std::to_string(choices) + " " + noun + " of target '" + target + "'";
}

}  // namespace

std::optional<TargetFormat> selectTargetFormat(const RenderTarget& target, const Value* value) {
    return pickChoice(target.formatVariable, target.format, target.formats, value);
}

std::string formatChoiceError(const RenderTarget& target, const Value* value) {
    return choiceError(target.formatVariable, value, target.formats.size(), "formats", target.name);
}

std::optional<TargetSize> selectTargetSize(const RenderTarget& target, const Value* value) {
    return pickChoice(target.scaleVariable, target.size, target.scales, value);
}

std::string scaleChoiceError(const RenderTarget& target, const Value* value) {
    return choiceError(target.scaleVariable, value, target.scales.size(), "scales", target.name);
}

glm::ivec2 resolveTargetSize(const TargetSize& size, glm::ivec2 viewport) {
    if (!size.relative) return {size.width, size.height};
    // The small epsilon keeps exact products (256 × 0.25) from rounding up through float noise.
    auto scaled = [](int extent, double scale) {
        return std::max(1, static_cast<int>(std::ceil(extent * scale - 1e-9)));
    };
    return {scaled(viewport.x, size.scaleX), scaled(viewport.y, size.scaleY)};
}

}  // namespace rmfx
