// rmfx replay MANIFEST: renders each case of a replay manifest and compares its images with the
// stored references (or, with --update, stores them as the references). docs/replay.md.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>

#include "apps/ArgumentParser.h"
#include "cli/Commands.h"
#include "apps/OptionValues.h"
#include "core/FrameWatchdog.h"
#include "frontend/replay/ReplayManifest.h"
#include "gl/GlContext.h"
#include "io/file/OutputPath.h"
#include "io/image/ImageIO.h"
#include "io/media/MediaArguments.h"
#include "io/xml/JUnitReport.h"
#include "run/ReplayReport.h"
#include "run/ReplayRun.h"
#include "io/image/ImageCodecs.h"

namespace rmfx::cli {

using namespace rmfx::apps;  // the shared argument loop and option values
namespace {

namespace fs = std::filesystem;

struct ReplayArguments {
    std::optional<std::string> manifest;
    fs::path out = "replay-out";
    std::optional<fs::path> junit;
    std::optional<fs::path> report;  // --report DIR: DIR/index.html
    std::vector<std::string> cases;
    bool update = false;
    bool allTargets = false;  // with --update: store every target too, to name the pass that broke
    bool quiet = false;
    double frameBudget = kDefaultFrameBudgetSeconds;
    std::vector<fs::path> media;   // --media, after the manifest's <media> folders
    std::optional<bool> sandbox;   // --sandbox / --no-sandbox; nullopt: the manifest's choice (default on)
    MissingMedia missing = MissingMedia::Error;  // --missing-media
};

// With `names`, fills it with the parser's option names and parses nothing.
std::optional<ReplayArguments> parseArguments(const std::vector<std::string>& args, std::vector<std::string>* names = nullptr) {
    ReplayArguments a;
    auto fail = [](const std::string& message) -> std::optional<ReplayArguments> {
        std::cerr << "rmfx replay: " << message << "\n";
        return std::nullopt;
    };
    ArgumentParser parser;
    parser.own([&](const std::vector<std::string>& all, size_t& i) {
              MediaOptions media;
              const std::string& arg = all[i];
              auto taken = takeMediaArgument(all, i, media);
              if (taken && taken->empty()) {
                  if (arg == "--media") a.media.push_back(media.searchPath[0]);
                  else if (arg.rfind("--missing-media", 0) == 0) a.missing = media.missing;
                  else a.sandbox = media.sandbox;
              }
              return taken;
          }, kMediaOptionNames)
        .option({"--out"}, [&](const std::string& value) { a.out = value; return ""; })
        .option({"--junit"}, [&](const std::string& value) { a.junit = value; return ""; })
        .option({"--report"}, [&](const std::string& value) { a.report = value; return ""; })
        .option({"--case"}, [&](const std::string& value) { a.cases.push_back(value); return ""; })
        .option({"--frame-budget"}, [&](const std::string& value) -> std::string {
            char* end = nullptr;
            a.frameBudget = std::strtod(value.c_str(), &end);
            if (*end || !std::isfinite(a.frameBudget) || a.frameBudget < 0)
                return "--frame-budget: expected seconds ≥ 0 (0: no limit), got '" + value + "'";
            return "";
        })
        .flag({"--update"}, [&] { a.update = true; })
        .flag({"--all-targets"}, [&] { a.allTargets = true; })
        .flag({"-q", "--quiet"}, [&] { a.quiet = true; })
        .positional([&](const std::string& arg) -> std::string {
            if (a.manifest) return "one manifest at a time; got '" + *a.manifest + "' and '" + arg + "'";
            a.manifest = arg;
            return "";
        });
    if (names) {
        *names = parser.names();
        return std::nullopt;
    }
    if (std::string message = parser.parse(args); !message.empty()) return fail(message);
    if (!a.manifest) return fail("name a manifest file (see rmfx --help and docs/replay.md)");
    if (a.report && a.update)
        return fail("--report shows what a replay compared; --update compares nothing (run the replay after it)");
    if (a.allTargets && !a.update)
        return fail("--all-targets goes with --update: it stores every target of each case, and a replay without "
                    "it uses what was stored");
    return a;
}

// The cases --case names, in manifest order; all without --case. nullopt (reported) when a name
// is not in the manifest.
std::optional<std::vector<const ReplayCase*>> selectCases(const ReplayManifest& manifest,
                                                          const std::vector<std::string>& names) {
    std::vector<const ReplayCase*> selected;
    for (const std::string& name : names) {
        if (manifest.findCase(name)) continue;
        std::string known;
        for (const ReplayCase& c : manifest.cases) known += (known.empty() ? "" : ", ") + c.name;
        std::cerr << "rmfx replay: --case " << name << ": " << manifest.path.string() << " has no such case (it has: "
                  << known << ")\n";
        return std::nullopt;
    }
    for (const ReplayCase& c : manifest.cases)
        if (names.empty() || std::find(names.begin(), names.end(), c.name) != names.end()) selected.push_back(&c);
    return selected;
}

std::string channelsAndSize(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height) + ", " + std::to_string(image.channels) +
           (image.channels == 1 ? " channel" : " channels");
}

// What became of one case: the lines printed under it, the line for the JUnit report, counts.
struct CaseOutcome {
    JUnitTestCase::Outcome outcome = JUnitTestCase::Outcome::Passed;
    std::string message;  // one line: why it failed
    int comparesPassed = 0, comparesFailed = 0, comparesNotRun = 0;
    int referencesWritten = 0;
    ReportCase page;  // with --report: the compares' images and metrics

