#pragma once
// The camera of an imported effect that has no RmCamera. RenderMonkey showed such an effect
// through its viewer's camera, which the file does not keep, looking at the model; rmfx's default
// orbit camera (4 units from the origin) suits unit-sized models only, and RenderMonkey's models
// are about 100 units across: one would swallow it. Many files keep the viewer's last matrices in
// variables RenderMonkey filled by semantic (View and Projection, ViewProjection, or
// WorldViewProjection with World, ViewInverse): the camera is then recovered from them, those the
// passes' shaders read first (a file often keeps a stale View beside the matrix its shaders read). Otherwise the camera keeps its direction and moves to where the bounding sphere of the
// models the passes draw fills its field of view, leaving out a dome or box around the scene.

#include "model/Workspace.h"

namespace rmfx {

// With media resolved (model files are read for their bounds; one that does not load is left to
// the executor to report). Does nothing when the workspace's camera came from an RmCamera (its
// `where` names the element) or no pass draws a model other than a screen-aligned quad.
void frameDrawnModels(Workspace& ws);

}  // namespace rmfx
