// What a fragment shader that can write a storage buffer costs a GPU beyond its instructions: the
// question the health check's counting while drawing left open on an NVIDIA H200, where each
// 128x128 star pass went from 0.009 to 0.013 ms with counting code that no fragment ran
// (docs/performance.md, "On an NVIDIA H200, counting while drawing"). hdr_lighting's star pass in
// miniature: 45 draws a frame, each over a 128x128 RGBA16F target, eight taps of the target the
// draw before wrote (ping-pong), in variants rendered side by side:
//
//   plain           the pass's shader alone
//   bound           the same, with a storage buffer bound (the shader does not declare it)
//   counting        the shader with counting code after it, as gl/HealthInstrumentation adds: atomics
//                   only where the colour is NaN, infinite or negative, which no fragment here is;
//                   one buffer for every draw, bound once a frame
//   buffer-per-draw counting, each draw writing a buffer of its own (bound before it): whether the
//                   driver orders draws that write the same buffer one after another
//   early-tests     counting with layout(early_fragment_tests)
//
// A round renders --frames frames of each variant, the order rotated each round; a frame's GPU time
// is a GL_TIME_ELAPSED query around its 45 draws, its wall time renderFrame + glFinish. Printed: the
// median per draw of each variant, and each one's ratio to plain. Never run by ctest.
//
//   rmfx_bench_storage_writes [--rounds N] [--frames N]

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "bench/RoundFigures.h"
#include "bench/WholeNumberArgument.h"
#include "gl/GlContext.h"
#include "gl/GlFullScreenTriangle.h"
#include "gl/GlHandles.h"
#include "gl/GlProgramBuild.h"

namespace {

using namespace rmfx;
using Clock = std::chrono::steady_clock;

constexpr int kSize = 128;
constexpr int kDraws = 45;

const char* const kPass = R"(#version 450 core
uniform sampler2D Source;
out vec4 colour;
void passMain() {
    vec2 texel = 1.0 / vec2(textureSize(Source, 0));
    vec2 uv = gl_FragCoord.xy * texel;
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 8; ++i) sum += texture(Source, uv + float(i) * texel * vec2(1.0, 0.5)) * 0.125;
    colour = sum;
}
)";

const char* const kPlainMain = "void main() { passMain(); }\n";

const char* const kCountingMain = R"(layout(std430, binding = 0) buffer Health { int words[]; };
void main() {
    passMain();
    if (any(isnan(colour)) || any(isinf(colour)) || any(lessThan(colour, vec4(0.0)))) {
        int pixel = int(gl_FragCoord.y) * 128 + int(gl_FragCoord.x);
        atomicAdd(words[0], 1);
        atomicMin(words[1], pixel);
    }
}
)";

enum Variant { Plain, Bound, Counting, BufferPerDraw, EarlyTests, kVariants };
const char* const kNames[kVariants] = {"plain", "bound", "counting", "buffer-per-draw", "early-tests"};

ProgramHandle program(const std::string& fragment) {
    PassGlProgram fullScreen;
    fullScreen.vertexCode = fullScreenTriangleVertexSource();
    Result<ProgramHandle> p = relinkWithFragment(fullScreen, fragment);
    if (!p) {
        std::fprintf(stderr, "rmfx_bench_storage_writes: the shader does not build: %s\n", p.error().c_str());
        std::exit(1);
    }
    return std::move(*p);
}

// The fragment shader's text: the pass, then `main` (after the pass's #version line, the early
// tests' layout where asked).
std::string fragmentOf(const char* main, bool earlyTests) {
    std::string s = kPass;
    if (earlyTests) s.insert(s.find('\n') + 1, "layout(early_fragment_tests) in;\n");
    return s + main;
}

}  // namespace

