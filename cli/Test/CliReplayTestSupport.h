#pragma once
// What the `rmfx replay` tests share: a tiny workspace and manifest in a scratch folder (a Project),
// its references written with --update, and the images and JUnit reports a replay leaves.

#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "io/image/ImageIO.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test::cli_replay {

namespace fs = std::filesystem;

// 16x16 by default. `base` holds (u, v, blue, 1) with u, v the pixel centre's texture coordinate:
// (x + 0.5) / 16 = (2x + 1) / 32, exact in half and float. The output is base.rgb · Gain.
inline std::string tinyWorkspace(const std::string& blue = "0.25") {
    return R"(<workspace version="1" name="tiny" size="16x16">
  <float name="Gain" value="1"/>
  <target name="base" format="rgba32f" scale="1"/>
  <pass name="gradient" target="base">
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform vec2 rm_InvTargetSize;
out vec4 fragColor;
void main() { fragColor = vec4(gl_FragCoord.xy * rm_InvTargetSize, )" +
           blue + R"(, 1.0); }
]]></shader>
  </pass>
  <pass name="final">
    <sampler name="src" target="base" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
#version 450 core
uniform sampler2D src;
uniform float Gain;
out vec4 fragColor;
void main() { fragColor = vec4(texelFetch(src, ivec2(gl_FragCoord.xy), 0).rgb * Gain, 1.0); }
]]></shader>
  </pass>
</workspace>
)";
}

inline std::string tinyManifest(const std::string& gain = "1") {
    return lines({
        "<replay version=\"1\">",
        "  <defaults size=\"16x16\"/>",
        "  <case name=\"tiny\" workspace=\"fx/tiny.xml\">",
        "    <set name=\"Gain\" value=\"" + gain + "\"/>",
        "    <compare reference=\"refs/tiny.exr\" max=\"0.01\" store=\"half\"/>",
        "    <compare target=\"base\" reference=\"refs/tiny_base.exr\" error=\"relative\" max=\"0.2\"/>",
        "  </case>",
        "  <case name=\"second\" workspace=\"fx/tiny.xml\" size=\"8x4\">",
        "    <compare reference=\"refs/second.exr\"/>",
        "  </case>",
        "</replay>",
    });
}

// A replay's stdout with each case's time, " (1.23 s)", written " (… s)": the rest is the same run
// to run, so a test can compare all of it.
inline std::string withoutTimes(const std::string& out) {
    return std::regex_replace(out, std::regex(R"( \([0-9]+\.[0-9]{2} s\))"), " (… s)");
}

inline bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline Image readOk(const fs::path& file) {
    auto image = readImage(file);
    EXPECT_TRUE(image) << image.error();
    return image ? *image : Image{};
}

// The one <testsuite> of a JUnit report file, after checking its counts; nullptr (a test failure)
// when the file does not parse.
inline const tinyxml2::XMLElement* junitSuite(tinyxml2::XMLDocument& doc, const fs::path& file, const char* tests,
                                       const char* failures, const char* errors) {
    EXPECT_EQ(doc.LoadFile(file.c_str()), tinyxml2::XML_SUCCESS) << file;
    const tinyxml2::XMLElement* suite = doc.RootElement() ? doc.RootElement()->FirstChildElement("testsuite") : nullptr;
    EXPECT_TRUE(suite) << file;
    if (!suite) return nullptr;
    EXPECT_STREQ(suite->Attribute("tests"), tests);
    EXPECT_STREQ(suite->Attribute("failures"), failures);
    EXPECT_STREQ(suite->Attribute("errors"), errors);
    return suite;
}

// A scratch folder holding fx/tiny.xml and manifest.xml, references written with --update.
class Project {
public:
    Project() {
        dir_.write("fx/tiny.xml", tinyWorkspace());
        dir_.write("manifest.xml", tinyManifest());
    }
    const ScratchDir& dir() const { return dir_; }
    fs::path operator/(const std::string& name) const { return dir_ / name; }
    CommandResult replay(const std::string& options = "") const {
        return runRmfx("replay manifest.xml " + options, dir_.path());
    }
    void update() const {
        CommandResult r = replay("--update");
        ASSERT_EQ(r.status, 0) << r.out << r.err;
    }

private:
    ScratchDir dir_;
};

}  // namespace rmfx::test::cli_replay
