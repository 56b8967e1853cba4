#include "python/PyReplay.h"

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "frontend/replay/ReplayManifest.h"
#include "gl/HeadlessContexts.h"
#include "python/Arrays.h"
#include "python/Errors.h"
#include "run/ReplayRun.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace rmfx::python {

namespace {

struct CompareResult {
    std::string label;      // "output" or the target
    std::string reference;  // the stored image's path
    bool updated = false;   // update=True wrote the reference instead of comparing
    ImageComparison comparison;
    Image actual;
};

struct CaseResult {
    std::string name;
    std::string status;  // "passed", "failed", "error", "updated"
    double seconds = 0.0;
    Diagnostics diagnostics;
    std::vector<CompareResult> compares;
};

struct ReplayReport {
    std::string manifest;
    std::vector<CaseResult> cases;
    bool passed() const {
        for (const CaseResult& c : cases)
            if (c.status == "failed" || c.status == "error") return false;
        return true;
    }
};

std::string fspath(const py::object& path) { return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>(); }

ReplayManifest parseManifest(const py::object& path) {
    Result<ReplayManifest> manifest = parseReplayManifestFile(fspath(path));
    if (!manifest) fail(manifest.takeDiagnostics());
    return std::move(*manifest);
}

CaseResult runCase(const ReplayCase& c, const MediaOptions& media, HeadlessContexts& contexts, bool update) {
    CaseResult result;
    result.name = c.name;
    const auto start = std::chrono::steady_clock::now();
    Result<std::vector<Image>> images = renderReplayCase(c, media, &contexts);
    result.diagnostics = images.diagnostics();
    if (!images) {
        result.status = "error";
    } else {
        result.status = update ? "updated" : "passed";
        for (size_t i = 0; i < c.compares.size(); ++i) {
            const ReplayCompare& compare = c.compares[i];
            CompareResult r{compare.label(), compare.reference.string(), update, {}, std::move((*images)[i])};
            if (update) {
                if (Result<void> written = storeReference(r.actual, compare); !written) {
                    result.diagnostics.push_back({Diagnostic::Severity::Error, compare.where, compare.label(), written.error()});
                    result.status = "error";
                }
            } else {
                r.comparison = compareWithReference(r.actual, compare);
                if (!r.comparison.passed()) result.status = "failed";
            }
            result.compares.push_back(std::move(r));
        }
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

std::string describeCase(const CaseResult& c) {
    std::string text = c.name + ": " + c.status;
    for (const CompareResult& r : c.compares)
        if (!r.updated) text += "\n  " + r.label + ": " + (r.comparison.passed() ? "ok (" : "FAILED: ") + r.comparison.describe() +
                                (r.comparison.passed() ? ")" : "");
    for (const Diagnostic& d : c.diagnostics)
        if (d.severity == Diagnostic::Severity::Error) text += "\n  " + d.format();
    return text;
}

}  // namespace

void bindReplay(py::module_& m) {
    py::class_<CompareResult>(m, "ReplayCompare", "One <compare> of a replayed case: the image rendered against its reference.")
        .def_readonly("label", &CompareResult::label, "'output' or the target compared")
        .def_readonly("reference", &CompareResult::reference, "the stored reference image's path")
        .def_property_readonly("passed", [](const CompareResult& r) { return r.updated || r.comparison.passed(); })
        .def_property_readonly("problem", [](const CompareResult& r) -> py::object {
            return r.comparison.problem.empty() ? py::object(py::none()) : py::object(py::str(r.comparison.problem));
        }, "what no limit allows (sizes, channels, a NaN against a number), or None")
        .def_property_readonly("max_error", [](const CompareResult& r) { return r.comparison.metrics.maxError; })
        .def_property_readonly("max_error_at", [](const CompareResult& r) {
            const CompareMetrics& m = r.comparison.metrics;
            return py::make_tuple(m.maxX, m.maxY, m.maxChannel);
        }, "(x, y, channel) of the largest error, row 0 at the top")
        .def_property_readonly("mean_error", [](const CompareResult& r) { return r.comparison.metrics.meanError; })
        .def_property_readonly("percentile_error", [](const CompareResult& r) { return r.comparison.metrics.percentileError; })
        .def_property_readonly("fail_fraction", [](const CompareResult& r) { return r.comparison.metrics.failFraction(); })
        .def_property_readonly("checks", [](const CompareResult& r) {
            py::list checks;
            for (const LimitCheck& c : r.comparison.checks)
                checks.append(py::make_tuple(r.comparison.checkName(c), c.value, c.limit, c.passed()));
            return checks;
        }, "(what, measured, allowed, passed) for each limit of the <compare>")
        .def_property_readonly("description", [](const CompareResult& r) { return r.comparison.describe(); })
        .def_property_readonly("actual", [](const CompareResult& r) { return arrayFromImage(r.actual); },
                               "the rendered image, float32 (height, width, channels), row 0 at the top")
        .def_property_readonly("difference", [](const CompareResult& r) -> py::object {
            if (r.comparison.difference.empty()) return py::none();
            return arrayFromImage(r.comparison.difference);
        }, "the error image (one channel per channel, or ΔE_ITP), or None")
        .def("__repr__", [](const CompareResult& r) {
            return "<rmfx.ReplayCompare " + r.label + ": " + (r.updated ? "updated" : r.comparison.passed() ? "ok" : "FAILED") + ">";
        });

    py::class_<CaseResult>(m, "ReplayCase", "A replayed case of a manifest.")
        .def_readonly("name", &CaseResult::name)
        .def_readonly("status", &CaseResult::status, "'passed', 'failed', 'error' (it did not render) or 'updated'")
        .def_property_readonly("passed", [](const CaseResult& c) { return c.status == "passed" || c.status == "updated"; })
        .def_readonly("seconds", &CaseResult::seconds)
        .def_readonly("diagnostics", &CaseResult::diagnostics, "the workspace's and the render's errors and warnings")
        .def_readonly("compares", &CaseResult::compares)
        .def_property_readonly("description", &describeCase, "what rmfx replay prints for it")
        .def("__repr__", [](const CaseResult& c) { return "<rmfx.ReplayCase " + c.name + ": " + c.status + ">"; });

    py::class_<ReplayReport>(m, "ReplayReport", "What rmfx.replay found: every case run, in manifest order.")
        .def_readonly("manifest", &ReplayReport::manifest)
        .def_readonly("cases", &ReplayReport::cases)
        .def_property_readonly("passed", &ReplayReport::passed, "no case failed or failed to render")
        .def("__getitem__", [](const ReplayReport& r, const std::string& name) -> const CaseResult& {
            for (const CaseResult& c : r.cases)
                if (c.name == name) return c;
            fail("the report has no case '" + name + "'", "case " + name);
        }, py::return_value_policy::reference_internal)
        .def("__repr__", [](const ReplayReport& r) {
            return "<rmfx.ReplayReport " + r.manifest + ": " + std::to_string(r.cases.size()) + " cases, " +
                   (r.passed() ? "passed" : "FAILED") + ">";
        });

    m.def("replay_cases", [](const py::object& manifest) {
        std::vector<std::string> names;
        for (const ReplayCase& c : parseManifest(manifest).cases) names.push_back(c.name);
        return names;
    }, py::arg("manifest"), "replay_cases(manifest) -> [str]: the names of its cases, in order (nothing rendered)");

    m.def("replay", [](const py::object& manifestPath, std::optional<std::vector<std::string>> cases,
                       const std::vector<py::object>& media, const std::string& missingMedia, bool update) {
        if (missingMedia != "error" && missingMedia != "placeholder")
            fail("missing_media: expected 'error' or 'placeholder', got '" + missingMedia + "'", "missing_media");
        const ReplayManifest manifest = parseManifest(manifestPath);
        std::vector<const ReplayCase*> chosen;
        if (cases) {
            for (const std::string& name : *cases) {
                const ReplayCase* c = manifest.findCase(name);
                if (!c) fail("the manifest has no case '" + name + "'", "case " + name);  // before any case renders
                chosen.push_back(c);
            }
        } else {
            for (const ReplayCase& c : manifest.cases) chosen.push_back(&c);
        }
        MediaOptions options = manifest.media;
        for (const py::object& folder : media) options.searchPath.emplace_back(fspath(folder));
        options.missing = missingMedia == "placeholder" ? MissingMedia::Placeholder : MissingMedia::Error;
        ReplayReport report;
        report.manifest = manifest.path.string();
        HeadlessContexts contexts;
        for (const ReplayCase* c : chosen) report.cases.push_back(runCase(*c, options, contexts, update));
        return report;
    }, py::arg("manifest"), py::kw_only(), py::arg("cases") = py::none(), py::arg("media") = std::vector<py::object>{},
    py::arg("missing_media") = "error", py::arg("update") = false,
    "replay(manifest, *, cases=None, media=[], missing_media='error', update=False) -> ReplayReport\n\n"
    "Runs the cases of an rmfx replay manifest (all, or the names given) as rmfx replay does, in this process: each "
    "case's workspace rendered headless and every <compare> measured against its stored reference with its limits. "
    "A case that fails to render is status 'error' with its diagnostics, and the others still run. update=True stores "
    "the rendered images as the references instead (rmfx replay --update). Raises rmfx.Error only for the manifest "
    "itself (unreadable, invalid, an unknown case name).");
}

}  // namespace rmfx::python
