#include "model/SemanticValues.h"

#include <cctype>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>

namespace rmfx {
namespace {

struct Entry {
    std::string name;
    UniformType type;
    std::string meaning;
    std::function<Value(const SemanticInputs&)> value;
};

Value scalar(double v) { return Value::ofFloat(static_cast<float>(v)); }

Value vector(ValueType type, std::initializer_list<double> components) {
    Value out;
    out.type = type;
    int i = 0;
    for (double c : components) out.data[static_cast<size_t>(i++)] = static_cast<float>(c);
    return out;
}

Value matrix(const glm::dmat4& m) {
    Value out;
    out.type = ValueType::Mat4;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row) out.data[static_cast<size_t>(column * 4 + row)] = static_cast<float>(m[column][row]);
    return out;
}

// The camera's frame in world space: columns of the inverse view matrix.
glm::dvec3 cameraAxis(const SemanticInputs& in, int column) { return glm::dvec3(glm::inverse(in.view)[column]); }

double cycled(const SemanticInputs& in) { return in.cyclePeriod > 0 ? std::fmod(in.time, in.cyclePeriod) : in.time; }

std::vector<Entry> buildTable() {
    std::vector<Entry> t;
    using In = const SemanticInputs&;
    // The six matrices and the four forms of each, as RenderMonkey names them.
    const std::pair<const char*, std::function<glm::dmat4(In)>> bases[] = {
        {"World", [](In in) { return in.world; }},
        {"View", [](In in) { return in.view; }},
        {"Projection", [](In in) { return in.projection; }},
        {"WorldView", [](In in) { return in.view * in.world; }},
        {"ViewProjection", [](In in) { return in.projection * in.view; }},
        {"WorldViewProjection", [](In in) { return in.projection * in.view * in.world; }},
    };
    for (const auto& [base, of] : bases) {
        auto m = of;
        t.push_back({base, UniformType::Mat4, "the " + std::string(base) + " matrix", [m](In in) { return matrix(m(in)); }});
        t.push_back({std::string(base) + "Inverse", UniformType::Mat4, "its inverse",
                     [m](In in) { return matrix(glm::inverse(m(in))); }});
        t.push_back({std::string(base) + "Transpose", UniformType::Mat4, "its transpose",
                     [m](In in) { return matrix(glm::transpose(m(in))); }});
        t.push_back({std::string(base) + "InverseTranspose", UniformType::Mat4, "the transpose of its inverse",
                     [m](In in) { return matrix(glm::transpose(glm::inverse(m(in)))); }});
    }
    auto vec4 = [](glm::dvec3 v, double w) { return vector(ValueType::Vec4, {v.x, v.y, v.z, w}); };
    t.push_back({"ViewPosition", UniformType::Vec4, "the camera position in world space (w = 1)",
                 [vec4](In in) { return vec4(cameraAxis(in, 3), 1.0); }});
    t.push_back({"ViewDirection", UniformType::Vec4, "the unit direction the camera looks along, world space (w = 0)",
                 [vec4](In in) { return vec4(glm::normalize(-cameraAxis(in, 2)), 0.0); }});
    t.push_back({"ViewSideVector", UniformType::Vec4, "the camera's unit right vector, world space (w = 0)",
                 [vec4](In in) { return vec4(glm::normalize(cameraAxis(in, 0)), 0.0); }});
    t.push_back({"ViewUpVector", UniformType::Vec4, "the camera's unit up vector, world space (w = 0)",
                 [vec4](In in) { return vec4(glm::normalize(cameraAxis(in, 1)), 0.0); }});
    t.push_back({"FOV", UniformType::Float, "the vertical field of view in radians", [](In in) { return scalar(in.fovYRadians); }});
    t.push_back({"NearClipPlane", UniformType::Float, "the near plane distance", [](In in) { return scalar(in.nearPlane); }});
    t.push_back({"FarClipPlane", UniformType::Float, "the far plane distance", [](In in) { return scalar(in.farPlane); }});

    // Time: X is seconds modulo the cycle period, 1 the fraction of the period, 2PI that times 2π.
    const double twoPi = 6.283185307179586;
    const std::pair<const char*, std::function<double(In)>> clocks[] = {
        {"0_X", [](In in) { return cycled(in); }},
        {"0_1", [](In in) { return in.cyclePeriod > 0 ? cycled(in) / in.cyclePeriod : 0.0; }},
        {"0_2PI", [twoPi](In in) { return in.cyclePeriod > 0 ? cycled(in) / in.cyclePeriod * twoPi : 0.0; }},
    };
    for (const auto& [suffix, of] : clocks) {
        auto c = of;
        std::string s = suffix;
        t.push_back({"Time" + s, UniformType::Float, "cycling time", [c](In in) { return scalar(c(in)); }});
        t.push_back({"SinTime" + s, UniformType::Float, "sin(Time" + s + ")", [c](In in) { return scalar(std::sin(c(in))); }});
        t.push_back({"CosTime" + s, UniformType::Float, "cos(Time" + s + ")", [c](In in) { return scalar(std::cos(c(in))); }});
        t.push_back({"TanTime" + s, UniformType::Float, "tan(Time" + s + ")", [c](In in) { return scalar(std::tan(c(in))); }});
        t.push_back({"Time" + s + "_Packed", UniformType::Vec4, "(Time" + s + ", sin, cos, tan)", [c](In in) {
                         double v = c(in);
                         return vector(ValueType::Vec4, {v, std::sin(v), std::cos(v), std::tan(v)});
                     }});
    }
    t.push_back({"TimeCyclePeriod", UniformType::Float, "the period Time0_X cycles over, seconds",
                 [](In in) { return scalar(in.cyclePeriod); }});
    t.push_back({"TimeElapsed", UniformType::Float, "seconds since the previous frame", [](In in) { return scalar(in.deltaTime); }});
    t.push_back({"FPS", UniformType::Float, "frames per second: 1 / TimeElapsed (0 on the first frame)",
                 [](In in) { return scalar(in.deltaTime > 0 ? 1.0 / in.deltaTime : 0.0); }});

    t.push_back({"ViewportWidth", UniformType::Float, "viewport width, pixels", [](In in) { return scalar(in.viewport.x); }});
    t.push_back({"ViewportHeight", UniformType::Float, "viewport height, pixels", [](In in) { return scalar(in.viewport.y); }});
    t.push_back({"ViewportWidthInverse", UniformType::Float, "1 / ViewportWidth", [](In in) { return scalar(1.0 / in.viewport.x); }});
    t.push_back({"ViewportHeightInverse", UniformType::Float, "1 / ViewportHeight",
                 [](In in) { return scalar(1.0 / in.viewport.y); }});
    t.push_back({"ViewportDimensions", UniformType::Vec2, "(width, height)",
                 [](In in) { return vector(ValueType::Vec2, {double(in.viewport.x), double(in.viewport.y)}); }});
    t.push_back({"ViewportDimensionsInverse", UniformType::Vec2, "(1 / width, 1 / height)",
                 [](In in) { return vector(ValueType::Vec2, {1.0 / in.viewport.x, 1.0 / in.viewport.y}); }});
    t.push_back({"InverseViewportDimensions", UniformType::Vec2, "(1 / width, 1 / height)",
                 [](In in) { return vector(ValueType::Vec2, {1.0 / in.viewport.x, 1.0 / in.viewport.y}); }});

    t.push_back({"PassIndex", UniformType::Float, "the pass's position in the pass list, from 0",
                 [](In in) { return scalar(in.passIndex); }});
    for (int k = 1; k <= 4; ++k) {
        std::string n = std::to_string(k);
        t.push_back({"RandomFraction" + n + "PerPass", UniformType::Float, "a number in [0, 1), new every pass and frame",
                     [k](In in) { return scalar(randomFraction(in.frame, in.passIndex, k)); }});
        t.push_back({"RandomFraction" + n + "PerEffect", UniformType::Float, "a number in [0, 1), new every frame",
                     [k](In in) { return scalar(randomFraction(in.frame, -1, k)); }});
    }

    // The mouse: 0 headless; the editor gives the cursor.
    auto ndcX = [](In in) { return in.mouse.x / in.viewport.x * 2.0 - 1.0; };
    auto ndcY = [](In in) { return 1.0 - in.mouse.y / in.viewport.y * 2.0; };
    t.push_back({"MouseCoordinateX", UniformType::Float, "cursor x, pixels from the left", [](In in) { return scalar(in.mouse.x); }});
    t.push_back({"MouseCoordinateY", UniformType::Float, "cursor y, pixels from the top", [](In in) { return scalar(in.mouse.y); }});
    t.push_back({"MouseCoordinateXY", UniformType::Vec2, "(MouseCoordinateX, MouseCoordinateY)",
                 [](In in) { return vector(ValueType::Vec2, {in.mouse.x, in.mouse.y}); }});
    t.push_back({"MouseCoordinateXNDC", UniformType::Float, "cursor x in [-1, 1]", [ndcX](In in) { return scalar(ndcX(in)); }});
    t.push_back({"MouseCoordinateYNDC", UniformType::Float, "cursor y in [-1, 1], up", [ndcY](In in) { return scalar(ndcY(in)); }});
    t.push_back({"MouseCoordinateXYNDC", UniformType::Vec2, "(MouseCoordinateXNDC, MouseCoordinateYNDC)",
                 [ndcX, ndcY](In in) { return vector(ValueType::Vec2, {ndcX(in), ndcY(in)}); }});
    t.push_back({"LeftMouseButton", UniformType::Float, "1 while held", [](In in) { return scalar(in.mouseButtons.x); }});
    t.push_back({"MiddleMouseButton", UniformType::Float, "1 while held", [](In in) { return scalar(in.mouseButtons.y); }});
    t.push_back({"RightMouseButton", UniformType::Float, "1 while held", [](In in) { return scalar(in.mouseButtons.z); }});
    return t;
}

const std::vector<Entry>& table() {
    static const std::vector<Entry> entries = buildTable();
    return entries;
}

const std::vector<SemanticInfo>& infos() {
    static const std::vector<SemanticInfo> list = [] {
        std::vector<SemanticInfo> out;
        for (size_t i = 0; i < table().size(); ++i) {
            const Entry& e = table()[i];
            out.push_back({static_cast<int>(i), e.name.c_str(), e.type, e.meaning.c_str()});
        }
        return out;
    }();
    return list;
}

bool equalIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

}  // namespace

