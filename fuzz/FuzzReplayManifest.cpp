// Fuzz target "replay_manifest": the bytes as a replay manifest (docs/replay.md), parsed as
// `rmfx replay` parses it. Properties of an accepted manifest: every case has a compare and is
// found by its name.

#include "frontend/replay/ReplayManifest.h"
#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"

namespace rmfx::fuzz {

void fuzzReplayManifest(const std::uint8_t* data, std::size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    const std::filesystem::path& folder = freshScratchFolder();
    Result<ReplayManifest> parsed = parseReplayManifestText(text, folder / "manifest.xml", folder);
    formatAll(parsed.diagnostics());
    fuzzCheck(parsed.ok() == !hasErrors(parsed.diagnostics()),
              "the parser returned a manifest together with errors, or neither");
    if (!parsed) return;
    for (const ReplayCase& c : parsed->cases) {
        fuzzCheck(!c.compares.empty(), "case '" + c.name + "' has no compare");
        fuzzCheck(parsed->findCase(c.name) == &c, "case '" + c.name + "' is not found by its name");
        c.overrides();
        for (const ReplayCompare& compare : c.compares) compare.label();
    }
}

}  // namespace rmfx::fuzz
