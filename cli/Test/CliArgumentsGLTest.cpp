// No silent traps in the arguments: every argument error exits 1 before any work; each
// command's --help is its usage; a file that is not there is said not to exist; an argument
// that would change nothing says so and why; images are refused from their header by the memory
// they would take; and every flag a message suggests is one a parser takes.

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/ClaimedSizeExr.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

class CliArgumentsGLTest : public GlTest {};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string effect(const std::string& name) { return shellQuoted(sourceDir() / "effects" / (name + ".xml")); }

TEST_F(CliArgumentsGLTest, EachCommandsHelpIsItsUsage) {
    ScratchDir dir;
    for (const std::string command : {"render", "validate", "list", "replay", "edit", "bench"}) {
        for (const std::string& asked : {command + " --help", command + " -h", "help " + command}) {
            CommandResult cli = runRmfx(asked, dir.path());
            EXPECT_EQ(cli.status, 0) << asked << ": " << cli.err;
            EXPECT_EQ(cli.out.rfind("usage:\n  rmfx " + command + " ", 0), 0u) << asked << ":\n" << cli.out;
            EXPECT_TRUE(has(cli.out, "exit status")) << cli.out;
        }
    }
    CommandResult render = runRmfx("render --help", dir.path());
    EXPECT_TRUE(has(render.out, "render options:")) << render.out;
    EXPECT_TRUE(has(render.out, "--preroll N")) << render.out;
    EXPECT_TRUE(has(render.out, "file options")) << render.out;
    EXPECT_FALSE(has(render.out, "replay options:")) << render.out;
    CommandResult replay = runRmfx("replay --help", dir.path());
    EXPECT_TRUE(has(replay.out, "replay options:")) << replay.out;
    EXPECT_FALSE(has(replay.out, "render options:")) << replay.out;
}

// rmfx edit checks its arguments itself, then starts the editor's program (rmfx-edit) in its place
// with the same arguments, so that rmfx links no windowing library.
TEST_F(CliArgumentsGLTest, EditChecksItsArgumentsThenStartsTheEditorsProgramWithThem) {
    ScratchDir dir;
    CommandResult bad = runRmfx("edit fx.xml --sise 64x32", dir.path());
    EXPECT_EQ(bad.status, 1);
    EXPECT_EQ(bad.err.rfind("rmfx edit: unknown option '--sise'", 0), 0u) << bad.err;

    CommandResult nowhere = runRmfx("edit fx.xml", dir.path(), "RMFX_EDITOR=/nonexistent/rmfx-edit");
    EXPECT_EQ(nowhere.status, 2);
    EXPECT_EQ(nowhere.err, "rmfx edit: RMFX_EDITOR names '/nonexistent/rmfx-edit', which is not a program that can be run\n");

    // A stand-in for the editor that says what it was given and exits with a status of its own.
    std::ofstream(dir / "fake-edit.sh") << "#!/bin/sh\necho \"$@\"\nexit 7\n";
    std::filesystem::permissions(dir / "fake-edit.sh", std::filesystem::perms::owner_all);
    CommandResult started = runRmfx("edit fx.xml --size 64x32 --set 'Tint=1 0 0'", dir.path(),
                                    "RMFX_EDITOR=" + shellQuoted(dir / "fake-edit.sh"));
    EXPECT_EQ(started.status, 7) << started.err;
    EXPECT_EQ(started.out, "fx.xml --size 64x32 --set Tint=1 0 0\n");
}

TEST_F(CliArgumentsGLTest, AMissingWorkspaceIsSaidNotToExist) {
    ScratchDir dir;
    CommandResult cli = runRmfx("render nothere.xml", dir.path());
    EXPECT_EQ(cli.status, 1);
    EXPECT_EQ(cli.err, "nothere.xml: error: the file does not exist\n");
    fs::create_directories(dir / "folder.xml");
    CommandResult folder = runRmfx("validate folder.xml", dir.path());
    EXPECT_EQ(folder.status, 1);
    EXPECT_EQ(folder.err, "folder.xml: error: it is a folder, not a file\n");
}

