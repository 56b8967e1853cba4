#pragma once
// Replay manifests (docs/replay.md): the regression tests of `rmfx replay`. A manifest lists
// cases: a workspace rendered headless at a fixed size, frame count, time step and variable
// settings, and the images (the output, render targets) to compare with stored references.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "io/image/ImageCompare.h"
#include "io/media/MediaResolver.h"
#include "model/RunSettings.h"

namespace rmfx {

// <set name="Exposure_Level" value="0.5"/>: what `rmfx render --set` does.
struct ReplaySet {
    SourceLocation where;
    std::string name;
    std::string value;
};

// <input name="scene" file="shots/a.exr"/>: what `rmfx render --input scene=shots/a.exr` does, so
// that a case runs an effect on the user's own image. The name may be left out when the workspace
// has one input; "FILE.exr:layer" picks an EXR part or layer.
struct ReplayInput {
    SourceLocation where;
    std::string name;                // "" for the workspace's only input
    std::string fileText;            // as written in the manifest
    std::filesystem::path file;      // resolved against the manifest's folder, normalised (the layer kept)

    std::string label() const;       // <input name="scene" file="shots/a.exr">
};

struct ReplayCompare {
    SourceLocation where;
    std::string target;                 // a render target; "" for the workspace's output
    std::string referenceText;          // as written in the manifest
    std::filesystem::path reference;    // resolved against the manifest's folder, normalised
    CompareLimits limits;
    bool storeHalf = false;             // --update writes 16-bit half floats instead of 32-bit

    // The name in messages and output files: the target, or "output".
    std::string label() const { return target.empty() ? "output" : target; }
};

struct ReplayCase {
    SourceLocation where;
    std::string name;
    std::string workspaceText;          // as written in the manifest
    std::filesystem::path workspace;    // resolved against the manifest's folder, normalised
    RunSettings run;                    // size {0, 0}: the workspace's own size
    std::optional<std::vector<std::string>> effects;  // as --effects; nullopt: the workspace's choice
    bool check = false;  // check="true": as rmfx render --check; NaN or an infinity in a target fails the case
    std::vector<ReplaySet> sets;
    std::vector<ReplayInput> inputs;
    std::vector<ReplayCompare> compares;  // at least one

    std::vector<std::pair<std::string, std::string>> overrides() const;
};

struct ReplayManifest {
    std::filesystem::path path;
    std::filesystem::path folder;  // where relative paths resolve
    // <media dir> folders, and <replay sandbox>: replay sandboxes its workspaces unless the
    // manifest says sandbox="false" (or `rmfx replay --no-sandbox`).
    MediaOptions media{{}, true};
    std::vector<ReplayCase> cases;

    const ReplayCase* findCase(std::string_view name) const;
};

// The manifest with its warnings, or the diagnostics with at least one error.
Result<ReplayManifest> parseReplayManifestFile(const std::filesystem::path& path);
// `path` names the text in diagnostics; `folder` is where relative paths resolve.
Result<ReplayManifest> parseReplayManifestText(const std::string& text, const std::filesystem::path& path,
                                               const std::filesystem::path& folder);

}  // namespace rmfx
