// What rmfx writes can be trusted: every output is written whole or not at all (a failed write
// exits non-zero naming the file and the reason, leaves no partial file and the previous file as
// it was), and an output that cannot be written is refused before any frame renders.

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/ImageIO.h"
#include "tests/support/GlTestSupport.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;

class CliOutputsGLTest : public GlTest {};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Noise (a hash of the pixel and the frame's image) that no image format compresses much: every
// output at 96x64 is far larger than the limit the tests set.
const char* kNoise = R"(<workspace version="1" name="noise" size="96x64">
  <input name="frame" file="seed.exr"/>
  <pass name="noise">
    <sampler name="Frame" texture="frame" filter="nearest"/>
    <shader stage="fragment"><![CDATA[
uniform sampler2D Frame;
out vec4 c;
float hash(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }
void main() {
    vec2 p = gl_FragCoord.xy + texelFetch(Frame, ivec2(0), 0).xy * 97.0;
    c = vec4(hash(p), hash(p + 17.0), hash(p + 41.0), 1.0);
}
]]></shader>
  </pass>
  <output transform="none"/>
</workspace>
)";

void writeSeed(const fs::path& file, float value) {
    Image seed = blankHdrImage(2, 2);
    for (float& v : seed.pixels) v = value;
    ASSERT_TRUE(writeImage(file, seed).ok());
}

std::vector<std::string> filesIn(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) names.push_back(fs::relative(entry.path(), dir).string());
    std::sort(names.begin(), names.end());
    return names;
}

constexpr long kLimit = 4096;  // bytes: the messages fit, no 96x64 noise image does

// Each format: the render fails under the file-size limit with exit status 2 naming the file
// and "File too large"; the previous image is unchanged and nothing else is left beside it.
TEST_F(CliOutputsGLTest, AWriteOverTheFileSizeLimitLeavesThePreviousImageForEveryFormat) {
    for (const std::string ext : {"exr", "hdr", "png", "jpg", "tga", "bmp"}) {
        ScratchDir dir;
        dir.write("noise.xml", kNoise);
        writeSeed(dir / "seed.exr", 0.0f);
        const std::string out = "out." + ext;
        CommandResult first = runRmfx("render noise.xml --size 8x4 -o " + out, dir.path());
        ASSERT_EQ(first.status, 0) << first.err;
        const std::string previous = readText(dir / out);
        const std::vector<std::string> before = filesIn(dir.path());

        CommandResult limited = runRmfxWithFileSizeLimit("render noise.xml -q -o " + out, dir.path(), kLimit);
        EXPECT_EQ(limited.status, 2) << ext << ": " << limited.err;
        EXPECT_TRUE(has(limited.err, out)) << limited.err;
        EXPECT_TRUE(has(limited.err, "File too large")) << limited.err;
        EXPECT_FALSE(has(limited.err, "wrote")) << limited.err;
        EXPECT_EQ(readText(dir / out), previous) << ext << ": the previous image changed";
        EXPECT_EQ(filesIn(dir.path()), before) << ext << ": a file was left behind";

        // The same render without the limit replaces the image whole.
        CommandResult full = runRmfx("render noise.xml -q -o " + out, dir.path());
        ASSERT_EQ(full.status, 0) << full.err;
        Result<Image> written = readImage(dir / out);
        ASSERT_TRUE(written.ok()) << written.error();
        EXPECT_EQ(written->width, 96);
        EXPECT_GT(fs::file_size(dir / out), static_cast<uintmax_t>(kLimit)) << ext << ": the limit would not have bitten";
    }
}

// A sequence: the first frame that cannot be written ends the run (exit 2, naming it); every
// output frame there was before is as it was, and no temporary file stays.
TEST_F(CliOutputsGLTest, ASequenceWriteOverTheLimitLeavesThePreviousFrames) {
    ScratchDir dir;
    dir.write("noise.xml", kNoise);
    writeSeed(dir / "seed.exr", 0.0f);
    fs::create_directories(dir / "shot");
    fs::create_directories(dir / "out");
    for (int k = 1; k <= 3; ++k) {
        writeSeed(dir / ("shot/f.000" + std::to_string(k) + ".exr"), 0.1f * k);
        dir.write("out/f.000" + std::to_string(k) + ".png", "previous frame " + std::to_string(k));
    }
    const std::vector<std::string> before = filesIn(dir.path());
    CommandResult limited = runRmfxWithFileSizeLimit("render noise.xml --input shot/f.%04d.exr -o out/f.%04d.png", dir.path(), kLimit);
    EXPECT_EQ(limited.status, 2) << limited.err;
    EXPECT_TRUE(has(limited.err, "out/f.0001.png")) << limited.err;
    EXPECT_TRUE(has(limited.err, "File too large")) << limited.err;
    for (int k = 1; k <= 3; ++k)
        EXPECT_EQ(readText(dir / ("out/f.000" + std::to_string(k) + ".png")), "previous frame " + std::to_string(k));
    EXPECT_EQ(filesIn(dir.path()), before);
}

