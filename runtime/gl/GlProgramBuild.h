#pragma once
// A pass's shaders compiled and linked into a GL program, and what the linked program exposes:
// its active uniforms and vertex inputs. Needs a current GL context.

#include <set>
#include <string>
#include <vector>

#include "core/Result.h"
#include "gl/GlHandles.h"
#include "frontend/shader/PassProgram.h"
#include "model/EffectSelection.h"
#include "model/Workspace.h"

namespace rmfx {

struct PassGlProgram {
    ProgramHandle program;
    std::set<std::string> initializedUniforms;  // declared with a value: unbound, they keep it
    std::string vertexCode, fragmentCode;       // as compiled
};

// Compiles and links the pass's assembled program source (compile/CompiledFrame.h). Compiler errors
// are mapped to the shader files' lines.
Result<PassGlProgram> linkPassProgram(const Pass& pass, const PassProgramSource& source);

// Assembles the pass's program source anew from its files with the prelude of the effects asked
// for (hot reload), then links it as above; warnings of assembly come along.
Result<PassGlProgram> buildPassProgram(const Workspace& ws, const Pass& pass, const ShaderPrelude& prelude);

// The program linked again with `fragmentCode` in place of its fragment shader's (the health
// check's counting version of it); on failure the compiler's or linker's log.
Result<ProgramHandle> relinkWithFragment(const PassGlProgram& built, const std::string& fragmentCode);

// A uniform outside any block, as reflection gives it ("name[0]" as "name").
struct ProgramUniform {
    std::string name;
    int glType = 0;
    int location = -1;
    int arraySize = 1;
};
std::vector<ProgramUniform> programUniforms(unsigned program);

// The names of the active vertex inputs, built-ins (gl_Vertex, …) included.
std::set<std::string> activeInputs(unsigned program);

}  // namespace rmfx
