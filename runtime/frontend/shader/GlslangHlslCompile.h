#pragma once
// glslang's HLSL front end on one stage, and the bytes a request and its outcome cross between
// rmfx and rmfx-hlsl-worker as (the program that runs glslang apart: core/IsolatedWorker.h says
// why). Only the standard library and glslang: the worker is built from this file alone.

#include <string>
#include <vector>

namespace rmfx {

struct GlslangHlslRequest {
    bool vertex = false;  // else a pixel shader
    std::string entryPoint;
    std::string code;

    std::string serialize() const;
    // False for bytes that are no request (the worker says so and fails).
    static bool deserialize(const std::string& bytes, GlslangHlslRequest& out);
};

struct GlslangHlslOutcome {
    enum Kind : char { Failed = 'F', NoEntryPoint = 'E', Compiled = 'S' };
    Kind kind = Failed;
    std::string log;              // Failed: glslang's info log
    std::vector<unsigned> spirv;  // Compiled

    std::string serialize() const;
    static GlslangHlslOutcome deserialize(const std::string& bytes);
};

// Runs glslang in this process: only rmfx-hlsl-worker calls it (a malformed shader can crash it).
GlslangHlslOutcome compileHlslToSpirv(const GlslangHlslRequest& request);

}  // namespace rmfx
