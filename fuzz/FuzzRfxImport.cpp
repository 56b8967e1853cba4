// Fuzz target "rfx_import" (not built yet): the bytes as a RenderMonkey .rfx file (with the files
// it names, FuzzInputFiles.h), imported, then checked as the "workspace" target checks a parsed
// workspace. Written against runtime/RfxImporter.h as the rfx branch had it; to enable it after
// merging, uncomment its rmfx_add_fuzzer line in fuzz/CMakeLists.txt, adapt the calls below if
// the importer's API changed, and put the test .rfx files in tests/rfx/ (scripts/fuzz.sh seeds
// the target from there).

#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"
#include "fuzz/FuzzWorkspace.h"
#include "runtime/RfxImporter.h"

namespace rmfx::fuzz {

void fuzzRfxImport(const std::uint8_t* data, std::size_t size) {
    FuzzInput input = splitFuzzInput({reinterpret_cast<const char*>(data), size});
    std::filesystem::path folder = freshScratchFolder() / "a" / "b" / "rfx";
    std::filesystem::create_directories(folder);
    writeParts(input.parts, folder);
    writeParts({{"fuzz.rfx", input.main}}, folder);
    listRfxEffects(folder / "fuzz.rfx");
    checkParsedWorkspace(importRfxText(input.main, folder / "fuzz.rfx", folder));
}

}  // namespace rmfx::fuzz
