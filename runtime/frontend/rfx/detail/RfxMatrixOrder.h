#pragma once
// Which way round a RenderMonkey workspace's HLSL multiplies its semantic matrices, from the
// version that saved it (RmEffectWorkspace XML_VERSION="RenderMonkey 1.5"). RenderMonkey up to
// 1.5 passed matrices in OpenGL's layout, so its HLSL wrote mul(view_proj_matrix, Pos); from 1.6
// on it passed them as D3DX does, and its template wrote mul(Input.Position, matViewProjection).
// docs/rendermonkey.md, "Matrices", has the files this was read from.

#include "frontend/rfx/detail/RfxElement.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

// ColumnVector for versions before 1.6, RowVector for later ones. A missing or unreadable
// XML_VERSION is read as a later version, with a warning.
HlslMatrixOrder hlslMatrixOrderOf(const RfxElement& workspace);

}  // namespace rmfx::rfx
