#pragma once
// RmState elements of a pass's RmRenderStateBlock → the pass's blend, depth and raster state.
//
// OpenGL effects name their states (GL_CullMode, GL_BlendSourceRGB…) and number the values with
// RenderMonkey's own 1-based enumerations (compare functions 1 NEVER … 8 ALWAYS, blend factors
// 1 ZERO … 15 SRC_ALPHA_SATURATE, blend equations 1 ADD … 5 MAX, cull modes 1 none, 2 front,
// 3 back, 4 front and back, front faces 1 CCW, 2 CW). Direct3D effects use D3DRENDERSTATETYPE
// numbers in STATE and D3D9 enumerations in VALUE (D3DCMP_*, D3DBLEND_*, D3DBLENDOP_*, D3DCULL_*).
// Float-valued states keep the IEEE-754 bits of the float in the integer VALUE. A state rmfx's
// model has no place for is a warning naming the state and its value; a value outside the
// state's enumeration is an error.

#include "frontend/rfx/detail/RfxEffectCatalogue.h"
#include "frontend/rfx/detail/RfxElement.h"
#include "model/Workspace.h"

namespace rmfx::rfx {

// RenderMonkey's state at the start of a frame: depth test and write on with LESS_EQUAL (its
// preview window has a depth buffer), no blending, no culling.
void setRenderMonkeyDefaults(Pass& pass);

// The RmState children of an RmRenderStateBlock, applied over the pass's blend, depth and raster
// state. States carry over from pass to pass (as the device's did), so the pass should come in
// with the state of the pass that ran before it. separateAlpha, D3DRS_SEPARATEALPHABLENDENABLE,
// carries over with them; so do the alpha blend states as set, which finishD3dRenderStates then
// replaces in the pass (not in what carries over) when alpha blending is not separate.
void applyRenderStateBlock(const RfxElement& block, RfxApi api, Pass& pass, bool& separateAlpha);

void applyGlRenderState(const RfxElement& state, Pass& pass);
// separateAlpha: set by D3DRS_SEPARATEALPHABLENDENABLE; pass it to finishD3dRenderStates.
void applyD3dRenderState(const RfxElement& state, Pass& pass, bool& separateAlpha);
// Without separate alpha blending, Direct3D blends alpha with the colour factors and operation.
void finishD3dRenderStates(Pass& pass, bool separateAlpha);

// The float whose IEEE-754 bits are the 32-bit integer `bits` (read modulo 2^32).
float floatFromBits(long long bits);

// A state's VALUE. RenderMonkey wrote states as 32-bit integers, floats as their IEEE-754 bits;
// files edited by hand or by other tools also write floats as decimal text ("0.250000"). For a
// state that holds a float (`isFloat`) such text is read as the float and returned as its bits;
// for the others decimal text of a whole number ("1.000000") is that number, and anything else is
// an error on the element.
std::optional<long long> stateValue(const RfxElement& state, bool isFloat);

}  // namespace rmfx::rfx
