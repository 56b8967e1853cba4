#include "editor/TargetHealthBadge.h"

namespace rmfx::editor {
namespace {

const char* shortName(HealthKind kind) {
    switch (kind) {
        case HealthKind::NaN: return "NaN";
        case HealthKind::PositiveInfinity: return "+Inf";
        case HealthKind::NegativeInfinity: return "-Inf";
        case HealthKind::Negative: return "neg";
        case HealthKind::AtFormatMax: return "max";
    }
    return "";
}

}  // namespace

std::map<std::string, TargetHealthBadge> targetHealthBadges(const FrameHealth& health) {
    std::map<std::string, const PassHealth*> lastWriter;
    for (const PassHealth& p : health.passes) lastWriter[p.target] = &p;
    std::map<std::string, TargetHealthBadge> badges;
    for (const auto& [target, pass] : lastWriter) {
        TargetHealthBadge& badge = badges[target];
        badge.inspected = pass->inspected;
        if (!pass->inspected) {
            badge.details = "not inspected: its format clamps whatever a shader writes";
            continue;
        }
        for (HealthKind kind : allHealthKinds) {  // NaN and the infinities come first
            const long long count = pass->counts[static_cast<size_t>(kind)];
            if (count == 0) continue;
            badge.text += (badge.text.empty() ? "" : " ") + std::string(shortName(kind)) + " " + std::to_string(count);
            badge.error = badge.error || healthKindIsError(kind);
            badge.details += (badge.details.empty() ? "" : "\n") + std::string(healthKindName(kind)) + ": " +
                             std::to_string(count) + " pixels, written by pass '" + pass->pass + "'";
        }
        if (badge.text.empty()) badge.details = "no NaN, infinity, negative value or value at its format's largest";
    }
    for (const HealthFinding& f : health.findings)
        if (auto it = badges.find(f.target); it != badges.end())
            it->second.details += "\nfirst in this frame: " + describeFinding(f);
    return badges;
}

}  // namespace rmfx::editor
