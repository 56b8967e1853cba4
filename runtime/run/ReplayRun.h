#pragma once
// Replaying one case of a manifest (ReplayManifest.h): render its workspace headless and read
// back the images it compares, then compare each with its reference or store it as the new
// reference. What `rmfx replay` does per case.

#include <filesystem>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "frontend/replay/ReplayManifest.h"
#include "io/image/ImageCompare.h"
#include "model/Image.h"

#include "gl/HeadlessContexts.h"

namespace rmfx {

// Loads and validates the case's workspace, applies its <set> values, checks that its compares
// name targets the workspace has, renders the frames and reads the images. Needs a current GL
// context; the rest of a run is unaffected by a failing case. `media`: the manifest's search path
// and sandbox, with the command line's changes. With `contexts`, the context of the workspace's
// profile is made current first. The images, one per compare in order; the diagnostics: errors and
// warnings of the workspace, of the case's <set> and <compare> elements against it (located in the
// manifest), and of rendering.
Result<std::vector<Image>> renderReplayCase(const ReplayCase& c, const MediaOptions& media, HeadlessContexts* contexts = nullptr);

// A render target of a case after its frames, and the pass that wrote it last.
struct CaseTarget {
    std::string target;
    std::string pass;
    Image image;
    bool isOutput = false;  // the workspace's output, which a <compare> without target reads
};

// Renders the case as renderReplayCase does, but keeps every target (nothing is culled for the
// compares, no memory is shared) and reads each target the last frame wrote, in the order of the
// passes that wrote them last: what `rmfx replay --update --all-targets` stores, and what a failing
// case compares with it to find the pass that broke.
Result<std::vector<CaseTarget>> renderReplayTargets(const ReplayCase& c, const MediaOptions& media,
                                                    HeadlessContexts* contexts = nullptr);

// Where `--update --all-targets` keeps a case's targets: "<case>.targets/" beside the reference of
// its first compare, one "<target>.exr" each.
std::filesystem::path caseTargetsFolder(const ReplayCase& c);
// The file of one target there (characters a file name should not hold become '_').
std::filesystem::path caseTargetFile(const ReplayCase& c, const std::string& target);

// The first target of a failing case that differs from its stored reference beyond the limits:
// the limits of the compare that reads that target, else `limits` (the failing compare's).
struct FirstDifference {
    const CaseTarget* target = nullptr;  // null: every stored target matched
    ImageComparison comparison;
    int position = 0;                     // of `target`, 1-based, among the targets rendered
    std::vector<std::string> matched;     // the targets before it that matched their references
    std::vector<std::string> unstored;    // targets rendered without a stored reference
};
FirstDifference findFirstDifference(const ReplayCase& c, const std::vector<CaseTarget>& targets,
                                    const CompareLimits& limits);

// Reads the reference and compares. A reference that cannot be read is a failed comparison
// whose problem says so.
ImageComparison compareWithReference(const Image& actual, const ReplayCompare& compare);

// Writes `actual` as the compare's reference (creating its folder): EXR, 32-bit float or 16-bit
// half as the compare says.
Result<void> storeReference(const Image& actual, const ReplayCompare& compare);

}  // namespace rmfx
