#include "tests/TestSupport.h"

#include <unistd.h>

#include <fstream>

#include <gtest/gtest.h>

namespace rmfx::test {

std::filesystem::path sourceDir() { return RMFX_SOURCE_DIR; }
std::filesystem::path binaryDir() { return RMFX_BINARY_DIR; }

std::string lines(std::initializer_list<std::string> list) {
    std::string out;
    for (const std::string& l : list) out += l + "\n";
    return out;
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

}  // namespace rmfx::test
