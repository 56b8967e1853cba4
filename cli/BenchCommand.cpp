// rmfx bench [MANIFEST]: measures every variant of the manifest's stages on each input, GPU time
// and error against the stage's float64 ideal, and writes accuracy.{csv,json,svg,md}
// (docs/accuracy-vs-time.md).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

#include "bench/accuracy/AccuracyPlot.h"
#include "bench/accuracy/BenchResults.h"
#include "bench/accuracy/NumberText.h"
#include "bench/accuracy/ResultWriters.h"
#include "bench/accuracy/StageIdeal.h"
#include "bench/accuracy/VariantManifest.h"
#include "bench/accuracy/VariantRun.h"
#include "apps/ArgumentParser.h"
#include "cli/Commands.h"
#include "compile/RunPreparation.h"
#include "apps/OptionValues.h"
#include "gl/GlContext.h"
#include "io/file/AtomicFile.h"
#include "io/file/OutputPath.h"
#include "io/image/ImageIO.h"
#include "io/media/MediaArguments.h"
#include "io/xml/XmlElementReader.h"
#include "run/HeadlessRun.h"
#include "validation/WorkspaceLoader.h"
#include "io/image/ImageCodecs.h"

namespace rmfx::cli {

using namespace rmfx::apps;  // the shared argument loop and option values
namespace {

namespace fs = std::filesystem;
using namespace rmfx::accuracy;

struct BenchArguments {
    fs::path manifest = "bench/variants.xml";
    std::vector<fs::path> inputs;
    bool scenes = true;
    glm::ivec2 size{512, 512};
    FrameCounts counts{5, 20};
    std::vector<std::string> stages;
    std::vector<std::string> variants;  // substrings
    fs::path out = "bench-out";
    std::optional<TimeSource> ranked;  // nullopt: auto
    bool quiet = false;
    WorkspaceLoadOptions load;  // --media, --sandbox
};

// With `names`, fills it with the parser's option names and parses nothing.
std::optional<BenchArguments> parseArguments(const std::vector<std::string>& args, std::vector<std::string>* names = nullptr) {
    BenchArguments a;
    bool manifestGiven = false;
    auto count = [](const std::string& text, int low, int& out) {
        char* end = nullptr;
        long n = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || *end || n < low || n > 100000) return false;
        out = static_cast<int>(n);
        return true;
    };
    ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) { return takeMediaArgument(all, i, a.load.media); }, kMediaOptionNames)
        .option({"--input"}, [&](const std::string& value) { a.inputs.push_back(value); return ""; })
        .option({"--size"}, [&](const std::string& value) -> std::string {
            auto size = xml::parseSize(value);
            if (!size || size->first > 16384 || size->second > 16384)
                return "--size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, got '" + value + "'";
            a.size = {size->first, size->second};
            return "";
        })
        .option({"--frames"}, [&](const std::string& value) -> std::string {
            if (!count(value, 1, a.counts.frames)) return "--frames: expected a count from 1 to 100000, got '" + value + "'";
            return "";
        })
        .option({"--warmup"}, [&](const std::string& value) -> std::string {
            if (!count(value, 0, a.counts.warmup)) return "--warmup: expected a count from 0 to 100000, got '" + value + "'";
            return "";
        })
        .option({"--stage"}, [&](const std::string& value) { a.stages.push_back(value); return ""; })
        .option({"--variant"}, [&](const std::string& value) { a.variants.push_back(value); return ""; })
        .option({"--out"}, [&](const std::string& value) { a.out = value; return ""; })
        .option({"--time"}, [&](const std::string& value) -> std::string {
            if (value != "gpu" && value != "wall" && value != "auto") return "--time: expected gpu, wall or auto, got '" + value + "'";
            if (value == "auto") a.ranked.reset();
            else a.ranked = value == "gpu" ? TimeSource::Gpu : TimeSource::Wall;
            return "";
        })
        .flag({"--scenes"}, [&] { a.scenes = true; })
        .flag({"--no-scenes"}, [&] { a.scenes = false; })
        .flag({"-q", "--quiet"}, [&] { a.quiet = true; })
        .positional([&](const std::string& arg) -> std::string {
            if (manifestGiven) return "one manifest at a time; got '" + a.manifest.string() + "' and '" + arg + "'";
            a.manifest = arg;
            manifestGiven = true;
            return "";
        });
    if (names) {
        *names = parser.names();
        return std::nullopt;
    }
    if (std::string message = parser.parse(args); !message.empty()) {
        std::cerr << "rmfx bench: " << message << "\n";
        return std::nullopt;
    }
    return a;
}

