// Fuzz target "rfx_import": the bytes as a RenderMonkey .rfx file (with the files it names,
// FuzzInputFiles.h), listed, imported, then checked as the "workspace" target checks a parsed
// workspace. Seeds: tests/rfx/.

#include "frontend/rfx/RfxImporter.h"
#include "fuzz/FuzzEntries.h"
#include "fuzz/FuzzInputFiles.h"
#include "fuzz/FuzzWorkspace.h"

namespace rmfx::fuzz {

void fuzzRfxImport(const std::uint8_t* data, std::size_t size) {
    FuzzInput input = splitFuzzInput({reinterpret_cast<const char*>(data), size});
    std::filesystem::path folder = freshScratchFolder() / "a" / "b" / "rfx";
    std::filesystem::create_directories(folder);
    writeParts(input.parts, folder);
    writeParts({{"fuzz.rfx", input.main}}, folder);
    (void)listRfxEffects(folder / "fuzz.rfx");
    checkParsedWorkspace(importRfxText(input.main, folder / "fuzz.rfx", folder));
}

}  // namespace rmfx::fuzz
