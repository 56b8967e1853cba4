#include "bench/accuracy/StageIdeal.h"

#include <cstdio>
#include <optional>

#include "reference/IdealBloom.h"
#include "reference/IdealLuminance.h"
#include "reference/IdealStreak.h"
#include "reference/IdealToneMap.h"
#include "reference/StageInput.h"

namespace rmfx::accuracy {
namespace {

class Parameters {
public:
    Parameters(const Workspace& ws, IdealKind kind) : ws_(ws), kind_(kind) {}

    double get(const char* name) {
        const Variable* v = ws_.findVariable(name);
        if (v && v->value.type == ValueType::Float) return v->value.asFloat();
        if (missing_.empty())
            missing_ = ws_.path.string() + ": the " + idealKindName(kind_) + " ideal reads float variable '" + name +
                       "', which the workspace " + (v ? "declares with another type" : "does not declare");
        return 0.0;
    }
    const std::string& missing() const { return missing_; }

private:
    const Workspace& ws_;
    IdealKind kind_;
    std::string missing_;
};

std::string exactText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

}  // namespace

Result<StageIdeal> computeStageIdeal(IdealKind kind, const Workspace& ws, const Image& input) {
    StageIdeal ideal;
    ideal.kind = kind;
    ideal.sanitisedInput = test::sanitisedInput(input);
    const test::RefImage& s = ideal.sanitisedInput;
    Parameters p(ws, kind);
    switch (kind) {
        case IdealKind::Bloom: {
            test::BloomParameters b{p.get("Bloom_Threshold"), p.get("Bloom_Strength"), p.get("Bloom_Sigma")};
            if (p.missing().empty()) ideal.image = test::idealBloom(s, b);
            break;
        }
        case IdealKind::Streak: {
            test::StreakParameters k{p.get("Streak_Threshold"), p.get("Streak_Strength"), p.get("Streak_Length")};
            if (p.missing().empty()) ideal.image = test::idealStreak(s, k);
            break;
        }
        case IdealKind::Luminance:
            ideal.logAverage = test::idealLuminance(s, p.get("Luminance_Delta")).logAverage;
            break;
        case IdealKind::ToneMap: {
            test::ToneMapParameters t;
            t.sceneLuminance = test::idealLuminance(s).logAverage;
            t.middleGray = p.get("Middle_Gray");
            t.whitePoint = p.get("White_Point");
            t.exposure = p.get("Exposure");
            p.get("Scene_Luminance");
            if (!p.missing().empty()) break;
            ideal.logAverage = t.sceneLuminance;
            ideal.image = test::toneMapDisplay(s, t);
            ideal.settings = {{"Scene_Luminance", exactText(t.sceneLuminance)}};
            break;
        }
    }
    if (!p.missing().empty()) return Error{p.missing()};
    return ideal;
}

Result<ErrorMetrics> stageMetrics(const StageIdeal& ideal, const Image& output) {
    const test::RefImage& s = ideal.sanitisedInput;
    if (ideal.kind == IdealKind::Luminance) {
        if (output.empty()) return Error{"the luminance output is empty"};
        return luminanceStageMetrics(output.at(0, 0, 0), ideal.logAverage, s);
    }
    if (output.width != s.width || output.height != s.height)
        return Error{"the output is " + std::to_string(output.width) + "x" + std::to_string(output.height) +
                     ", the input " + std::to_string(s.width) + "x" + std::to_string(s.height) +
                     ": the stage's output must have the input's size"};
    test::RefImage actual = test::fromImage(output);
    if (ideal.kind == IdealKind::ToneMap) return toneMapStageMetrics(actual, ideal.image);
    return imageStageMetrics(actual, ideal.image);
}

}  // namespace rmfx::accuracy
