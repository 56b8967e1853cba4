// rmfx command line: renders, validates and replays workspaces through the runtime library only.

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "cli/Commands.h"

namespace {

const char* usage = R"(rmfx — runs RenderMonkey-style effect workspaces as OpenGL passes

usage:
  rmfx render [WORKSPACE] [options]   render headless and write an image
  rmfx validate WORKSPACE...          check workspaces (structure, references, shaders) without GL
  rmfx list FILE.rfx                  list a RenderMonkey file's effects: passes, shaders, targets,
                                      samplers, models, streams, the variables each pass needs, media
                                      files and which are missing (--media, --missing-media)
  rmfx replay MANIFEST [options]      regression tests: render the manifest's cases and compare them
                                      with their reference images (docs/replay.md)
  rmfx edit WORKSPACE [options]       open the editor: the running effect beside a panel of its
                                      variables, render targets and timing (docs/editor.md)
  rmfx bench [MANIFEST] [options]     measure each variant of the stages (default manifest
                                      bench/variants.xml): GPU time and error against a float64
                                      ideal; CSV, JSON, SVG plot, table (docs/accuracy-vs-time.md)
  rmfx COMMAND --help                 that command's usage and options
  rmfx --options                      every command's options, one "COMMAND OPTION" a line
  rmfx --help | --version

WORKSPACE is an rmfx workspace file (docs/workspace-format.md) or a RenderMonkey .rfx file
(docs/rendermonkey.md); without one, render uses the built-in default workspace.

render, validate and edit option for .rfx files:
  --effect NAME          the effect to run: its dotted path as `rmfx list` prints it ("Effect
                         Workspace.Group.Effect", or "Group.Effect"), or a name only one effect
                         has (default: the file's ACTIVE_EFFECT)
  --rfx-matrices row-vector|column-vector
                         how a Direct3D effect's HLSL multiplies the matrices rmfx fills by
                         semantic: mul(v, M) or mul(M, v) (default: the side of mul() the
                         code puts them on, else the RenderMonkey that saved the file, 1.5 and
                         before column-vector; docs/rendermonkey.md)

render options:
  -o, --output FILE      image to write: .exr/.hdr keep float data; .png/.jpg/.tga/.bmp get the
                         output's display transform (default: WORKSPACE-NAME.png)
  --size WxH             viewport size (default: the workspace's size attribute, else 512x512)
  --frames N             frames to render before writing (default 1)
  --dt SECONDS           fixed time step between frames (default 1/60; a sequence's, instead of
                         --fps)
  --set NAME=VALUE       override a variable (repeatable), e.g. --set Exposure_Level=2
                         or --set Sun_Direction="0 1 0"
  --input [NAME=]FILE[:layer]
                         your image for the workspace's <input> NAME (docs/inputs.md): it
                         replaces the scene the workspace draws, at the image's size unless
                         --size; an EXR part or layer after ':'. A frame pattern
                         (shot/f.%04d.exr, f.####.exr) runs the sequence, one output per frame
  --fps N                a sequence's frame rate: dt = 1/N (default 24)
  --preroll N            a sequence: render N frames of its first image before the first output,
                         so light adaptation and frame="previous" targets start settled on the
                         shot instead of fading in (default 0); with --frame-range, the N frames
                         before the range, as the whole run renders them (docs/sequences.md)
  --frame-range A-B      a sequence: write only frames A to B (the numbers in the file names),
                         each as the whole shot's run gives it: one render-farm task per chunk
  --texture NAME=FILE    replace a texture's file for this run (repeatable), .rfx too; a cube
                         map takes one image (2:1 longitude/latitude, 4:3 or 3:4 cross, DDS)
                         or six faces: NAME=px,nx,py,ny,pz,nz
  --target NAME          write this render target instead of the output (written linear, no transform)
  --transform none|srgb  override the display transform for 8-bit images
  --effects A,B          compute only these effects (<effect> groups); the others' passes are
                         culled and their targets not allocated (default: the workspace's choice)
  --explain              print the frame's schedule: each pass run or culled and why, each target
                         with size, format, bytes and shared memory, and the peak GPU memory;
                         alone (no -o, no --check) it prints the plan without rendering or a GL
                         context; with -o it renders and adds what content skip skipped
  --no-pool              give every target memory of its own (no sharing between lifetimes)
  --check                after each pass, inspect on the GPU the target it wrote for NaN, ±Inf,
                         negative values and values at its format's largest; report the first
                         pass that wrote each, with a pixel, its value and the pass's inputs there
                         (exit status 4 when NaN or an infinity was found; the image is written)
  --check-method auto|while-drawing|after-pass
                         how --check looks: the passes' own shaders count what they write, or a
                         draw over each target after its pass (default auto: while-drawing on a
                         GPU; on a software rasteriser such as llvmpipe, while-drawing only where
                         consecutive passes draw into one target); implies --check
  --content-skip on|off  skip on the GPU the effects whose source holds nothing this frame
                         (<effect source>; default on; the image is the same either way)
  --memory-budget MiB    the most render-target memory a frame may hold (default 4096); a
                         workspace that needs more fails before anything is allocated
  --frame-budget SECONDS stop with exit status 3 when a frame (GPU work included) takes longer
                         (default 60; 0: no limit): a shader that loops too long ends the run
  -q, --quiet            print nothing but errors

replay options:
  --out DIR              where failing compares leave their diff and actual images, as
                         DIR/CASE/NAME.diff.exr and DIR/CASE/NAME.actual.exr (default: replay-out)
  --junit FILE           also write a JUnit XML report, one testcase per case
  --report DIR           also write DIR/index.html: every case, failures first, with reference,
                         actual and difference side by side, a slider and flicker, an exposure
                         control for HDR images, the metrics against their limits (docs/replay.md)
  --case NAME            replay only this case (repeatable)
  --update               store the renders as the references instead of comparing
  --all-targets          with --update: also store every target of each case (CASE.targets/ beside
                         its first reference); a failing case then names the first pass whose
                         target differs (later --updates keep them current)
  --frame-budget SECONDS as for render: the case past its budget is reported (and written to the
                         JUnit report) as an error, and replay stops with exit status 3
  -q, --quiet            print only failing cases and errors

edit options:
  --size WxH             viewport size (default: the workspace's size); the effect is shown 1:1
                         at the window's top-left corner
  --set NAME=VALUE       override a variable's starting value (repeatable), as for render
  --view TARGET          open the viewer of a render target from the start (repeatable)
  --input [NAME=]FILE    an image for the workspace's <input>, as for render; it hot-reloads, and an
                         image dropped on the window replaces it
  --texture NAME=FILE    a texture's or cube map's file for this run, as for render
  --check                start with the numeric health check on (as render --check): a badge
                         under each target's thumbnail, the first bad pixel on hover
  --split F              start with the before/after view: the input left of F (0 to 1) of the
                         width, the output right of it; needs --input
  --frames N             render N frames at a fixed step, write the screenshots, exit
                         (the mouse is ignored meanwhile)
  --dt SECONDS           the step of --frames runs (default 1/60)
  --screenshot FILE      with --frames: write the whole window to FILE (PNG)
  --output-screenshot FILE
                         with --frames: write the effect's output to FILE, as render would

bench options:
  --input FILE.exr       also measure on this image (repeatable); its size is the viewport
  --scenes, --no-scenes  include the manifest's scenes (default) or not; workspace scenes are
                         rendered at --size into DIR/inputs/NAME.exr
  --size WxH             size of the rendered scenes (default 512x512)
  --frames N             timed frames per variant (default 20); the median, p10, p90, min, max
  --warmup N             frames before timing (default 5)
  --stage NAME           only this stage (repeatable)
  --variant TEXT         only variants whose name contains TEXT (repeatable)
  --out DIR              where accuracy.csv, .json, .svg and .md go (default bench-out)
  --time gpu|wall|auto   the time the table, plot and Pareto front use: GPU timer queries, or
                         the wall clock of each frame with glFinish; auto (default): wall on
                         Mesa's llvmpipe/softpipe (their timer queries miss most of the
                         rasterising), else gpu. CSV and JSON always hold both
  -q, --quiet            print only errors, no progress line per variant

file options (render, validate, edit, bench, replay; --media and --missing-media on list too; docs/media.md):
  --media DIR            also look for textures, models and shader files in DIR (repeatable, in
                         order), by their trailing path components, then by file name; names are
                         matched ignoring case and "\" separates, as in RenderMonkey files
  --sandbox              refuse file references and #include roots leading outside the workspace
                         folder and the --media folders ("..", absolute paths, symbolic links)
  --no-sandbox           no sandbox: the default, except for replay, which sandboxes unless told
                         so here or by its manifest (<replay sandbox="false">)
  --max-image-memory MiB the most memory one image may take decoded (4 floats a pixel; default
                         2048): a larger one is refused from its header, before it is read
  --missing-media error|placeholder
                         a texture or model found nowhere: an error (default), or a stand-in with
                         a warning: a magenta and grey checker, the built-in mesh its file name
                         names (teapot, sphere, torus, quad, plane) or a cube (also on list)

exit status: render, validate, edit: 0 success, 1 invalid workspace or arguments (an output
that cannot be written or an unknown effect included, found before anything renders), 2 rendering,
GL or write failure (edit: also no window, or an rmfx built without the editor), 3 a frame past its
budget, 4 (render --check) NaN or an infinity in a target. replay: 0 every case
passed, 1 a case failed (comparison, workspace or rendering error) or the manifest or arguments
are invalid, 2 no GL context. bench: 0 success, 1 invalid manifest, arguments, input or workspace,
2 no GL context or a variant failed to render.
)";

// Each command: what runs it, and the options its parser takes (rmfx --options).
struct Command {
    const char* name;
    int (*run)(const std::vector<std::string>& args);
    std::vector<std::string> (*optionNames)();
};

const Command commands[] = {
    {"render", rmfx::cli::renderCommand, rmfx::cli::renderOptionNames},
    {"validate", rmfx::cli::validateCommand, rmfx::cli::validateOptionNames},
    {"list", rmfx::cli::listCommand, rmfx::cli::listOptionNames},
    {"replay", rmfx::cli::replayCommand, rmfx::cli::replayOptionNames},
    {"edit", rmfx::cli::editCommand, rmfx::cli::editOptionNames},
    {"bench", rmfx::cli::benchCommand, rmfx::cli::benchOptionNames},
};

const Command* findCommand(const std::string& name) {
    for (const Command& c : commands)
        if (name == c.name) return &c;
    return nullptr;
}

// Whether a usage paragraph's first line ("render options:", "file options (render, …):")
// names `command` as a word.
bool headingNames(const std::string& heading, const std::string& command) {
    for (size_t at = heading.find(command); at != std::string::npos; at = heading.find(command, at + 1)) {
        const bool startsWord = at == 0 || !std::isalpha(static_cast<unsigned char>(heading[at - 1]));
        const size_t end = at + command.size();
        const bool endsWord = end >= heading.size() || !std::isalpha(static_cast<unsigned char>(heading[end]));
        if (startsWord && endsWord) return true;
    }
    return false;
}

// rmfx COMMAND --help: the command's line of the overview, then every paragraph of options whose
// heading names the command, and the exit statuses.
std::string commandUsage(const std::string& command) {
    const std::string text = usage;
    std::vector<std::string> paragraphs;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find("\n\n", start);
        if (end == std::string::npos) end = text.size();
        paragraphs.push_back(text.substr(start, end - start));
        start = end + 2;
    }
    std::string out = "usage:\n";
    const std::string overview = paragraphs.size() > 1 ? paragraphs[1] : "";
    bool inCommand = false;
    for (size_t start = 0; start < overview.size();) {
        size_t end = overview.find('\n', start);
        if (end == std::string::npos) end = overview.size();
        const std::string line = overview.substr(start, end - start);
        if (line.rfind("  rmfx ", 0) == 0) inCommand = line.rfind("  rmfx " + command + " ", 0) == 0;
        if (inCommand) out += line + "\n";
        start = end + 1;
    }
    for (size_t i = 2; i < paragraphs.size(); ++i) {
        const std::string heading = paragraphs[i].substr(0, paragraphs[i].find('\n'));
        if (heading.rfind("exit status", 0) == 0 || (heading.find("option") != std::string::npos && headingNames(heading, command)))
            out += "\n" + paragraphs[i] + "\n";
    }
    return out;
}

bool asksForHelp(const std::vector<std::string>& args) {
    return std::any_of(args.begin(), args.end(), [](const std::string& a) { return a == "--help" || a == "-h"; });
}

}  // namespace

int main(int argc, char** argv) {
    // A file-size limit (ulimit -f) then makes a write fail with EFBIG, which the atomic writes
    // report and clean up after, instead of killing the process with a half-written file beside
    // the output.
    std::signal(SIGXFSZ, SIG_IGN);
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        if (args.size() > 1 && findCommand(args[1])) {
            std::fputs(commandUsage(args[1]).c_str(), stdout);
            return 0;
        }
        std::fputs(usage, args.empty() ? stderr : stdout);
        return args.empty() ? 1 : 0;
    }
    if (args[0] == "--version") {
        std::puts("rmfx 0.1.0 (workspace format 1)");
        return 0;
    }
    if (args[0] == "--options") {
        for (const char* option : {"--help", "--version", "--options"}) std::printf("rmfx %s\n", option);
        for (const Command& command : commands)
            for (const std::string& option : command.optionNames()) std::printf("%s %s\n", command.name, option.c_str());
        return 0;
    }
    const std::string name = args[0];
    args.erase(args.begin());
    const Command* command = findCommand(name);
    if (!command) {
        std::cerr << "rmfx: unknown command '" << name << "' (try rmfx --help)\n";
        return 1;
    }
    if (asksForHelp(args)) {
        std::fputs(commandUsage(name).c_str(), stdout);
        return 0;
    }
    return command->run(args);
}
