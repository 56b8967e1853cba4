#pragma once
// Direct3D 9's compiler accepted a vector constructor as the target of an assignment, the value's
// components going to the named variables in order:
//     float3 vNormal; float fGloss;
//     float4(vNormal, fGloss) = tex2D(bump_glossMap, Tex);
// (ATI's stock Iridescent Butterfly). glslang refuses it. This step writes the assignment out,
// in place and on the same lines:
//     { float4 rm_unpacked_1 = tex2D(bump_glossMap, Tex); vNormal = rm_unpacked_1.xyz; fGloss = rm_unpacked_1.w; }

#include <string>
#include <vector>

namespace rmfx {

struct HlslConstructorAssignments {
    std::string code;        // the rewritten code, every line where it was
    std::vector<int> lines;  // the 1-based line of each assignment written out
};

// Each statement `TYPEn(a, b, …) = VALUE;` inside a function body whose targets are plain names
// declared before it (a parameter or a local, `float3 a, c;`) with scalar or vector types of
// the same base type whose widths add up to n. Anything else is left for glslang to report.
HlslConstructorAssignments writeOutConstructorAssignments(const std::string& code);

}  // namespace rmfx
