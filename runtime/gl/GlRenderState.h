#pragma once
// A pass's blend, depth and rasterizer state, set on the current GL context before it draws. The
// state each call last set is remembered, so that a pass asking for what the pass before it left
// makes no GL call (the executor issues a frame's passes one after another, and most ask for the
// same). What is remembered is forgotten at the start of each frame and whenever something else
// may have drawn in between (the health check, content skip's probe, the editor).

#include <optional>

#include "model/Workspace.h"

namespace rmfx {

class GlRenderState {
public:
    // `compatibility`: the context is a compatibility-profile one, which draws front and back faces
    // in their own polygon modes and lines wider than a pixel (validation refuses both otherwise).
    // `rowsTopFirst`: the workspace's passes draw the picture's top row at GL's row 0
    // (rowsTopFirst(TextureSpace)), which turns the winding GL sees over.
    void apply(const Pass& pass, bool compatibility, bool rowsTopFirst);
    // After the pass's draw: filled polygons and 1-pixel lines again, where the pass changed them.
    void restoreFilledPolygons(const Pass& pass, bool compatibility);
    void depthMask(bool write);
    // The context's state is no longer known: the next calls set everything.
    void forget() { *this = GlRenderState(); }

private:
    void enable(unsigned cap, bool on, std::optional<bool>& known);

    std::optional<bool> blend_, depthTest_, cull_, depthMask_;
    std::optional<unsigned> polygonFront_, polygonBack_, depthFunc_, cullFace_, frontFace_;
    std::optional<float> lineWidth_;
    std::optional<BlendState> blendState_;
};

}  // namespace rmfx
