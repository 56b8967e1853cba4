#pragma once
// The vertex stage of a pass in a Direct3D texture space (model/Workspace.h TextureSpace): the
// shader's main is renamed and called from a new main that turns clip-space y over (so that the
// top of the picture lands on row 0 of the target, where Direct3D's v = 0 reads it) and, for
// Direct3D 9, moves the geometry by D3D9's half pixel (its pixel centres lie at whole-number
// window coordinates: the pixel at column i is shaded with what lies at x = i, not i + 0.5).
// Wrapping main, rather than adding statements at its end, keeps a `return` in it harmless.
// The GL executor turns the winding over with the picture (gl/GlRenderState).

#include <string_view>

#include "frontend/shader/ShaderPreprocessor.h"
#include "model/Workspace.h"

namespace rmfx {

// Nothing for TextureSpace::OpenGL. The half-pixel step reads rm_InvTargetSize (one texel of the
// target the pass draws, which the executor fills), declared when the code does not declare it.
void turnClipSpaceOver(PreprocessedShader& vertexShader, TextureSpace space);

// Whether the code holds `uniform [WORD] vec2 rm_InvTargetSize` (spaces as a regex's \s between,
// `uniform` and the name whole words): what the regex \buniform\s+(\w+\s+)?vec2\s+rm_InvTargetSize\b
// finds, by a scan (libstdc++'s regex was a tenth of the rfx_import fuzz target's time under ASan).
bool declaresInvTargetSize(std::string_view code);

}  // namespace rmfx