struct BenchInput {
    std::string name;
    fs::path file;
    Image image;
};

std::string uniqueName(std::string name, const std::vector<BenchInput>& inputs) {
    auto taken = [&](const std::string& n) {
        return std::any_of(inputs.begin(), inputs.end(), [&](const BenchInput& i) { return i.name == n; });
    };
    if (!taken(name)) return name;
    for (int k = 2;; ++k)
        if (!taken(name + "_" + std::to_string(k))) return name + "_" + std::to_string(k);
}

// Renders a scene workspace's target at `size` into DIR/inputs/NAME.exr.
Result<fs::path> renderScene(const SceneSpec& scene, glm::ivec2 size, const fs::path& folder,
                             const WorkspaceLoadOptions& load) {
    std::string what = "scene '" + scene.name + "': ";
    RunRequest request;
    request.workspace = scene.workspace;
    request.load = load;
    request.size = size;
    request.plan.outputs = {scene.target};
    Result<LoadedRun> loaded = loadRun(request);
    if (!loaded) return Error{what + formatAll(loaded.diagnostics())};
    if (!loaded->ws.canReadTarget(scene.target))
        return Error{what + scene.workspace.string() + " has no target '" + scene.target + "' (" +
                     loaded->ws.describeTargets() + ")"};
    Result<PreparedRun> prepared = compileRun(std::move(*loaded), request);
    if (!prepared) return Error{what + formatAll(prepared.diagnostics())};
    auto run = runHeadless(*prepared, {size, 1, 1.0f / 60.0f});
    if (!run) return Error{what + formatAll(run.diagnostics())};
    std::unique_ptr<GlExecutor>& executor = *run;
    auto image = executor->readTarget(scene.target);
    if (!image) return Error{what + image.error()};
    fs::path file = folder / (scene.name + ".exr");
    if (auto written = writeImage(file, *image); !written) return Error{what + written.error()};
    return file;
}

Result<Image> readInput(const fs::path& file) {
    if (!fs::exists(file)) return Error{file.string() + ": no such file"};
    auto image = readImage(file);
    if (!image) return Error{image.error()};
    if (!image->highDynamicRange)
        return Error{file.string() + ": not a float image (the bench's inputs are HDR: EXR with half or float data)"};
    return image;
}

std::optional<std::vector<BenchInput>> gatherInputs(const BenchArguments& a, const VariantManifest& manifest) {
    std::vector<BenchInput> inputs;
    std::vector<std::pair<std::string, fs::path>> files;
    if (a.scenes) {
        fs::path folder = a.out / "inputs";
        std::error_code ec;
        fs::create_directories(folder, ec);
        for (const SceneSpec& scene : manifest.scenes) {
            if (!scene.file.empty()) {
                files.emplace_back(scene.name, scene.file);
                continue;
            }
            auto rendered = renderScene(scene, a.size, folder, a.load);
            if (!rendered) {
                std::cerr << "rmfx bench: " << rendered.error() << "\n";
                return std::nullopt;
            }
            files.emplace_back(scene.name, *rendered);
        }
    }
    for (const fs::path& file : a.inputs) files.emplace_back(file.stem().string(), file);
    for (const auto& [name, file] : files) {
        auto image = readInput(file);
        if (!image) {
            const fs::path& path = file;  // clang 14 cannot capture a structured binding
            bool sceneFile = std::any_of(manifest.scenes.begin(), manifest.scenes.end(),
                                         [&](const SceneSpec& s) { return s.file == path; });
            std::cerr << "rmfx bench: input '" << name << "': " << image.error()
                      << (sceneFile && !fs::exists(file) ? " (the build writes the sample media: cmake --build BUILD "
                                                           "--target rmfx_sample_media; or --no-scenes)"
                                                         : "")
                      << "\n";
            return std::nullopt;
        }
        inputs.push_back({uniqueName(name, inputs), file, std::move(*image)});
    }
    if (inputs.empty()) std::cerr << "rmfx bench: no inputs (--no-scenes and no --input FILE.exr)\n";
    if (inputs.empty()) return std::nullopt;
    return inputs;
}

