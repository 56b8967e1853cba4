#pragma once
// Direct3D 9's compiler let a shader assign to a global it did not declare static (`gain = gain *
// 2;`): the global is a constant the application sets, and the assignment went to a copy private
// to that run of the shader. glslang's HLSL front end refuses it ("can't modify a uniform"). This
// step writes out the copy fxc made: a `static` global beside the constant, set from it at the
// start of the entry point, and read and written in its place by every function.

#include <string>
#include <vector>

#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {

struct HlslWritableGlobals {
    std::string code;                  // the rewritten code, every line where it was
    std::vector<std::string> written;  // the globals given a copy, in declaration order
    std::vector<int> lines;            // the 1-based line of each one's declaration
};

// For each global declared at file scope without static or const (not a sampler or texture) that
// a function body assigns to (=, op=, ++, --, also through a swizzle or index), and that the body
// does not declare itself: the copy `rm_writable_NAME`, declared on the line of NAME's declaration,
// assigned from NAME at the start of `entryPoint`'s body, and used for NAME in every function body.
// Code without such a write, or without the entry point, comes back unchanged.
HlslWritableGlobals giveWrittenGlobalsACopy(const std::string& code, const std::string& entryPoint);
// The same, given `blanked`, BlankedHlsl(code), that the caller scans in other ways too.
HlslWritableGlobals giveWrittenGlobalsACopy(const std::string& code, const BlankedHlsl& blanked, const std::string& entryPoint);

}  // namespace rmfx