    bool passed() const { return outcome == JUnitTestCase::Outcome::Passed; }
    // A line under the case's progress line; `onFailure`: shown only when the case fails (the
    // metrics of a compare that passed, next to one that did not).
    void line(const std::string& text, bool onFailure = false) { lines_.push_back({"    " + text + "\n", onFailure}); }
    void fail(JUnitTestCase::Outcome why, const std::string& text) {
        outcome = why;
        message += (message.empty() ? "" : " | ") + text;
    }
    // The lines to show: all of them when the case failed.
    std::string report() const {
        std::string out;
        for (const auto& [text, onFailure] : lines_)
            if (!onFailure || !passed()) out += text;
        return out;
    }

private:
    std::vector<std::pair<std::string, bool>> lines_;
};

class ReplayRunner {
public:
    ReplayRunner(const ReplayArguments& a, HeadlessContexts& contexts, MediaOptions media, fs::path manifestFolder)
        : a_(a), contexts_(contexts), media_(std::move(media)), manifestFolder_(std::move(manifestFolder)) {}

    CaseOutcome run(const ReplayCase& c) {
        CaseOutcome o;
        Result<std::vector<Image>> render = renderReplayCase(c, media_, &contexts_);
        for (const Diagnostic& d : render.diagnostics())
            if (d.severity == Diagnostic::Severity::Error || !a_.quiet) o.line(d.format());
        if (!render) {
            for (const Diagnostic& d : render.diagnostics())
                if (d.severity == Diagnostic::Severity::Error) {
                    o.fail(JUnitTestCase::Outcome::Error, d.format());
                    break;
                }
            o.comparesNotRun = static_cast<int>(c.compares.size());
            return o;
        }
        const CompareLimits* failedLimits = nullptr;
        for (size_t i = 0; i < c.compares.size(); ++i) {
            if (a_.update) update(c.compares[i], (*render)[i], o);
            else if (!compare(c, c.compares[i], (*render)[i], o) && !failedLimits) failedLimits = &c.compares[i].limits;
        }
        // Stored targets are kept current by every --update once a case has them.
        if (a_.update && o.passed() && (a_.allTargets || fs::is_directory(caseTargetsFolder(c)))) updateTargets(c, o);
        if (failedLimits) findBrokenPass(c, *failedLimits, o);
        return o;
    }

private:
    void update(const ReplayCompare& compare, const Image& image, CaseOutcome& o) {
        if (auto written = storeReference(image, compare); !written) {
            o.line(compare.label() + ": " + written.error());
            o.fail(JUnitTestCase::Outcome::Error, compare.label() + ": " + written.error());
            ++o.comparesFailed;
            return;
        }
        o.line("wrote " + compare.reference.string() + " (" + compare.label() + ", " + channelsAndSize(image) + ", " +
               (compare.storeHalf ? "half" : "float") + ")");
        ++o.referencesWritten;
    }