struct StagePlan {
    const StageSpec* stage = nullptr;
    Workspace workspace;
    CheckedPrograms programs;  // validation's, handed to every variant's compile
    std::vector<Variant> variants;
};

std::optional<std::vector<StagePlan>> planStages(const BenchArguments& a, const VariantManifest& manifest) {
    for (const std::string& name : a.stages)
        if (!manifest.findStage(name)) {
            std::string known;
            for (const StageSpec& s : manifest.stages) known += (known.empty() ? "" : ", ") + s.name;
            std::cerr << "rmfx bench: --stage " << name << ": " << manifest.path.string()
                      << " has no such stage (it has: " << known << ")\n";
            return std::nullopt;
        }
    std::vector<StagePlan> plans;
    for (const StageSpec& stage : manifest.stages) {
        if (!a.stages.empty() && std::find(a.stages.begin(), a.stages.end(), stage.name) == a.stages.end()) continue;
        StagePlan plan;
        plan.stage = &stage;
        for (Variant& v : expandVariants(stage)) {
            bool wanted = a.variants.empty() || std::any_of(a.variants.begin(), a.variants.end(), [&](const std::string& s) {
                              return v.name.find(s) != std::string::npos;
                          });
            if (wanted) plan.variants.push_back(std::move(v));
        }
        if (plan.variants.empty()) continue;
        Result<Workspace> loaded = loadWorkspace(stage.workspace, {}, a.load, &plan.programs);
        if (!loaded) {
            std::cerr << "rmfx bench: stage " << stage.name << " (" << stage.where.file << ":" << stage.where.line
                      << "):\n" << formatAll(loaded.diagnostics());
            return std::nullopt;
        }
        plan.workspace = std::move(*loaded);
        plans.push_back(std::move(plan));
    }
    if (plans.empty()) {
        std::cerr << "rmfx bench: no variant matches the --stage and --variant filters\n";
        return std::nullopt;
    }
    return plans;
}

std::string utcNow() {
    std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

std::string commandLine(const std::vector<std::string>& args) {
    std::string out = "rmfx bench";
    for (const std::string& arg : args)
        out += " " + (arg.find_first_of(" \t'\"") == std::string::npos ? arg : "'" + arg + "'");
    return out;
}

bool writeText(const fs::path& file, const std::string& text) {
    Result<void> written = writeFileAtomically(file, text, false);
    if (!written) std::cerr << "rmfx bench: " << written.error() << "\n";
    return written.ok();
}

std::string sizesOf(const std::vector<BenchInput>& inputs) {
    std::string out;
    for (const BenchInput& i : inputs) {
        std::string s = std::to_string(i.image.width) + "x" + std::to_string(i.image.height);
        if (out.find(s) == std::string::npos) out += (out.empty() ? "" : ", ") + s;
    }
    return out;
}

}  // namespace

std::vector<std::string> benchOptionNames() {
    std::vector<std::string> names;
    (void)parseArguments({}, &names);
    return names;
}

