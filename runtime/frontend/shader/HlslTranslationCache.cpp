#include "frontend/shader/HlslTranslationCache.h"

namespace rmfx {
namespace {

// Each field with its length first, so that no two argument lists make the same key.
void append(std::string& key, const std::string& field) {
    key += std::to_string(field.size());
    key += ':';
    key += field;
}

std::string cacheKey(const PreprocessedShader& hlsl, const HlslStage& stage, const SourceLocation& where,
                     const std::string& element) {
    std::string key;
    append(key, hlsl.code);
    for (const SourceLocation& origin : hlsl.lineOrigins) {
        append(key, origin.file);
        append(key, std::to_string(origin.line));
    }
    key += '|';
    for (const std::filesystem::path& file : hlsl.files) append(key, file.string());
    key += '|';
    append(key, stage.stage == ShaderStage::Vertex ? "vertex" : "fragment");
    append(key, stage.entryPoint);
    append(key, stage.profile);
    append(key, where.file);
    append(key, std::to_string(where.line));
    append(key, element);
    return key;
}

}  // namespace

HlslTranslationCache::HlslTranslationCache(size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}

HlslTranslationCache& HlslTranslationCache::shared() {
    static HlslTranslationCache cache;
    return cache;
}

Result<HlslTranslation> HlslTranslationCache::translate(const PreprocessedShader& hlsl, const HlslStage& stage,
                                                        const SourceLocation& where, const std::string& element) {
    std::string key = cacheKey(hlsl, stage, where, element);
    {
        std::lock_guard lock(mutex_);
        if (auto it = entries_.find(key); it != entries_.end()) {
            recency_.splice(recency_.begin(), recency_, it->second.recency);
            return it->second.result;
        }
    }
    // Translated without the lock: two threads asking for the same new key both translate, and
    // the first to finish is kept.
    Result<HlslTranslation> result = translateHlslStage(hlsl, stage, where, element);
    std::lock_guard lock(mutex_);
    ++translations_;
    if (entries_.count(key)) return result;
    recency_.push_front(key);
    entries_.emplace(std::move(key), Entry{result, recency_.begin()});
    if (entries_.size() > capacity_) {
        entries_.erase(recency_.back());
        recency_.pop_back();
    }
    return result;
}

size_t HlslTranslationCache::translations() const {
    std::lock_guard lock(mutex_);
    return translations_;
}

size_t HlslTranslationCache::size() const {
    std::lock_guard lock(mutex_);
    return entries_.size();
}

}  // namespace rmfx
