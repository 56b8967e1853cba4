#pragma once
// `rmfx render --explain`: the workspace's inputs and the files given for them, the schedule of a
// frame as a table, the effects the frame's content skipped (each pass run or culled and why),
// the targets with size, format, bytes, lifetime and the memory they share, and the frame's peak
// GPU memory against the total of all declared targets.

#include <map>
#include <set>
#include <string>

#include "graph/PassGraph.h"
#include "graph/TargetPlan.h"
#include "model/Workspace.h"

namespace rmfx {

struct FrameExplanationInput {
    const Workspace* ws = nullptr;
    const PassGraph* graph = nullptr;
    const TargetPlan* plan = nullptr;
    std::set<std::string> askedEffects;
    std::set<std::string> switchedOffEffects;
    bool pooled = true;
    // The file each given <input> was given (rmfx render --input), as the user wrote it.
    std::map<std::string, std::string> inputFiles;
    // Whether effects with a source may be skipped by content, whether a frame ran (false: the
    // plan alone is explained, and content skip's answers are not known), and those the last
    // frame skipped, with why.
    bool contentSkip = true;
    bool frameRan = true;
    std::map<std::string, std::string> contentSkipped;
    // Passes drawn compiled without the effects they read where those are skipped, by pass.
    std::map<std::string, std::set<std::string>> drawnWithoutSkipped;
    // Passes outside the effects drawn only where those effects run (only they read them), by pass.
    std::map<std::string, std::set<std::string>> drawnOnlyForEffects;
    // Effects with a source run whatever it holds, with why (a target of theirs is an output).
    std::map<std::string, std::string> runningWhateverTheContent;
};

std::string explainFrame(const FrameExplanationInput& input);

// 1536 → "1.5 KiB"; exact bytes below 1 KiB.
std::string formatBytes(std::size_t bytes);

}  // namespace rmfx
