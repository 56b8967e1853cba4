// The bench's result files (bench/accuracy/ResultWriters.h, AccuracyPlot.h): CSV and JSON hold
// the measured numbers (an infinite PSNR as "inf" and null), the markdown table and the SVG plot
// show every variant and mark the Pareto front.

#include <cmath>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include "bench/accuracy/AccuracyPlot.h"
#include "bench/accuracy/ResultWriters.h"
#include "tests/support/JsonValue.h"

namespace rmfx::accuracy {
namespace {

BenchResults sample() {
    BenchResults r;
    r.device = "4.5 (Core Profile) Mesa, llvmpipe \"test\"";
    r.size = "64x32";
    r.frames = 7;
    r.warmup = 2;
    r.date = "2026-01-02T03:04:05Z";
    r.command = "rmfx bench --frames 7";
    BenchRow a;
    a.input = "scene";
    a.stage = "bloom";
    a.variant = "dual_filter Downsample=1/4";
    a.effects = "dual_filter";
    a.settings = "Downsample=1 Target_Format=1";
    a.time = {7, 1.25, 1.0, 1.5, 0.875, 2.0};
    a.wall = {7, 10.5, 10.0, 12.0, 9.0, 13.0};
    a.error = {0.5, 0.0123456789, 38.25};
    a.pareto = true;
    BenchRow b = a;
    b.variant = "gauss49, exact";  // a comma: quoted in CSV
    b.time = {7, 3.0, 2.5, 3.5, 2.0, 4.0};
    b.error = {0.0, 0.0, std::numeric_limits<double>::infinity()};
    r.rows = {a, b};
    return r;
}

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

TEST(BenchResultWriters, CsvHasTheDocumentedColumnsAndInfForAnInfinitePsnr) {
    std::vector<std::string> csv = linesOf(resultsCsv(sample()));
    ASSERT_EQ(csv.size(), 3u);
    EXPECT_EQ(csv[0],
              "input,stage,variant,effects,settings,frames,median_ms,p10_ms,p90_ms,min_ms,max_ms,max_rel_error,"
              "mean_rel_error,psnr_db,pareto,wall_median_ms,wall_p10_ms,wall_p90_ms");
    EXPECT_EQ(csv[1],
              "scene,bloom,dual_filter Downsample=1/4,dual_filter,Downsample=1 Target_Format=1,7,1.2500,1.0000,1.5000,"
              "0.8750,2.0000,0.5,0.0123457,38.250,1,10.5000,10.0000,12.0000");
    EXPECT_EQ(csv[2],
              "scene,bloom,\"gauss49, exact\",dual_filter,Downsample=1 Target_Format=1,7,3.0000,2.5000,3.5000,2.0000,"
              "4.0000,0,0,inf,1,10.5000,10.0000,12.0000");
}

TEST(BenchResultWriters, JsonParsesAndHoldsTheRunAndEveryRow) {
    std::string text = resultsJson(sample());
    auto json = test::JsonReader::parse(text);
    ASSERT_TRUE(json) << text;
    EXPECT_EQ((*json)["device"].string, "4.5 (Core Profile) Mesa, llvmpipe \"test\"");
    EXPECT_EQ((*json)["size"].string, "64x32");
    EXPECT_EQ((*json)["frames"].number, 7);
    EXPECT_EQ((*json)["warmup"].number, 2);
    EXPECT_EQ((*json)["date"].string, "2026-01-02T03:04:05Z");
    EXPECT_EQ((*json)["ranked_time"].string, "gpu");
    const auto& rows = (*json)["rows"].array;
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0]["median_ms"].number, 1.25);
    EXPECT_EQ(rows[0]["p10_ms"].number, 1.0);
    EXPECT_NEAR(rows[0]["mean_rel_error"].number, 0.0123456789, 1e-12);
    EXPECT_EQ(rows[0]["psnr_db"].number, 38.25);
    EXPECT_TRUE(rows[0]["pareto"].boolean);
    EXPECT_EQ(rows[0]["wall_median_ms"].number, 10.5);
    EXPECT_EQ(rows[0]["wall_p90_ms"].number, 12.0);
    EXPECT_EQ(rows[1]["variant"].string, "gauss49, exact");
    EXPECT_EQ(rows[1]["psnr_db"].kind, test::JsonValue::Kind::Null);
}

TEST(BenchResultWriters, MarkdownTableBoldsTheFront) {
    BenchResults r = sample();
    r.rows[1].pareto = false;
    std::string md = resultsMarkdown(r, "scene");
    EXPECT_NE(md.find("**bloom**"), std::string::npos);
    EXPECT_NE(md.find("| **dual_filter Downsample=1/4** | Downsample=1 Target_Format=1 | 1.250 | 1.000–1.500 | 0.5 | "
                      "0.0123 | 38.25 |"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("| gauss49, exact |"), std::string::npos) << md;
    EXPECT_NE(md.find("| inf |"), std::string::npos) << md;
    EXPECT_EQ(resultsMarkdown(r, "other").find("| dual"), std::string::npos);
    r.ranked = TimeSource::Wall;  // the table shows the time that ranks
    EXPECT_NE(resultsMarkdown(r, "scene").find("| wall median ms |"), std::string::npos);
    EXPECT_NE(resultsMarkdown(r, "scene").find("| 10.500 | 10.000–12.000 |"), std::string::npos);
}

TEST(BenchResultWriters, SvgPlotIsWellFormedWithOneDotPerVariantAndTheCapSaid) {
    std::string svg = accuracyPlotSvg(sample(), "scene");
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    size_t dots = 0;
    for (size_t at = 0; (at = svg.find("<circle", at)) != std::string::npos; ++at) ++dots;
    EXPECT_EQ(dots, 2u);
    EXPECT_NE(svg.find("≥100 dB"), std::string::npos);  // the infinite PSNR, capped and said
    EXPECT_NE(svg.find("PSNR above 100 dB"), std::string::npos);
    EXPECT_NE(svg.find("<polyline"), std::string::npos);  // the front's step line
    EXPECT_NE(svg.find("median GPU time per frame (timer queries), ms (log scale)"), std::string::npos);
    EXPECT_NE(svg.find("llvmpipe &quot;test&quot;"), std::string::npos);  // escaped
}

}  // namespace
}  // namespace rmfx::accuracy