    // --all-targets: every target of the case, in a folder of their own that holds nothing else.
    void updateTargets(const ReplayCase& c, CaseOutcome& o) {
        Result<std::vector<CaseTarget>> targets = renderReplayTargets(c, media_, &contexts_);
        fs::path folder = caseTargetsFolder(c);
        auto failed = [&](const std::string& message) {
            o.line(message);
            o.fail(JUnitTestCase::Outcome::Error, message);
        };
        if (!targets) {
            for (const Diagnostic& d : targets.diagnostics())
                if (d.severity == Diagnostic::Severity::Error) return failed("all targets: " + d.format());
            return failed("all targets: the case did not render");
        }
        std::error_code ec;
        fs::remove_all(folder, ec);
        fs::create_directories(folder, ec);
        if (ec) return failed(folder.string() + ": cannot create the folder: " + ec.message());
        std::string names;
        for (const CaseTarget& t : *targets) {
            if (auto written = writeImage(caseTargetFile(c, t.target), t.image); !written) return failed(written.error());
            names += (names.empty() ? "" : ", ") + t.target;
        }
        o.line("wrote " + relativeToManifest(folder) + " (" + std::to_string(targets->size()) +
               (targets->size() == 1 ? " target: " : " targets, in pass order: ") + names + ")");
    }

    // After a failed compare: with stored targets, the first one that differs names the pass that broke.
    void findBrokenPass(const ReplayCase& c, const CompareLimits& limits, CaseOutcome& o) {
        fs::path folder = caseTargetsFolder(c);
        if (!fs::is_directory(folder)) {
            o.line("which pass broke: no targets stored in " + relativeToManifest(folder) +
                   " (rmfx replay --update --all-targets stores them)");
            return;
        }
        Result<std::vector<CaseTarget>> targets = renderReplayTargets(c, media_, &contexts_);
        if (!targets) {
            o.line("which pass broke: the case did not render with every target kept");
            for (const Diagnostic& d : targets.diagnostics())
                if (d.severity == Diagnostic::Severity::Error) o.line("  " + d.format());
            return;
        }
        FirstDifference first = findFirstDifference(c, *targets, limits);
        if (!first.unstored.empty()) {
            std::string names;
            for (const std::string& t : first.unstored) names += (names.empty() ? "" : ", ") + t;
            o.line("which pass broke: no stored reference for " + names + " (stored before the workspace changed?)");
        }
        if (!first.target) {
            o.line("which pass broke: every stored target matches (" + std::to_string(first.matched.size()) +
                   " compared): only what the compares read differs");
            return;
        }
        const CaseTarget& t = *first.target;
        std::string before = first.matched.empty() ? "none" : "";
        for (const std::string& m : first.matched) before += (before.empty() ? "" : ", ") + m;
        o.line("first difference: pass '" + t.pass + "' writing target '" + t.target + "' (" +
               std::to_string(first.position) + " of " + std::to_string(targets->size()) + " targets in pass order): " +
               first.comparison.describe());
        o.line("  targets before it that match: " + before);
        o.fail(JUnitTestCase::Outcome::Failed, "first difference at pass '" + t.pass + "' (target '" + t.target + "')");
        fs::path out = a_.out / c.name / "targets";
        std::error_code ignored;
        fs::create_directories(out, ignored);
        ReportCompare shown{t.target, first.comparison, t.image, caseTargetFile(c, t.target), std::nullopt, std::nullopt};
        if (!first.comparison.difference.empty() &&
            writeFailureImage("diff:  ", out / (t.target + ".diff.exr"), first.comparison.difference, o))
            shown.diffFile = out / (t.target + ".diff.exr");
        if (writeFailureImage("actual:", out / (t.target + ".actual.exr"), t.image, o))
            shown.actualFile = out / (t.target + ".actual.exr");
        if (a_.report) {
            o.page.firstDifference = std::move(shown);
            o.page.firstDifferencePass = t.pass;
        }
    }

    // A path under the manifest's folder as the manifest would write it; others whole.
    std::string relativeToManifest(const fs::path& path) const {
        std::error_code ec;
        fs::path relative = fs::relative(path, manifestFolder_, ec);
        if (ec || relative.empty() || *relative.begin() == "..") return path.string();
        return relative.generic_string() + "/";
    }