// -o that cannot take an image: refused with exit status 1 before the frame renders (--explain
// prints the schedule only after a frame has run, so its absence shows none did).
TEST_F(CliOutputsGLTest, AnOutputThatCannotBeWrittenIsRefusedBeforeTheFrame) {
    ScratchDir dir;
    dir.write("noise.xml", kNoise);
    writeSeed(dir / "seed.exr", 0.0f);
    fs::create_directories(dir / "folder.png");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"missing/out.png", "the folder 'missing' does not exist"},
        {"out.xyz", "unknown image file extension '.xyz' (known: .exr .hdr .png .jpg .jpeg .tga .bmp)"},
        {"folder.png", "'folder.png' is a folder, not a file"},
        {"out", "no image file extension"},
    };
    for (const auto& [output, why] : cases) {
        CommandResult cli = runRmfx("render noise.xml --explain -o " + output, dir.path());
        EXPECT_EQ(cli.status, 1) << output << ": " << cli.err;
        EXPECT_TRUE(has(cli.err, "rmfx render: -o: ")) << cli.err;
        EXPECT_TRUE(has(cli.err, why)) << cli.err;
        EXPECT_EQ(cli.out, "") << output << ": the frame ran before the output was checked";
    }
    // The default output (the workspace's name) is checked as well, once the name is known.
    fs::create_directories(dir / "noise.png");
    CommandResult named = runRmfx("render noise.xml --explain", dir.path());
    EXPECT_EQ(named.status, 0) << named.err;  // --explain alone writes nothing
    CommandResult fallback = runRmfx("render noise.xml", dir.path());
    EXPECT_EQ(fallback.status, 1) << fallback.err;
    EXPECT_TRUE(has(fallback.err, "'noise.png' is a folder, not a file")) << fallback.err;
}

// Images are read and written through the image codecs module (runtime/io/image/ImageCodecs.h),
// loaded when a command needs it: without it a render fails naming the module's path and the
// loader's reason and writes nothing; validate, which reads no image, never loads it.
TEST_F(CliOutputsGLTest, WithoutTheImageCodecsModuleARenderSaysWhyAndWritesNothing) {
    ScratchDir dir;
    dir.write("noise.xml", kNoise);
    writeSeed(dir / "seed.exr", 0.0f);
    const std::string missing = (dir / "gone/rmfx-image-codecs.so").string();
    CommandResult render = runRmfx("render noise.xml -o out.png", dir.path(), "RMFX_IMAGE_CODECS=" + missing);
    EXPECT_EQ(render.status, 2) << render.err;  // as for any texture that cannot be read
    EXPECT_TRUE(has(render.err, "noise.xml:2: error: texture 'frame': cannot load rmfx's image codecs '" + missing +
                                    "': ")) << render.err;
    EXPECT_TRUE(has(render.err, "No such file or directory")) << render.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    CommandResult validate = runRmfx("validate noise.xml", dir.path(), "RMFX_IMAGE_CODECS=" + missing);
    EXPECT_EQ(validate.status, 0) << validate.err;
}

// replay: --out, --report and --junit that cannot be written are refused before any case runs.
TEST_F(CliOutputsGLTest, ReplayOutputsAreCheckedBeforeAnyCase) {
    ScratchDir dir;
    dir.write("plain", "a file");
    dir.write("m.xml", R"(<replay version="1"><case name="c" workspace="none.xml"><compare reference="r.exr"/></case></replay>)");
    for (const std::string& option : {std::string("--out plain/sub"), std::string("--report plain/r"),
                                      std::string("--junit plain/j.xml")}) {
        CommandResult cli = runRmfx("replay m.xml " + option, dir.path());
        EXPECT_EQ(cli.status, 1) << option << ": " << cli.err;
        EXPECT_TRUE(has(cli.err, "rmfx replay: " + option.substr(0, option.find(' ')) + ": ")) << cli.err;
        EXPECT_FALSE(has(cli.out, "[1/1]")) << "a case ran first: " << cli.out;
    }
}

}  // namespace
}  // namespace rmfx::test