int benchCommand(const std::vector<std::string>& args) {
    auto a = parseArguments(args);
    if (!a) return 1;
    startLoadingImageCodecs();  // meanwhile, the manifest and its workspaces load
    Result<VariantManifest> parsed = parseVariantManifestFile(a->manifest);
    std::cerr << formatAll(parsed.diagnostics());
    if (!parsed) {
        if (!fs::exists(a->manifest))
            std::cerr << "rmfx bench: run it in the repository root, or name the manifest (bench/variants.xml)\n";
        return 1;
    }
    const VariantManifest& manifest = *parsed;
    auto plans = planStages(*a, manifest);
    if (!plans) return 1;
    for (const fs::path& file : a->inputs)
        if (!fs::exists(file)) {
            std::cerr << "rmfx bench: input '" << file.stem().string() << "': " << file.string() << ": no such file\n";
            return 1;
        }
    if (Result<void> usable = checkOutputFolder(a->out); !usable) {
        std::cerr << "rmfx bench: --out: " << usable.error() << "\n";
        return 1;
    }

    // One context for every stage, so that their timings compare: compatibility when any asks for it.
    GlProfile profile = GlProfile::Core;
    for (const auto& plan : *plans)
        if (plan.workspace.profile == GlProfile::Compatibility) profile = GlProfile::Compatibility;
    auto context = GlContext::createHeadless(profile);
    if (!context) {
        std::cerr << "rmfx bench: " << context.error() << "\n";
        return 2;
    }
    std::error_code ec;
    fs::create_directories(a->out, ec);
    if (ec) {
        std::cerr << "rmfx bench: cannot create " << a->out.string() << ": " << ec.message() << "\n";
        return 1;
    }
    auto inputs = gatherInputs(*a, manifest);
    if (!inputs) return 1;

    BenchResults results;
    results.device = (*context)->description();
    results.size = sizesOf(*inputs);
    results.frames = a->counts.frames;
    results.warmup = a->counts.warmup;
    results.date = utcNow();
    results.command = commandLine(args);
    // Mesa's software rasterisers answer timer queries per thread (TimeSource in BenchResults.h).
    bool software = results.device.find("llvmpipe") != std::string::npos ||
                    results.device.find("softpipe") != std::string::npos;
    results.ranked = a->ranked.value_or(software ? TimeSource::Wall : TimeSource::Gpu);

    size_t total = 0, done = 0;
    for (const StagePlan& plan : *plans) total += plan.variants.size() * inputs->size();
    for (const BenchInput& input : *inputs) {
        glm::ivec2 size{input.image.width, input.image.height};
        for (const StagePlan& plan : *plans) {
            const StageSpec& stage = *plan.stage;
            auto ideal = computeStageIdeal(stage.ideal, plan.workspace, input.image);
            if (!ideal) {
                std::cerr << "rmfx bench: stage " << stage.name << ": " << ideal.error() << "\n";
                return 1;
            }
            for (const Variant& variant : plan.variants) {
                ++done;
                auto measured = measureVariant(plan.workspace, stage, variant, input.file, size, ideal->settings, a->counts,
                                               &plan.programs);
                if (!measured) {
                    std::cerr << "rmfx bench: input '" << input.name << "', " << measured.error() << "\n";
                    return 2;
                }
                auto metrics = stageMetrics(*ideal, measured->output);
                if (!metrics) {
                    std::cerr << "rmfx bench: input '" << input.name << "', stage " << stage.name << ", variant '"
                              << variant.name << "': " << metrics.error() << "\n";
                    return 2;
                }
                BenchRow row{input.name, stage.name, variant.name, variant.effect, variant.settingsText(),
                             measured->time, measured->wall, *metrics, false};
                if (!a->quiet)
                    std::cout << "[" << done << "/" << total << "] " << input.name << " " << stage.name << " "
                              << variant.name << ": GPU " << fixedText(row.time.median, 3) << " ms (p10 "
                              << fixedText(row.time.p10, 3) << ", p90 " << fixedText(row.time.p90, 3) << "), wall "
                              << fixedText(row.wall.median, 3) << " ms, mean rel. error " << numberText(row.error.meanRelative, 3) << ", max "
                              << numberText(row.error.maxRelative, 3) << ", PSNR " << fixedText(row.error.psnrDb, 2)
                              << " dB" << std::endl;
                results.rows.push_back(std::move(row));
            }
        }
    }
    addSummaryRows(results);
    markParetoFronts(results);

    std::string table = "<!-- " + results.command + " -->\n\nMeasured on " + results.device + ", inputs " +
                        results.size + ", median of " + std::to_string(results.frames) + " frames after " +
                        std::to_string(results.warmup) + " warm-up frames, " + results.date + "; time: " +
                        timeSourceTitle(results.ranked) + ". Inputs: ";
    for (size_t i = 0; i < inputs->size(); ++i) table += (i ? ", " : "") + (*inputs)[i].name;
    table += ". Times and mean errors are means over the inputs, max error the largest, PSNR the smallest; "
             "**bold**: on the Pareto front (no variant both faster and more accurate).\n" +
             resultsMarkdown(results, kAllInputs);
    bool ok = writeText(a->out / "accuracy.csv", resultsCsv(results)) &&
              writeText(a->out / "accuracy.json", resultsJson(results)) &&
              writeText(a->out / "accuracy.svg", accuracyPlotSvg(results, kAllInputs)) &&
              writeText(a->out / "accuracy.md", table);
    if (!ok) return 2;
    if (!a->quiet)
        std::cout << "bench: " << done << (done == 1 ? " measurement" : " measurements") << "; wrote "
                  << (a->out / "accuracy.csv").string() << ", .json, .svg, .md\n";
    return 0;
}

}  // namespace rmfx::cli
