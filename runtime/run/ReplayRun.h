#pragma once
// Replaying one case of a manifest (ReplayManifest.h): render its workspace headless and read
// back the images it compares, then compare each with its reference or store it as the new
// reference. What `rmfx replay` does per case.

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

// Reads the reference and compares. A reference that cannot be read is a failed comparison
// whose problem says so.
ImageComparison compareWithReference(const Image& actual, const ReplayCompare& compare);

// Writes `actual` as the compare's reference (creating its folder): EXR, 32-bit float or 16-bit
// half as the compare says.
Result<void> storeReference(const Image& actual, const ReplayCompare& compare);

}  // namespace rmfx
