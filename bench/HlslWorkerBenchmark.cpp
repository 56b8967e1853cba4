// What compiling HLSL stages in rmfx-hlsl-worker costs, a process per stage (how rmfx compiled
// them before the worker lived for the run) against one worker for the run (core/IsolatedWorker.h),
// with glslang in this process as the floor. Each round compiles the same STAGES distinct stages
// (a vertex and a pixel shader in turn, the size of the effects' ones) all three ways, interleaved
// so that the machine's load falls on each alike; prints the median and range over the rounds.
//
//   rmfx_bench_hlsl_worker [--stages N] [--rounds N]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "bench/RoundFigures.h"
#include "bench/WholeNumberArgument.h"
#include "core/IsolatedWorker.h"
#include "frontend/shader/HlslWorker.h"

namespace {

using Clock = std::chrono::steady_clock;

rmfx::GlslangHlslRequest stage(int i) {
    std::string n = std::to_string(i);
    if (i % 2 == 0) {
        return {true, "main",
                "float4x4 WorldViewProjection;\nfloat4 offset" + n + ";\n"
                "struct VS_OUTPUT { float4 Pos : POSITION; float4 Col : COLOR0; float2 Tex : TEXCOORD1; };\n"
                "VS_OUTPUT main(float4 Pos : POSITION, float2 Tex : TEXCOORD0) {\n"
                "    VS_OUTPUT o;\n    o.Pos = mul(Pos + offset" + n + ", WorldViewProjection);\n"
                "    o.Col = float4(Tex, 0, 1);\n    o.Tex = Tex * " + n + ".0;\n    return o;\n}\n"};
    }
    return {false, "main",
            "float4 tint;\nfloat gain;\nsampler2D baseMap;\n"
            "float4 main(float2 uv : TEXCOORD1, float4 colour : COLOR0) : COLOR {\n"
            "    float4 sum = 0;\n    for (int k = 0; k < 4; ++k) sum += tex2D(baseMap, uv + k * " + n + ".0 / 512.0);\n"
            "    return sum * tint * gain + colour;\n}\n"};
}

bool compiled(const rmfx::Result<std::string>& answer) {
    return answer && rmfx::GlslangHlslOutcome::deserialize(*answer).kind == rmfx::GlslangHlslOutcome::Compiled;
}

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    int stages = 50, rounds = 5;
    for (int i = 1; i < argc; ++i) {
        std::optional<int> value = i + 1 < argc ? rmfx::bench::wholeNumberArgument(argv[i + 1], 1, 100000) : std::nullopt;
        if (std::strcmp(argv[i], "--stages") == 0 && value) stages = *value;
        else if (std::strcmp(argv[i], "--rounds") == 0 && value) rounds = *value;
        else {
            std::fprintf(stderr, "usage: rmfx_bench_hlsl_worker [--stages N] [--rounds N] (whole numbers from 1)\n");
            return 2;
        }
        ++i;
    }
    rmfx::Result<std::string> program = rmfx::hlslWorkerProgram();
    if (!program) {
        std::fprintf(stderr, "rmfx_bench_hlsl_worker: %s\n", program.error().c_str());
        return 1;
    }
    std::vector<std::string> requests;
    for (int i = 0; i < stages; ++i) requests.push_back(stage(i).serialize());

    std::vector<double> perStage, forTheRun, inProcess;
    for (int round = 0; round < rounds; ++round) {
        auto start = Clock::now();
        for (const std::string& request : requests) {
            rmfx::IsolatedWorker once(*program);
            if (!compiled(once.request(request, rmfx::kHlslWorkerTimeout))) {
                std::fprintf(stderr, "rmfx_bench_hlsl_worker: a stage did not compile in a worker of its own\n");
                return 1;
            }
        }
        perStage.push_back(millisecondsSince(start));

        start = Clock::now();
        rmfx::IsolatedWorker worker(*program);
        for (const std::string& request : requests) {
            if (!compiled(worker.request(request, rmfx::kHlslWorkerTimeout))) {
                std::fprintf(stderr, "rmfx_bench_hlsl_worker: a stage did not compile in the worker for the run\n");
                return 1;
            }
        }
        forTheRun.push_back(millisecondsSince(start));

        start = Clock::now();
        for (int i = 0; i < stages; ++i) {
            if (rmfx::compileHlslToSpirv(stage(i)).kind != rmfx::GlslangHlslOutcome::Compiled) {
                std::fprintf(stderr, "rmfx_bench_hlsl_worker: a stage did not compile in this process\n");
                return 1;
            }
        }
        inProcess.push_back(millisecondsSince(start));
    }

    std::printf("%d HLSL stages, %d rounds: milliseconds for all the stages, median (range)\n", stages, rounds);
    auto row = [&](const char* label, const std::vector<double>& samples) {
        std::printf("  %-34s %9.1f  (%.1f to %.1f)   %.2f ms a stage\n", label, rmfx::bench::median(samples),
                    *std::min_element(samples.begin(), samples.end()), *std::max_element(samples.begin(), samples.end()),
                    rmfx::bench::median(samples) / stages);
    };
    row("a worker process per stage (before)", perStage);
    row("one worker for the run (now)", forTheRun);
    row("glslang in this process (floor)", inProcess);
    std::printf("  speed-up of the worker for the run: %.1fx\n", rmfx::bench::median(perStage) / rmfx::bench::median(forTheRun));
    return 0;
}