    // Whether the compare passed.
    bool compare(const ReplayCase& c, const ReplayCompare& compare, const Image& image, CaseOutcome& o) {
        ImageComparison result = compareWithReference(image, compare);
        fs::path folder = a_.out / c.name;
        fs::path diffFile = folder / (compare.label() + ".diff.exr");
        fs::path actualFile = folder / (compare.label() + ".actual.exr");
        // Images of an earlier failure must not outlive it.
        std::error_code ignored;
        fs::remove(diffFile, ignored);
        fs::remove(actualFile, ignored);
        fs::remove_all(folder / "targets", ignored);
        ReportCompare* shown = nullptr;
        if (a_.report) {
            o.page.compares.push_back({compare.label(), result, image, compare.reference, std::nullopt, std::nullopt});
            shown = &o.page.compares.back();
        }
        if (result.passed()) {
            ++o.comparesPassed;
            o.line(compare.label() + ": ok (" + result.describe() + ")", true);
            fs::remove(folder, ignored);  // only when empty
            return true;
        }
        ++o.comparesFailed;
        o.line(compare.label() + ": FAILED: " + result.describe());
        o.fail(JUnitTestCase::Outcome::Failed, compare.label() + ": " + result.describe());
        fs::create_directories(folder, ignored);
        if (!result.difference.empty() && writeFailureImage("diff:  ", diffFile, result.difference, o) && shown)
            shown->diffFile = diffFile;
        if (writeFailureImage("actual:", actualFile, image, o) && shown) shown->actualFile = actualFile;
        return false;
    }

    // Whether it was written.
    bool writeFailureImage(const std::string& what, const fs::path& file, const Image& image, CaseOutcome& o) {
        if (auto written = writeImage(file, image); !written) {
            o.line("  " + what + " " + written.error());
            return false;
        }
        o.line("  " + what + " " + file.string());
        return true;
    }

    const ReplayArguments& a_;
    HeadlessContexts& contexts_;
    MediaOptions media_;
    fs::path manifestFolder_;
};

}  // namespace

std::vector<std::string> replayOptionNames() {
    std::vector<std::string> names;
    (void)parseArguments({}, &names);
    return names;
}

