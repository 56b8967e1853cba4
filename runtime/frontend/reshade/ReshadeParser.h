#pragma once
// The parser of ReShade FX effects: the preprocessed text (ReshadePreprocessor.h) read into the
// effect's syntax tree (ReshadeSyntax.h), every declaration with the file and line the user wrote
// it on, through includes and macros.
//
//   Diagnostics diagnostics;
//   PreprocessedReshade pre = preprocessReshade(input, diagnostics);
//   ReshadeEffect effect = parseReshadeEffect(pre, diagnostics);
//   effect.textures[0].width → 960 (`Width = BUFFER_WIDTH / 2;` at 1920)
//
// It reads what ReShade's own parser (crosire/reshade, effect_parser_stmt.cpp) reads at the top
// level: `uniform`s with annotations and initial values; `texture`s with their property block
// (Width, Height, Depth, MipLevels, Format) or a semantic (`: COLOR`, `: DEPTH`); `sampler`s
// (Texture, AddressU/V/W, Min/Mag/MipFilter, MinLOD, MaxLOD, MipLODBias, SRGBTexture); `storage`s
// (Texture, MipLevel); `struct`s; `namespace`s (names qualified "Ns::Name"); `static` globals; a
// global without `static` is a uniform, as in ReShade (with its warning); functions with their
// parameters, semantics and body (a span of the code: braces matched, not parsed further);
// techniques with their annotations and passes, and every pass state ReShade knows, each value
// checked against its enumeration. Shader entry points, render targets and sampler textures are
// resolved through the namespaces as ReShade resolves names.
//
// Problems are Diagnostics "file:line: error: ELEMENT: message", ELEMENT the declaration
// ("uniform Strength", "texture BlurTex", "technique Bloom", "pass 2 of technique Bloom"). After an
// error it reads on from the next declaration, pass state or property, so one run reports several.
// Bounded for any input: namespaces nest 32 deep, expressions 200 deep, 4M tokens, 100 errors.

#include "core/Diagnostic.h"
#include "frontend/reshade/ReshadePreprocessor.h"
#include "frontend/reshade/ReshadeSyntax.h"

namespace rmfx {

// Problems are appended to `diagnostics`; the effect holds what was read, errors or not.
ReshadeEffect parseReshadeEffect(const PreprocessedReshade& source, Diagnostics& diagnostics);

}  // namespace rmfx
