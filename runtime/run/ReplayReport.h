#pragma once
// The HTML report of `rmfx replay --report DIR` (docs/replay.md): DIR/index.html, every case and
// compare with failures first; for each compare the reference, the actual render and a heat map
// of the difference with its scale, side by side, under a slider or flickering; HDR images
// tone-mapped in the page with an exposure control; the metrics against their limits; links to
// the EXR files. Plain HTML, CSS and a little JavaScript, no network, opened from the file system.
//
// Images are written as each case finishes (addCase), so a long manifest does not hold them all:
// HDR ones as PNGs in Radiance's RGBE packing (the page decodes them, so the exposure control
// works on the linear values), embedded as data: URIs in one script per case because a page
// opened from file:// may not read pixels of image files beside it; heat maps as plain PNGs.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Result.h"
#include "io/image/ImageCompare.h"
#include "model/Image.h"

namespace rmfx {

struct ReportCompare {
    std::string label;                        // "output", a target, or what a first difference names
    ImageComparison comparison;               // metrics, checks, the error image
    Image actual;
    std::filesystem::path referenceFile;      // the stored reference (EXR), read for the preview
    std::optional<std::filesystem::path> actualFile, diffFile;  // EXRs written for a failure
};

struct ReportCase {
    enum class Status { Passed, Failed, Error };
    std::string name;
    Status status = Status::Passed;
    double seconds = 0;
    std::string log;                          // the lines printed under the case
    std::vector<ReportCompare> compares;
    // From stored targets (rmfx replay --update --all-targets): the first target that differs.
    std::optional<ReportCompare> firstDifference;
    std::string firstDifferencePass;
};

class ReplayReportWriter {
public:
    // Creates DIR and DIR/img, removing the images of an earlier report there (cN-….js and .png;
    // other files in img/ are left alone).
    static Result<ReplayReportWriter> open(const std::filesystem::path& dir, std::string title);

    // Writes the case's images now and keeps what the page says about it.
    Result<void> addCase(const ReportCase& c);
    // Writes DIR/index.html: failing and broken cases first, in manifest order otherwise.
    Result<std::filesystem::path> finish(double seconds);

private:
    // What the page says about one compare once its images are written.
    struct CompareEntry {
        std::string label, id;  // id: the images' names in the page
        ImageComparison comparison;  // without its error image
        bool hasReference = false, hasActual = false;
        int width = 0, height = 0;   // of the images shown
        // The heat maps written, each at its full scale and what that scale is: one at the
        // compare's limit (what is over it shows in cyan) and, shown first when it is larger, one
        // at the largest error (where the error is).
        struct HeatMap {
            std::string file;  // relative to DIR
            double scale = 0;
            std::string meaning;
        };
        std::vector<HeatMap> heatMaps;
        std::string referenceLink, actualLink, diffLink;  // relative to DIR; empty: none
    };
    struct CaseEntry {
        ReportCase::Status status = ReportCase::Status::Passed;
        std::string name, log, firstDifferencePass;
        double seconds = 0;
        std::vector<CompareEntry> compares;
        std::optional<CompareEntry> firstDifference;
    };

    ReplayReportWriter() = default;
    Result<CompareEntry> writeCompare(const ReportCompare& compare, const std::string& id, std::string& script);
    std::string link(const std::filesystem::path& file) const;

    std::filesystem::path dir_;
    std::string title_;
    std::vector<CaseEntry> cases_;
};

}  // namespace rmfx
