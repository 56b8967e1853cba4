#pragma once
// The Variables section of the editor panel: one widget per workspace variable (chosen by
// chooseWidget), its description as tooltip, a reset button each, Reset all, and Save, which
// writes the current values back into the workspace file.

#include <string>

#include "run/LiveWorkspace.h"

namespace rmfx::editor {

class VariablesPanel {
public:
    void draw(LiveWorkspace& session);

private:
    void save(LiveWorkspace& session);
    std::string status_;
    bool statusIsError_ = false;
};

}  // namespace rmfx::editor
