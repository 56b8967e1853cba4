#pragma once
// The effects of a RenderMonkey workspace: RENDER_MONKEY → RmEffectWorkspace → optional
// RmEffectGroup → RmOpenGLEffect / RmOpenGLESEffect / RmDirectXEffect, each named by its dotted
// path ("Effect Workspace.Group.Effect", the form of ACTIVE_EFFECT).

#include <string>
#include <vector>

#include <tinyxml2.h>

#include "core/Diagnostic.h"

namespace rmfx::rfx {

enum class RfxApi { OpenGL, OpenGLES, Direct3D };
const char* rfxApiName(RfxApi api);

struct RfxEffectEntry {
    std::string path;       // "Effect Workspace.Group.Effect"
    std::string name;       // "Effect"
    RfxApi api = RfxApi::OpenGL;
    bool active = false;    // named by ACTIVE_EFFECT
    const tinyxml2::XMLElement* element = nullptr;
    const tinyxml2::XMLElement* group = nullptr;      // its RmEffectGroup, or null
    const tinyxml2::XMLElement* workspace = nullptr;  // the RmEffectWorkspace
};

struct RfxCatalogue {
    std::vector<RfxEffectEntry> effects;  // in file order
    std::string activePath;               // ACTIVE_EFFECT as written
};

// Reads the effect tree under RENDER_MONKEY; problems (no RmEffectWorkspace, ACTIVE_EFFECT
// naming no effect) become diagnostics.
RfxCatalogue readCatalogue(const tinyxml2::XMLElement* root, const std::string& file, Diagnostics& diagnostics);

// The effect `wanted` names: a whole dotted path, the path without the workspace's name
// ("Group.Effect"), or an effect name that only one effect has; empty: the active effect (or
// the only one). Null with an error listing the effects when none matches.
const RfxEffectEntry* chooseEffect(const RfxCatalogue& catalogue, const std::string& wanted, const std::string& file,
                                   Diagnostics& diagnostics);

}  // namespace rmfx::rfx
