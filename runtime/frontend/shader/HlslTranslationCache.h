#pragma once
// HLSL translations by their input, so that a pass's HLSL is translated once per load although
// validation and the GL executor both assemble the pass (assemblePassProgram), and again on a
// reload only where the text changed.

#include <cstddef>
#include <list>
#include <mutex>
#include <string>
#include <unordered_map>

#include "frontend/shader/HlslTranslator.h"

namespace rmfx {

class HlslTranslationCache {
public:
    // Holds at most `capacity` translations; the least recently used goes first.
    explicit HlslTranslationCache(size_t capacity = defaultCapacity);
    HlslTranslationCache(const HlslTranslationCache&) = delete;
    HlslTranslationCache& operator=(const HlslTranslationCache&) = delete;

    // The one assemblePassProgram uses (process-wide, thread-safe).
    static HlslTranslationCache& shared();

    // translateHlslStage's result (its warnings or errors included) for these arguments, from the
    // cache when the same arguments were translated before. The key is everything the result
    // depends on: the preprocessed code, its line origins and files, the stage, entry point and
    // profile, and the location and element diagnostics are reported under.
    Result<HlslTranslation> translate(const PreprocessedShader& hlsl, const HlslStage& stage,
                                      const SourceLocation& where, const std::string& element);

    size_t translations() const;  // how many times translate() ran the translator
    size_t size() const;          // translations held

    static constexpr size_t defaultCapacity = 128;

private:
    struct Entry {
        Result<HlslTranslation> result;
        std::list<std::string>::iterator recency;
    };

    mutable std::mutex mutex_;
    size_t capacity_;
    size_t translations_ = 0;
    std::list<std::string> recency_;  // keys, most recently used first
    std::unordered_map<std::string, Entry> entries_;
};

}  // namespace rmfx
