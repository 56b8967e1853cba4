// libFuzzer's entry point around one rmfx fuzz entry (RMFX_FUZZ_ENTRY, set by fuzz/CMakeLists.txt).
#include <cstddef>
#include <cstdint>

namespace rmfx::fuzz {
void RMFX_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rmfx::fuzz::RMFX_FUZZ_ENTRY(data, size);
    return 0;
}