int replayCommand(const std::vector<std::string>& args) {
    auto a = parseArguments(args);
    if (!a) return 1;
    startLoadingImageCodecs();  // meanwhile, the manifest and its workspaces load
    // Where the results go is checked before any case renders. The JUnit report's folder is
    // created when missing, as --out and --report are.
    auto junitUsable = [&]() -> Result<void> {
        if (!a->junit) return {};
        std::error_code ec;
        if (fs::is_directory(*a->junit, ec)) return Error{"'" + a->junit->string() + "' is a folder, not a file"};
        return checkOutputFolder(a->junit->has_parent_path() ? a->junit->parent_path() : fs::path("."));
    };
    for (auto [option, usable] : {std::pair{"--out", checkOutputFolder(a->out)},
                                  std::pair{"--junit", junitUsable()},
                                  std::pair{"--report", a->report ? checkOutputFolder(*a->report) : Result<void>()}}) {
        if (!usable) {
            std::cerr << "rmfx replay: " << option << ": " << usable.error() << "\n";
            return 1;
        }
    }
    Result<ReplayManifest> parsed = parseReplayManifestFile(*a->manifest);
    std::cerr << formatAll(parsed.diagnostics());
    if (!parsed) return 1;
    const ReplayManifest& manifest = *parsed;
    auto cases = selectCases(manifest, a->cases);
    if (!cases) return 1;

    // Each case runs in the context of its workspace's profile; the core one must open.
    HeadlessContexts contexts;
    auto context = contexts.use(GlProfile::Core);
    if (!context) {
        std::cerr << "rmfx replay: " << context.error() << "\n";
        return 2;
    }

    using Clock = std::chrono::steady_clock;
    auto started = Clock::now();
    JUnitTestSuite suite;
    suite.name = "rmfx replay " + manifest.path.string();
    int casesFailed = 0, comparesPassed = 0, comparesFailed = 0, comparesNotRun = 0, referencesWritten = 0;
    MediaOptions media = manifest.media;
    media.searchPath.insert(media.searchPath.end(), a->media.begin(), a->media.end());
    media.sandbox = a->sandbox.value_or(media.sandbox);
    media.missing = a->missing;
    ReplayRunner runner(*a, contexts, std::move(media), manifest.folder);
    std::optional<ReplayReportWriter> report;
    int status = 0;
    if (a->report) {
        auto opened = ReplayReportWriter::open(*a->report, manifest.path.string());
        if (!opened) {
            std::cerr << "rmfx replay: --report: " << opened.error() << "\n";
            return 1;
        }
        report = std::move(*opened);
    }
    for (size_t i = 0; i < cases->size(); ++i) {
        const ReplayCase& c = *(*cases)[i];
        std::string progress = "[" + std::to_string(i + 1) + "/" + std::to_string(cases->size()) + "] " + c.name + " ... ";
        if (!a->quiet) std::cout << progress << std::flush;
        auto caseStarted = Clock::now();
        // A frame past its budget cannot be interrupted: record the case as an error, write the
        // report so far, and stop.
        ReplayCase budgeted = c;
        budgeted.run.frameBudgetSeconds = a->frameBudget;
        budgeted.run.onFrameBudget = [&](const std::string& message) {
            double seconds = std::chrono::duration<double>(Clock::now() - caseStarted).count();
            if (a->quiet) std::cout << progress;
            std::cout << "FAILED\n  " << message << "\n" << std::flush;
            suite.cases.push_back({c.name, "replay." + manifest.path.stem().string(), seconds,
                                   JUnitTestCase::Outcome::Error, message, message});
            suite.seconds = std::chrono::duration<double>(Clock::now() - started).count();
            if (a->junit) (void)writeJUnit(*a->junit, suite);
            std::cerr << "rmfx replay: error: case '" << c.name << "': " << message
                      << "; stopping, the cases after it did not run\n" << std::flush;
            std::_Exit(kExitFrameBudget);
        };
        CaseOutcome o = runner.run(budgeted);
        double seconds = std::chrono::duration<double>(Clock::now() - caseStarted).count();
        bool passed = o.passed();
        char time[32];
        std::snprintf(time, sizeof time, " (%.2f s)\n", seconds);
        if (a->quiet && !passed) std::cout << progress;
        if (!a->quiet || !passed)
            std::cout << (passed ? (a->update ? "updated" : "ok") : "FAILED") << time << o.report() << std::flush;
        casesFailed += passed ? 0 : 1;
        comparesPassed += o.comparesPassed;
        comparesFailed += o.comparesFailed;
        comparesNotRun += o.comparesNotRun;
        referencesWritten += o.referencesWritten;
        suite.cases.push_back({c.name, "replay." + manifest.path.stem().string(), seconds, o.outcome, o.message, o.report()});
        if (report) {
            o.page.name = c.name;
            o.page.seconds = seconds;
            o.page.log = o.report();
            o.page.status = passed ? ReportCase::Status::Passed
                              : o.outcome == JUnitTestCase::Outcome::Error ? ReportCase::Status::Error
                                                                            : ReportCase::Status::Failed;
            if (auto added = report->addCase(o.page); !added) {
                std::cerr << "rmfx replay: --report: " << added.error() << "\n";
                status = 1;
            }
        }
    }
    suite.seconds = std::chrono::duration<double>(Clock::now() - started).count();

    int total = static_cast<int>(cases->size());
    if (!a->quiet) {
        std::cout << "replay: " << (total - casesFailed) << " of " << total << (total == 1 ? " case" : " cases")
                  << " passed, " << casesFailed << " failed; ";
        if (a->update)
            std::cout << referencesWritten << (referencesWritten == 1 ? " reference" : " references") << " written";
        else
            std::cout << comparesPassed << " of " << (comparesPassed + comparesFailed + comparesNotRun)
                      << " compares passed, " << comparesFailed << " failed";
        if (comparesNotRun > 0) std::cout << ", " << comparesNotRun << " not run";
        std::cout << "\n";
    }
    if (casesFailed > 0) status = 1;
    if (report) {
        if (auto written = report->finish(suite.seconds); !written) {
            std::cerr << "rmfx replay: --report: " << written.error() << "\n";
            status = 1;
        } else if (!a->quiet) {
            std::cout << "replay: wrote " << written->string() << "\n";
        }
    }
    if (a->junit) {
        if (auto written = writeJUnit(*a->junit, suite); !written) {
            std::cerr << "rmfx replay: " << written.error() << "\n";
            status = 1;
        } else if (!a->quiet) {
            std::cout << "replay: wrote " << a->junit->string() << "\n";
        }
    }
    return status;
}

}  // namespace rmfx::cli
