#pragma once
// The built-in default workspace (effects/default.xml, compiled into the library).

namespace rmfx {

const char* defaultWorkspaceText();
constexpr const char* defaultWorkspaceName = "<built-in default>";

}  // namespace rmfx
