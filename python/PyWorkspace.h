#pragma once
// rmfx.load(…) and the rmfx.Workspace it returns: a workspace loaded, validated and overridden
// through the run preparation every rmfx run uses (compile/RunPreparation.h: loadRun), whose
// variables and effects Python reads and sets. Renderers (python/PyRenderer.h) compile their runs
// from it, so what is set here is what they render.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "compile/RunPreparation.h"

namespace rmfx::python {

class PyWorkspace {
public:
    // The file (an rmfx workspace or a RenderMonkey .rfx), the media search path, what a missing
    // file becomes ("error" or "placeholder"), the .rfx effect to import ("" the active one), and
    // NAME=VALUE overrides. Raises rmfx.Error with the loader's diagnostics.
    // textures: "NAME=FILE" (or six faces "NAME=px,nx,py,ny,pz,nz") as rmfx render --texture takes
    // them; sandbox: references may not lead outside the workspace's folder and `media`.
    PyWorkspace(const std::string& path, const std::vector<std::string>& media, const std::string& missingMedia,
                const std::string& effect, const std::vector<std::pair<std::string, std::string>>& overrides,
                const std::vector<std::string>& textures = {}, bool sandbox = false);

    const Workspace& ws() const { return loaded_.ws; }
    const LoadedRun& loaded() const { return loaded_; }
    const RunRequest& request() const { return request_; }
    const Diagnostics& warnings() const { return warnings_; }

    // Sets a variable's value from its text form (validated as `rmfx render --set` validates it);
    // raises rmfx.Error naming the variable, leaving every value as it was.
    void set(const std::string& name, const std::string& text);
    const Variable& variable(const std::string& name) const;  // raises for an unknown name

    // The effects asked for (--effects); nullopt: the workspace's <output effects>, else all.
    const std::optional<std::vector<std::string>>& effects() const { return effects_; }
    void selectEffects(std::optional<std::vector<std::string>> effects);  // raises for an unknown name

    // Bumped by set() and by selectEffects(): a renderer updates its executor's values, or
    // compiles its run anew, when they differ from the ones it last saw.
    std::uint64_t valuesRevision() const { return valuesRevision_; }
    std::uint64_t effectsRevision() const { return effectsRevision_; }

private:
    RunRequest request_;  // the file and how it loads; request_.overrides: every value set so far
    LoadedRun loaded_;    // loadRun's result with those values
    Diagnostics warnings_;
    std::optional<std::vector<std::string>> effects_;
    std::uint64_t valuesRevision_ = 0;
    std::uint64_t effectsRevision_ = 0;
};

// rmfx.load, rmfx.Workspace, rmfx.Variable, rmfx.Effect.
void bindWorkspace(pybind11::module_& m);

}  // namespace rmfx::python
