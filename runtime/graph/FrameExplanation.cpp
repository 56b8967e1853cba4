#include "graph/FrameExplanation.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "model/EffectSelection.h"

namespace rmfx {
namespace {

// Columns padded to the widest cell; the last column is not padded.
std::string table(const std::vector<std::vector<std::string>>& rows) {
    std::vector<size_t> width;
    for (const auto& row : rows)
        for (size_t c = 0; c < row.size(); ++c) {
            if (width.size() <= c) width.push_back(0);
            width[c] = std::max(width[c], row[c].size());
        }
    std::string out;
    for (const auto& row : rows) {
        std::string line = " ";
        for (size_t c = 0; c < row.size(); ++c) {
            line += " " + row[c];
            if (c + 1 < row.size()) line += std::string(width[c] - row[c].size(), ' ');
        }
        out += line + "\n";
    }
    return out;
}

}  // namespace

std::string formatBytes(std::size_t bytes) {
    char buffer[32];
    if (bytes < 1024) return std::to_string(bytes) + " B";
    if (bytes < 1024 * 1024) std::snprintf(buffer, sizeof buffer, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
    else std::snprintf(buffer, sizeof buffer, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return buffer;
}

std::string explainFrame(const FrameExplanationInput& in) {
    const Workspace& ws = *in.ws;
    const PassGraph& graph = *in.graph;
    const TargetPlan& plan = *in.plan;
    std::ostringstream out;
    std::set<std::string> declared;
    for (const Effect& e : ws.effects) declared.insert(e.name);
    std::string outputs;
    for (const std::string& o : graph.outputs) outputs += (outputs.empty() ? "'" : ", '") + o + "'";
    out << ws.name << ": outputs " << outputs;
    if (!declared.empty())
        out << "; effects asked for: " << joinNames(in.askedEffects) << " (declared: " << joinNames(declared)
            << "); switched off: " << joinNames(in.switchedOffEffects);
    out << "\n\n";

    if (!ws.inputs.empty()) {
        out << "inputs:\n";
        std::vector<std::vector<std::string>> rows;
        for (const ImageInput& input : ws.inputs) {
            const Texture* texture = ws.findTexture(input.name);
            std::string what;
            const auto given = in.inputFiles.find(input.name);
            if (given != in.inputFiles.end()) {
                what = given->second;
                if (texture && texture->supplied)
                    what += " (" + std::to_string(texture->supplied->width) + "x" + std::to_string(texture->supplied->height) + ")";
            } else if (!input.replaces.empty()) {
                what = "no image given: the workspace draws target '" + input.replaces + "' itself";
            } else if (texture && !texture->files.empty()) {
                what = "no image given: its file " + texture->files.front();
            } else {
                what = "no image given";
            }
            rows.push_back({input.name, what});
            if (given != in.inputFiles.end() && !input.replaces.empty())
                rows.back().push_back("in place of target '" + input.replaces + "'");
        }
        out << table(rows) << "\n";
    }

    out << "passes: " << graph.schedule.size() << " of " << graph.nodes.size() << " run\n";
    std::vector<std::vector<std::string>> rows{{"#", "pass", "writes", "effect", "status", "why"}};
    for (size_t i = 0; i < graph.nodes.size(); ++i) {
        const PassNode& n = graph.nodes[i];
        std::string why = n.why;
        if (!n.skippedInputs.empty()) {
            std::string skipped;
            for (const std::string& t : n.skippedInputs) skipped += (skipped.empty() ? "'" : ", '") + t + "'";
            why += "; skips " + skipped + " (effect off)";
        }
        rows.push_back({std::to_string(i + 1), n.pass->name, n.target, n.effect ? n.effect->name : "-",
                        passFateName(n.fate), why});
    }
    out << table(rows) << "\n";

    size_t used = 0;
    for (const PlannedTarget& t : plan.targets) used += t.used ? 1 : 0;
    out << "targets: " << used << " of " << plan.targets.size() << " allocated, in " << plan.resources.size()
        << (plan.resources.size() == 1 ? " texture" : " textures") << (in.pooled ? "" : " (pooling off)") << "\n";
    auto passName = [&](int index) {
        return index >= static_cast<int>(ws.passes.size()) ? std::string("end of frame")
                                                           : ws.passes[static_cast<size_t>(index)].name;
    };
    rows = {{"target", "size", "format", "bytes", "lifetime", "memory"}};
    for (size_t i = 0; i < plan.targets.size(); ++i) {
        const PlannedTarget& t = plan.targets[i];
        std::string size = std::to_string(t.size.x) + "x" + std::to_string(t.size.y);
        if (!t.used) {
            rows.push_back({t.name, size, targetFormatName(t.format), "-", "-", "not allocated: no running pass uses it"});
            continue;
        }
        std::string memory = "#" + std::to_string(t.resource);
        const TargetResource& r = plan.resources[static_cast<size_t>(t.resource)];
        std::string others;
        for (int k : r.targets)
            if (k != static_cast<int>(i)) others += (others.empty() ? "" : ", ") + plan.targets[static_cast<size_t>(k)].name;
        if (!others.empty()) memory += " shared with " + others;
        if (t.history) memory += " (2 buffers: read with frame=\"previous\")";
        else if (t.carried) memory += " (own: kept from frame to frame)";
        std::string extras = std::string(t.mipmaps ? "+mips" : "") + (t.depth ? "+depth" : "");
        rows.push_back({t.name, size, std::string(targetFormatName(t.format)) + extras, formatBytes(t.bytes),
                        passName(t.firstUse) + " .. " + passName(t.lastUse), memory});
    }
    out << table(rows) << "\n";
    char percent[32];
    std::snprintf(percent, sizeof percent, "%.0f%%",
                  plan.declaredBytes ? 100.0 * static_cast<double>(plan.allocatedBytes) / static_cast<double>(plan.declaredBytes) : 0.0);
    out << "peak GPU memory of the frame: " << formatBytes(plan.allocatedBytes) << " (" << plan.allocatedBytes
        << " bytes) of " << formatBytes(plan.declaredBytes) << " (" << plan.declaredBytes
        << " bytes) for all declared targets: " << percent << "\n";

    // Effects with a source that ran this frame: skipped by content, or run because it held something.
    // (An effect whose passes the outputs do not need is culled, not skipped: the table above says so.)
    std::vector<std::string> sourced;
    for (const Effect& e : ws.effects) {
        const bool scheduled = std::any_of(graph.nodes.begin(), graph.nodes.end(),
                                           [&](const PassNode& n) { return n.effect && n.effect->name == e.name && n.fate == PassFate::Run; });
        if (!e.source.empty() && scheduled && in.askedEffects.count(e.name) && !in.switchedOffEffects.count(e.name))
            sourced.push_back(e.name);
    }
    if (!sourced.empty()) {
        out << (in.frameRan ? "\nskipped by content (the last frame):" : "\nskipped by content (decided on the GPU each frame; no frame ran):");
        if (!in.contentSkip) out << " nothing: --content-skip off";
        out << "\n";
        for (const std::string& name : sourced) {
            if (!in.contentSkip) break;
            const Effect& e = *ws.findEffect(name);
            auto skipped = in.contentSkipped.find(name);
            auto always = in.runningWhateverTheContent.find(name);
            if (always != in.runningWhateverTheContent.end())
                out << "  " << name << ": run whatever '" << e.source << "' holds: " << always->second << "\n";
            else if (!in.frameRan)
                out << "  " << name << ": skipped where "
                    << (e.gate.empty() ? "'" + e.source + "' holds no pixel it works on" : "its gate '" + e.gate + "' holds no non-zero pixel")
                    << "\n";
            else if (skipped != in.contentSkipped.end())
                out << "  " << name << ": skipped by content: " << skipped->second << "\n";
            else
                out << "  " << name << ": run: "
                    << (e.gate.empty() ? "'" + e.source + "' holds a pixel it works on" : "its gate '" + e.gate + "' holds a non-zero pixel")
                    << "\n";
        }
        for (const auto& [pass, effects] : in.drawnOnlyForEffects)
            if (in.contentSkip)
                out << "  " << pass << ": drawn only where " << joinNames(effects) << (effects.size() == 1 ? " runs" : " run") << " (only "
                    << (effects.size() == 1 ? "it reads" : "they read") << " what it writes)\n";
        for (const auto& [pass, effects] : in.drawnWithoutSkipped)
            if (in.contentSkip)
                out << "  " << pass << ": drawn compiled without " << joinNames(effects)
                    << (effects.size() == 1 ? " where it is skipped (it reads what it hands on)\n"
                                            : " where they are skipped (it reads what they hand on)\n");
    }
    return out.str();
}

}  // namespace rmfx
