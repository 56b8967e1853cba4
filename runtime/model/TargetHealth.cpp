#include "model/TargetHealth.h"

#include <cmath>

#include "core/ShortNumber.h"

namespace rmfx {

const char* healthKindName(HealthKind kind) {
    switch (kind) {
        case HealthKind::NaN: return "NaN";
        case HealthKind::PositiveInfinity: return "+Inf";
        case HealthKind::NegativeInfinity: return "-Inf";
        case HealthKind::Negative: return "negative values";
        case HealthKind::AtFormatMax: return "values at the format's largest";
    }
    return "";
}

bool healthKindIsError(HealthKind kind) {
    return kind == HealthKind::NaN || kind == HealthKind::PositiveInfinity || kind == HealthKind::NegativeInfinity;
}

const char* healthCheckMethodName(HealthCheckMethod method) {
    switch (method) {
        case HealthCheckMethod::Automatic: return "auto";
        case HealthCheckMethod::WhileDrawing: return "while-drawing";
        case HealthCheckMethod::AfterPass: return "after-pass";
    }
    return "auto";
}

std::optional<HealthCheckMethod> parseHealthCheckMethod(const std::string& name) {
    for (HealthCheckMethod m : {HealthCheckMethod::Automatic, HealthCheckMethod::WhileDrawing, HealthCheckMethod::AfterPass})
        if (name == healthCheckMethodName(m)) return m;
    return std::nullopt;
}

FormatHealthLimits formatHealthLimits(TargetFormat format) {
    const float half = 65504.0f;
    switch (format) {
        case TargetFormat::RGBA32F: return {true, 4, true, glm::vec4(0.0f)};
        case TargetFormat::RG32F: return {true, 2, true, glm::vec4(0.0f)};
        case TargetFormat::R32F: return {true, 1, true, glm::vec4(0.0f)};
        case TargetFormat::RGBA16F: return {true, 4, true, glm::vec4(half)};
        case TargetFormat::RG16F: return {true, 2, true, glm::vec4(half)};
        case TargetFormat::R16F: return {true, 1, true, glm::vec4(half)};
        case TargetFormat::R11G11B10F: return {true, 3, false, glm::vec4(65024.0f, 65024.0f, 64512.0f, 0.0f)};
        case TargetFormat::RGBA8:
        case TargetFormat::RGBA16:
        case TargetFormat::RGB10A2:
        case TargetFormat::R8:
        case TargetFormat::RG8:
        case TargetFormat::RG16: return {false, 4, false, glm::vec4(0.0f)};
    }
    return {};
}

namespace {

std::string number(float v) { return std::isnan(v) ? "nan" : shortNumber(v); }  // never "-nan"

std::string vector(glm::vec4 v) {
    return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ", " + number(v.w) + ")";
}

}  // namespace

std::string describeFinding(const HealthFinding& f) {
    std::string out = "pass '" + f.pass + "' wrote " + healthKindName(f.kind) + " into target '" + f.target + "' (" +
                      std::to_string(f.count) + (f.count == 1 ? " pixel" : " pixels") + "; first at x=" +
                      std::to_string(f.pixel.x) + " y=" + std::to_string(f.pixel.y);
    if (!f.recorded) return out + "; its value was not kept: more fragments lowered the first pixel than the check keeps)";
    out += ": " + vector(f.value);
    if (f.inputs.empty()) return out + "; the pass reads no 2D input)";
    out += "; there the inputs held:";
    for (size_t i = 0; i < f.inputs.size(); ++i)
        out += std::string(i == 0 ? " " : ", ") + f.inputs[i].first + " " + vector(f.inputs[i].second);
    return out + ")";
}

}  // namespace rmfx