int main(int argc, char** argv) {
    int rounds = 10, frames = 20;
    for (int i = 1; i < argc; i += 2) {
        const std::string option = argv[i];
        std::optional<int> n = i + 1 < argc ? bench::wholeNumberArgument(argv[i + 1], 1, 1000) : std::nullopt;
        if ((option != "--rounds" && option != "--frames") || !n) {
            std::fprintf(stderr, "rmfx_bench_storage_writes: bad argument '%s %s'\nusage: rmfx_bench_storage_writes [--rounds N] [--frames N] (N from 1 to 1000)\n",
                         option.c_str(), i + 1 < argc ? argv[i + 1] : "");
            return 2;
        }
        (option == "--rounds" ? rounds : frames) = *n;
    }
    auto context = GlContext::createHeadless();
    if (!context) {
        std::fprintf(stderr, "rmfx_bench_storage_writes: no headless GL context: %s\n", context.error().c_str());
        return 1;
    }
    std::printf("%s, %s\n", reinterpret_cast<const char*>(glGetString(GL_VERSION)), reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

    std::array<ProgramHandle, kVariants> programs{program(fragmentOf(kPlainMain, false)), program(fragmentOf(kPlainMain, false)),
                                                  program(fragmentOf(kCountingMain, false)), program(fragmentOf(kCountingMain, false)),
                                                  program(fragmentOf(kCountingMain, true))};
    for (const ProgramHandle& p : programs) glProgramUniform1i(p.get(), glGetUniformLocation(p.get(), "Source"), 0);

    // Two targets drawn in turn, each sampling the other; a smooth positive start.
    std::vector<float> start(static_cast<size_t>(kSize * kSize * 4));
    for (size_t i = 0; i < start.size(); ++i) start[i] = 0.25f + 0.5f * static_cast<float>(i % 97) / 97.0f;
    std::array<TextureHandle, 2> targets;
    std::array<FramebufferHandle, 2> framebuffers;
    for (int t = 0; t < 2; ++t) {
        targets[t] = createTexture(GL_TEXTURE_2D);
        glTextureStorage2D(targets[t].get(), 1, GL_RGBA16F, kSize, kSize);
        glTextureSubImage2D(targets[t].get(), 0, 0, 0, kSize, kSize, GL_RGBA, GL_FLOAT, start.data());
        glTextureParameteri(targets[t].get(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(targets[t].get(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(targets[t].get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(targets[t].get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        framebuffers[t] = createFramebuffer();
        glNamedFramebufferTexture(framebuffers[t].get(), GL_COLOR_ATTACHMENT0, targets[t].get(), 0);
    }
    // The shared buffer, then one per draw; two words each (count, first pixel).
    std::vector<BufferHandle> buffers;
    for (int b = 0; b <= kDraws; ++b) {
        buffers.push_back(createBuffer());
        const std::int32_t words[2] = {0, 0x7fffffff};
        glNamedBufferStorage(buffers.back().get(), sizeof words, words, 0);
    }
    VertexArrayHandle vertexArray = createVertexArray();
    glBindVertexArray(vertexArray.get());
    glViewport(0, 0, kSize, kSize);
    QueryHandle timer = createQuery(GL_TIME_ELAPSED);

    auto frame = [&](int v, double& gpuMs, double& wallMs) {
        const auto began = Clock::now();
        glBeginQuery(GL_TIME_ELAPSED, timer.get());
        glUseProgram(programs[static_cast<size_t>(v)].get());
        if (v != Plain) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0].get());
        for (int d = 0; d < kDraws; ++d) {
            if (v == BufferPerDraw) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[static_cast<size_t>(d + 1)].get());
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffers[d % 2].get());
            glBindTextureUnit(0, targets[(d + 1) % 2].get());
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        glEndQuery(GL_TIME_ELAPSED);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
        glFinish();
        wallMs = std::chrono::duration<double, std::milli>(Clock::now() - began).count();
        GLuint64 ns = 0;
        glGetQueryObjectui64v(timer.get(), GL_QUERY_RESULT, &ns);
        gpuMs = static_cast<double>(ns) * 1e-6;
    };

    std::array<std::vector<double>, kVariants> gpu, wall;
    double ignoredGpu = 0.0, ignoredWall = 0.0;
    for (int v = 0; v < kVariants; ++v) frame(v, ignoredGpu, ignoredWall);  // compile and warm
    for (int r = 0; r < rounds; ++r)
        for (int k = 0; k < kVariants; ++k) {
            const int v = (k + r) % kVariants;
            for (int f = 0; f < frames; ++f) {
                double g = 0.0, w = 0.0;
                frame(v, g, w);
                gpu[static_cast<size_t>(v)].push_back(g);
                wall[static_cast<size_t>(v)].push_back(w);
            }
        }
    if (glGetError() != GL_NO_ERROR) std::fprintf(stderr, "rmfx_bench_storage_writes: a GL error was raised\n");

    std::printf("rmfx_bench_storage_writes: %d draws a frame over %dx%d RGBA16F, 8 taps each; %d rounds of %d frames per variant\n\n",
                kDraws, kSize, kSize, rounds, frames);
    std::printf("| variant | GPU per draw (us), median | / plain | wall per frame (ms), median | / plain |\n|---|---|---|---|---|\n");
    const double plainGpu = bench::median(gpu[Plain]), plainWall = bench::median(wall[Plain]);
    for (int v = 0; v < kVariants; ++v) {
        const double g = bench::median(gpu[static_cast<size_t>(v)]), w = bench::median(wall[static_cast<size_t>(v)]);
        std::printf("| %s | %.2f | %.3f | %.3f | %.3f |\n", kNames[v], g * 1e3 / kDraws, plainGpu > 0 ? g / plainGpu : 0.0, w,
                    plainWall > 0 ? w / plainWall : 0.0);
    }
    return 0;
}
