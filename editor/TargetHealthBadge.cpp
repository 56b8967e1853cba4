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
    // What each target holds at the end of the frame: the last writer's counts, and before it those
    // of the passes it drew over (PassHealth::ownPixelsOnly), back to one whose counts cover the
    // whole target. Their pixels may overlap, so the sum can count a pixel more than once.
    std::map<std::string, std::vector<const PassHealth*>> holding;
    for (const PassHealth& p : health.passes) {
        std::vector<const PassHealth*>& writers = holding[p.target];
        if (!p.ownPixelsOnly) writers.clear();
        writers.push_back(&p);
    }
    std::map<std::string, TargetHealthBadge> badges;
    for (const auto& [target, writers] : holding) {
        TargetHealthBadge& badge = badges[target];
        const PassHealth& last = *writers.back();
        badge.inspected = last.inspected;
        if (!last.inspected) {
            badge.details = "not inspected: its format clamps whatever a shader writes";
            continue;
        }
        for (HealthKind kind : allHealthKinds) {  // NaN and the infinities come first
            long long total = 0;
            for (const PassHealth* pass : writers) {
                const long long count = pass->counts[static_cast<size_t>(kind)];
                if (count == 0) continue;
                total += count;
                badge.details += (badge.details.empty() ? "" : "\n") + std::string(healthKindName(kind)) + ": " +
                                 std::to_string(count) + " pixels, written by pass '" + pass->pass + "'";
            }
            if (total == 0) continue;
            badge.text += (badge.text.empty() ? "" : " ") + std::string(shortName(kind)) + " " + std::to_string(total);
            badge.error = badge.error || healthKindIsError(kind);
        }
        if (badge.text.empty()) badge.details = "no NaN, infinity, negative value or value at its format's largest";
    }
    for (const HealthFinding& f : health.findings)
        if (auto it = badges.find(f.target); it != badges.end())
            it->second.details += "\nfirst in this frame: " + describeFinding(f);
    return badges;
}

}  // namespace rmfx::editor
