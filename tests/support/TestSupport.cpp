#include "tests/support/TestSupport.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace rmfx::test {

std::filesystem::path sourceDir() { return RMFX_SOURCE_DIR; }
std::filesystem::path binaryDir() { return RMFX_BINARY_DIR; }

std::string lines(std::initializer_list<std::string> list) {
    std::string out;
    for (const std::string& l : list) out += l + "\n";
    return out;
}

bool hasLine(const std::string& text, const std::string& line) {
    for (size_t begin = 0; begin <= text.size();) {
        size_t end = text.find('\n', begin);
        if (end == std::string::npos) end = text.size();
        if (text.compare(begin, end - begin, line) == 0) return true;
        begin = end + 1;
    }
    return false;
}

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string shellQuoted(const std::filesystem::path& path) {
    std::string out = "'";
    for (char c : path.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

CommandResult runRmfx(const std::string& arguments, const std::filesystem::path& folder,
                      const std::string& environment) {
    std::filesystem::path binary = binaryDir() / "rmfx";
    EXPECT_TRUE(std::filesystem::exists(binary)) << binary;
    std::filesystem::path out = folder / "rmfx-stdout.txt", err = folder / "rmfx-stderr.txt";
    std::string command = "cd " + shellQuoted(folder) + " && " + environment + (environment.empty() ? "" : " ") +
                          shellQuoted(binary) + " " + arguments + " >" +
                          shellQuoted(out) + " 2>" + shellQuoted(err);
    int status = std::system(command.c_str());
    CommandResult result;
    EXPECT_TRUE(WIFEXITED(status)) << command;
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readText(out);
    result.err = readText(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
}

CommandResult runRmfxWithFileSizeLimit(const std::string& arguments, const std::filesystem::path& folder,
                                       long fileSizeLimit) {
    std::filesystem::path binary = binaryDir() / "rmfx";
    // Outside the folder, so that the limit's own failures do not land among the outputs; the
    // messages are short, well under any limit a test sets.
    std::filesystem::path out = folder.parent_path() / (folder.filename().string() + ".stdout.txt");
    std::filesystem::path err = folder.parent_path() / (folder.filename().string() + ".stderr.txt");
    std::string command = "cd " + shellQuoted(folder) + " && exec " + shellQuoted(binary) + " " + arguments + " >" +
                          shellQuoted(out) + " 2>" + shellQuoted(err);
    CommandResult result;
    pid_t child = ::fork();
    if (child == 0) {
        struct rlimit limit {static_cast<rlim_t>(fileSizeLimit), static_cast<rlim_t>(fileSizeLimit)};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        ::signal(SIGXFSZ, SIG_DFL);
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    int status = 0;
    EXPECT_GT(child, 0) << "fork failed";
    if (child > 0) ::waitpid(child, &status, 0);
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readText(out);
    result.err = readText(err);
    if (WIFSIGNALED(status)) result.err += "\n(killed by signal " + std::to_string(WTERMSIG(status)) + ")";
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
}

ScratchDir::ScratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "scratch";
    for (char& c : name)
        if (c == '/') c = '_';
    // The process id keeps two runs of the same test (two ctest runs on one build) apart.
    path_ = binaryDir() / "test-scratch" / (name + "." + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path ScratchDir::write(const std::string& name, const std::string& text) const {
    std::filesystem::path file = path_ / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
    return file;
}

std::string passXml(const std::string& name, const std::string& target, const std::vector<std::string>& reads,
                    const std::string& extra) {
    std::string xml = "  <pass name=\"" + name + "\"" + (target.empty() ? "" : " target=\"" + target + "\"") + ">\n";
    for (size_t i = 0; i < reads.size(); ++i) {
        std::string read = reads[i];
        bool previous = !read.empty() && read.back() == '\'';
        if (previous) read.pop_back();
        xml += "    <sampler name=\"s" + std::to_string(i) + "\" target=\"" + read + "\"" +
               (previous ? " frame=\"previous\"" : "") + "/>\n";
    }
    return xml + extra + "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>\n  </pass>\n";
}

}  // namespace rmfx::test
