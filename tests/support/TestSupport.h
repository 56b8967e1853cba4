#pragma once
// Paths and scratch folders shared by the tests.

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace rmfx::test {

std::filesystem::path sourceDir();  // the repository root
std::filesystem::path binaryDir();  // the build folder

// Joins lines with "\n", so the i-th string is line i + 1 of the text: tests then state the line
// of each element they expect a message about.
std::string lines(std::initializer_list<std::string> list);

// Whether `text` holds `line` as one whole line (between line breaks or the text's ends): a test
// checks one formatted diagnostic of several whole, its file:line included, not a piece of it.
bool hasLine(const std::string& text, const std::string& line);

// The whole text of a file; "" when it cannot be read.
std::string readText(const std::filesystem::path& file);

// A path in single quotes, for a shell command line.
std::string shellQuoted(const std::filesystem::path& path);

// A <pass> that writes `target` (empty: the output) with a trivial shader and one sampler per
// entry of `reads` (a trailing ' reads it with frame="previous"); `extra` goes inside the pass.
std::string passXml(const std::string& name, const std::string& target, const std::vector<std::string>& reads,
                    const std::string& extra = "");

struct CommandResult {
    int status = -1;  // the exit status; -1 when the process did not exit normally
    std::string out;  // stdout
    std::string err;  // stderr
};

// Runs the rmfx binary of this build in `folder` with `arguments` (quoted for the shell where
// needed) and `environment` (NAME=value words, or ""); stdout and stderr pass through files in
// `folder`.
CommandResult runRmfx(const std::string& arguments, const std::filesystem::path& folder,
                      const std::string& environment = "");
// The same under a file-size limit (RLIMIT_FSIZE, as `ulimit -f` sets it): a write past
// `fileSizeLimit` bytes fails, as on a full disk. SIGXFSZ keeps its default action, so a program
// that does not handle the limit is killed (status -1).
CommandResult runRmfxWithFileSizeLimit(const std::string& arguments, const std::filesystem::path& folder,
                                       long fileSizeLimit);

// A fresh, empty folder under the build tree, named after the running test; removed on destruction.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
    // Writes text to a file inside the folder and returns its path.
    std::filesystem::path write(const std::string& name, const std::string& text) const;

private:
    std::filesystem::path path_;
};

}  // namespace rmfx::test
