#include "fuzz/FuzzInputFiles.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace rmfx::fuzz {
namespace {

constexpr std::string_view kMarker = "//@@ ";
constexpr size_t kMaxParts = 64;

std::filesystem::path* scratch = nullptr;

// A relative name of plain components ('..' allowed) that stays inside the scratch folder.
bool safeName(const std::string& name, const std::filesystem::path& folder) {
    if (name.empty() || name.size() > 128 || name.front() == '/' || name.back() == '/') return false;
    int depth = 0;
    size_t start = 0;
    while (start <= name.size()) {
        size_t end = name.find('/', start);
        if (end == std::string::npos) end = name.size();
        std::string_view component(name.data() + start, end - start);
        if (component.empty() || component == "." || ++depth > 6) return false;
        for (char c : component)
            if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
        start = end + 1;
    }
    std::filesystem::path file = (folder / name).lexically_normal();
    auto [end, _] = std::mismatch(scratch->begin(), scratch->end(), file.begin(), file.end());
    return end == scratch->end() && file != *scratch;
}

// Memory (/dev/shm) where there is one to write to: creating and removing the folder's files on
// a disk's file system (ext4's journal) took three quarters of the shader_preprocessor target's
// time per input, 112 against 449 inputs a second without sanitizers. Otherwise the temp folder.
std::filesystem::path scratchParent() {
    const std::filesystem::path memory = "/dev/shm";
    std::error_code ignored;
    if (std::filesystem::is_directory(memory, ignored) && ::access(memory.c_str(), W_OK | X_OK) == 0) return memory;
    return std::filesystem::temp_directory_path();
}

void removeScratch() {
    std::error_code ignored;
    if (scratch) std::filesystem::remove_all(*scratch, ignored);
}

}  // namespace

FuzzInput splitFuzzInput(std::string_view bytes) {
    FuzzInput out;
    std::string* current = &out.main;
    size_t pos = 0;
    while (pos < bytes.size()) {
        size_t end = bytes.find('\n', pos);
        size_t next = end == std::string_view::npos ? bytes.size() : end + 1;
        std::string_view line = bytes.substr(pos, next - pos);
        if (line.substr(0, kMarker.size()) == kMarker && out.parts.size() < kMaxParts) {
            std::string_view name = line.substr(kMarker.size());
            while (!name.empty() && (name.back() == '\n' || name.back() == '\r' || name.back() == ' ')) name.remove_suffix(1);
            out.parts.push_back({std::string(name), {}});
            current = &out.parts.back().text;
        } else {
            current->append(line);
        }
        pos = next;
    }
    return out;
}

const std::filesystem::path& freshScratchFolder() {
    if (!scratch) {
        scratch = new std::filesystem::path((scratchParent() / ("rmfx-fuzz-" + std::to_string(getpid()))).lexically_normal());
        std::atexit(removeScratch);
    }
    std::error_code ignored;
    std::filesystem::remove_all(*scratch, ignored);
    std::filesystem::create_directories(*scratch);
    return *scratch;
}

void writeParts(const std::vector<FuzzPart>& parts, const std::filesystem::path& folder) {
    for (const FuzzPart& part : parts) {
        if (!scratch || !safeName(part.name, folder)) continue;
        std::filesystem::path file = folder / part.name;
        std::error_code failed;
        std::filesystem::create_directories(file.parent_path(), failed);
        if (failed || std::filesystem::is_directory(file)) continue;  // "a" as a file, then "a/b"
        std::ofstream(file, std::ios::binary) << part.text;
    }
}

}  // namespace rmfx::fuzz