TEST_F(CliArgumentsGLTest, AnUnknownEffectIsAnArgumentError) {
    ScratchDir dir;
    CommandResult cli = runRmfx("render " + effect("shader_5") + " --effects glow --size 16x16 -o x.exr", dir.path());
    EXPECT_EQ(cli.status, 1) << cli.err;
    EXPECT_TRUE(has(cli.err, "rmfx render: --effects: ")) << cli.err;
    EXPECT_TRUE(has(cli.err, "glow")) << cli.err;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

// shader_1 reads Sky_Float only while Environment_Format is 1: a --texture for it otherwise
// says so and names the setting; with the setting, no word.
TEST_F(CliArgumentsGLTest, ATextureThePassesDoNotReadSaysWhichSettingWouldReadIt) {
    ScratchDir dir;
    Image sky = blankHdrImage(64, 32);
    for (size_t i = 0; i < sky.pixels.size(); ++i) sky.pixels[i] = 0.5f + 0.25f * float(i % 7);
    ASSERT_TRUE(writeImage(dir / "pano.exr", sky).ok());
    const std::string base = "render " + effect("shader_1") + " --size 16x16 --texture Sky_Float=pano.exr";
    CommandResult unread = runRmfx(base + " -o a.exr", dir.path());
    EXPECT_EQ(unread.status, 0) << unread.err;
    EXPECT_TRUE(has(unread.err, "warning: --texture Sky_Float=pano.exr: the passes read texture 'Sky_Float' only while "
                                "Environment_Format is 1 (it is 0), so the file changes nothing: add --set Environment_Format=1"))
        << unread.err;
    CommandResult read = runRmfx(base + " --set Environment_Format=1 -o b.exr", dir.path());
    EXPECT_EQ(read.status, 0) << read.err;
    EXPECT_FALSE(has(read.err, "--texture Sky_Float")) << read.err;
}

// An --input whose passes belong to an effect left out is read by no pass that runs.
TEST_F(CliArgumentsGLTest, AnInputNoRunningPassSamplesSaysWhy) {
    ScratchDir dir;
    dir.write("two.xml", R"(<workspace version="1" name="two" size="4x4">
  <input name="extra"/>
  <target name="t" format="rgba16f"/>
  <effect name="base" passes="base"/>
  <effect name="mix" passes="mix"/>
  <pass name="base"><shader stage="fragment">out vec4 c; void main() { c = vec4(0.25); }</shader></pass>
  <pass name="mix">
    <blend mode="add"/>
    <sampler name="Extra" texture="extra"/>
    <shader stage="fragment">uniform sampler2D Extra; out vec4 c; void main() { c = texture(Extra, vec2(0.5)); }</shader>
  </pass>
</workspace>
)");
    Image extra = blankHdrImage(2, 2);
    ASSERT_TRUE(writeImage(dir / "extra.exr", extra).ok());
    CommandResult cli = runRmfx("render two.xml --input extra=extra.exr --effects base -o o.exr", dir.path());
    EXPECT_EQ(cli.status, 0) << cli.err;
    EXPECT_TRUE(has(cli.err, "warning: --input extra=extra.exr: no pass that runs samples input 'extra', so the image changes "
                             "nothing; pass 'mix': culled: effect left out"))
        << cli.err;
}

// The report's 8 KB EXR claiming 16000x16000 is refused from its header with exit status 1.
TEST_F(CliArgumentsGLTest, AnImageIsRefusedFromItsHeaderByTheMemoryItWouldTake) {
    ScratchDir dir;
    ASSERT_TRUE(writeExrClaimingSize(dir / "claims.exr", 16000, 16000));
    const std::string render = "render " + effect("shader_5") + " --input claims.exr -o x.exr";
    CommandResult cli = runRmfx(render, dir.path());
    EXPECT_EQ(cli.status, 1) << cli.err;
    EXPECT_TRUE(has(cli.err, "claims.exr: image is 16000x16000: decoded it would take 3907 MiB, over the limit of 2048 MiB "
                             "(--max-image-memory MiB raises it)"))
        << cli.err;
    // Before the workspace is even read: one that does not exist is not what is reported.
    CommandResult first = runRmfx("render nothere.xml --input claims.exr -o x.exr", dir.path());
    EXPECT_EQ(first.status, 1) << first.err;
    EXPECT_TRUE(has(first.err, "rmfx render: --input claims.exr: claims.exr: image is 16000x16000")) << first.err;
    EXPECT_FALSE(has(first.err, "nothere.xml")) << first.err;
    // The flag sets the limit for the run.
    CommandResult raised = runRmfx(render + " --max-image-memory 1 ", dir.path());
    EXPECT_EQ(raised.status, 1) << raised.err;
    EXPECT_TRUE(has(raised.err, "over the limit of 1 MiB")) << raised.err;
    CommandResult bad = runRmfx("render --max-image-memory lots", dir.path());
    EXPECT_EQ(bad.status, 1);
    EXPECT_TRUE(has(bad.err, "--max-image-memory: expected MiB")) << bad.err;
}

// Every "--flag" a message of rmfx's sources names is one a command's parser takes (rmfx
// --options prints them all), so no message suggests a flag that does not exist.
TEST_F(CliArgumentsGLTest, EveryFlagAMessageNamesIsOneAParserTakes) {
    ScratchDir dir;
    CommandResult options = runRmfx("--options", dir.path());
    ASSERT_EQ(options.status, 0) << options.err;
    std::set<std::string> known;
    std::istringstream lines(options.out);
    for (std::string command, option; lines >> command >> option;) known.insert(option);
    for (const char* expected : {"--output", "--preroll", "--no-sandbox", "--max-image-memory", "--junit", "--screenshot"})
        EXPECT_TRUE(known.count(expected)) << expected << " missing from rmfx --options:\n" << options.out;

    const std::regex literal(R"re("(?:[^"\\\n]|\\.)*")re");
    const std::regex flag(R"(--[a-z][a-z0-9-]*[a-z0-9])");
    std::set<std::string> unknown;
    int files = 0;
    for (const char* root : {"cli", "runtime", "editor"}) {
        for (const auto& entry : fs::recursive_directory_iterator(sourceDir() / root)) {
            const fs::path& path = entry.path();
            if (path.extension() != ".cpp" && path.extension() != ".h") continue;
            if (path.string().find("/Test/") != std::string::npos) continue;
            ++files;
            const std::string text = readText(path);
            for (auto s = std::sregex_iterator(text.begin(), text.end(), literal); s != std::sregex_iterator(); ++s) {
                std::string string = s->str();
                // Another program's flags, named with the program: "cmake --build BUILD".
                for (size_t at; (at = string.find("cmake --build")) != std::string::npos;) string.erase(at, 13);
                for (auto f = std::sregex_iterator(string.begin(), string.end(), flag); f != std::sregex_iterator(); ++f)
                    if (!known.count(f->str())) unknown.insert(f->str() + " in " + fs::relative(path, sourceDir()).string());
            }
        }
    }
    EXPECT_GT(files, 100);
    std::string list;
    for (const std::string& u : unknown) list += "  " + u + "\n";
    EXPECT_TRUE(unknown.empty()) << "flags no parser takes:\n" << list;
}

}  // namespace
}  // namespace rmfx::test