std::span<const SemanticInfo> semanticVariables() { return infos(); }

std::optional<SemanticInfo> findSemantic(std::string_view name) {
    for (const SemanticInfo& s : infos())
        if (equalIgnoringCase(s.name, name)) return s;
    return std::nullopt;
}

bool semanticFeeds(const SemanticInfo& semantic, UniformType uniform) {
    if (semantic.type == UniformType::Mat4 || uniform == UniformType::Mat4) return semantic.type == uniform;
    if (semantic.type == UniformType::Float && (uniform == UniformType::Int || uniform == UniformType::Bool)) return true;
    int have = floatVectorWidth(semantic.type), want = floatVectorWidth(uniform);
    return want > 0 && want <= have && (want > 1) == (have > 1);
}

Value semanticValue(const SemanticInfo& semantic, const SemanticInputs& inputs) {
    return table()[static_cast<size_t>(semantic.id)].value(inputs);
}

double randomFraction(int frame, int pass, int k) {
    // splitmix64 of the three numbers: well mixed, and the same on every run.
    uint64_t x = (static_cast<uint64_t>(static_cast<uint32_t>(frame)) << 32) ^
                 (static_cast<uint64_t>(static_cast<uint32_t>(pass + 1)) << 8) ^ static_cast<uint64_t>(k);
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    return static_cast<double>(x >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace rmfx
