#pragma once
// effects/shader_5.xml with all three effects, written out by hand in raw OpenGL 4.5 (DSA): the
// yardstick against which rmfx_bench_effects measures the interpreter's (GlExecutor's) CPU cost
// per frame. Its 20 passes, their targets, states, samplers and uniforms are spelled out in
// HandWrittenShader5.cpp; the workspace only supplies what a hand-written renderer would also
// read from disk or a settings file: the shader and image files, the variables' default values
// and the camera. Every target has its own texture (no pooling). tests/HandWrittenShader5GLTest
// checks that it renders the executor's image. Needs a current GL 4.5 context.

#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx::bench {

class HandWrittenShader5 {
public:
    // `ws`: effects/shader_5.xml as loaded (with any --set overrides applied to its variables).
    static Result<std::unique_ptr<HandWrittenShader5>> create(const Workspace& ws, glm::ivec2 viewport);
    ~HandWrittenShader5();
    HandWrittenShader5(const HandWrittenShader5&) = delete;
    HandWrittenShader5& operator=(const HandWrittenShader5&) = delete;

    // Issues one frame's passes and returns without waiting for them to finish.
    void renderFrame();

    unsigned outputTexture() const;  // rgba32f (shader_5's <output format>) at the viewport size: the screen
    int passCount() const;

    struct State;

private:
    explicit HandWrittenShader5(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace rmfx::bench
