#pragma once
// The "run one input" functions of the fuzz targets (fuzz/CMakeLists.txt lists them). Each takes
// arbitrary bytes and must return normally: a crash, hang, sanitizer report or a thrown
// FuzzPropertyViolation is a finding. libFuzzer calls them (fuzz/FuzzMain.cpp), and so does
// FuzzRegressionTest for every saved finding in tests/fuzz-regressions/<name>/.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rmfx::fuzz {

struct FuzzEntry {
    const char* name;  // the target's name: rmfx_fuzz_<name>, tests/fuzz-regressions/<name>/
    void (*run)(const std::uint8_t* data, std::size_t size);
};

// Every target, in fuzz/CMakeLists.txt's order.
const std::vector<FuzzEntry>& fuzzEntries();

// A property the code under test promises was broken (not a crash, but just as much a bug).
struct FuzzPropertyViolation : std::logic_error {
    using std::logic_error::logic_error;
};

inline void fuzzCheck(bool holds, const std::string& what) {
    if (!holds) throw FuzzPropertyViolation(what);
}

}  // namespace rmfx::fuzz
