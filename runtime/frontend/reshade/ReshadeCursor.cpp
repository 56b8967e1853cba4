#include "frontend/reshade/ReshadeCursor.h"

namespace rmfx {

ReshadeCursor::ReshadeCursor(const PreprocessedReshade& source, std::vector<ReshadeToken> tokens, Diagnostics& diagnostics)
    : source_(source), tokens_(std::move(tokens)), diagnostics_(diagnostics) {
    if (tokens_.empty() || tokens_.back().kind != ReshadeToken::Kind::End) tokens_.push_back({});
    limit_ = tokens_.size() - 1;
}

const ReshadeToken& ReshadeCursor::peek(size_t ahead) const {
    const size_t at = position_ + ahead;
    if (at < limit_ && !stopped_) return tokens_[at];
    end_ = tokens_[std::min(limit_, tokens_.size() - 1)];
    end_.kind = ReshadeToken::Kind::End;
    end_.length = 0;
    return end_;
}

std::string_view ReshadeCursor::text(const ReshadeToken& token) const {
    if (token.kind == ReshadeToken::Kind::End) return {};
    return std::string_view(source_.code).substr(token.offset, token.length);
}

bool ReshadeCursor::is(std::string_view spelling, size_t ahead) const {
    const ReshadeToken& t = peek(ahead);
    return (t.kind == ReshadeToken::Kind::Punct || t.kind == ReshadeToken::Kind::Identifier) && text(t) == spelling;
}

const ReshadeToken& ReshadeCursor::next() {
    const ReshadeToken& t = peek();
    if (position_ < limit_ && !stopped_) ++position_;
    return t;
}

const ReshadeToken& ReshadeCursor::previous() const {
    return tokens_[position_ == 0 ? 0 : std::min(position_, tokens_.size()) - 1];
}

bool ReshadeCursor::accept(std::string_view spelling) {
    if (!is(spelling)) return false;
    next();
    return true;
}

bool ReshadeCursor::expect(std::string_view spelling, const std::string& element) {
    if (accept(spelling)) return true;
    const bool belongsBefore = (spelling == ";" || spelling == ")" || spelling == "]") && position_ > 0;
    error(belongsBefore ? where(previous()) : here(), element,
          "expected '" + std::string(spelling) + "', found " + describe(peek()));
    return false;
}

std::optional<std::string> ReshadeCursor::expectIdentifier(const std::string& element, std::string_view what) {
    if (isKind(ReshadeToken::Kind::Identifier)) return std::string(text(next()));
    error(here(), element, "expected " + std::string(what) + ", found " + describe(peek()));
    return std::nullopt;
}

std::string ReshadeCursor::describe(const ReshadeToken& token) const {
    if (token.kind == ReshadeToken::Kind::End)
        return limit_ + 1 < tokens_.size() && !stopped_ ? describe(tokens_[limit_]) : "the end of the file";
    std::string_view t = text(token);
    if (t.size() > 40) return "'" + std::string(t.substr(0, 40)) + "…'";
    return "'" + std::string(t) + "'";
}

void ReshadeCursor::error(const SourceLocation& where, const std::string& element, const std::string& message) {
    if (errors_ >= kMaxErrors || abandoned_) return;
    if (lastError_ < diagnostics_.size()) {
        const Diagnostic& last = diagnostics_[lastError_];
        if (last.where.file == where.file && last.where.line == where.line && last.element == element && last.message == message) return;
    }
    lastError_ = diagnostics_.size();
    diagnostics_.push_back({Diagnostic::Severity::Error, where, element, message});
    if (++errors_ == kMaxErrors) {
        diagnostics_.push_back({Diagnostic::Severity::Error, where, "", "too many errors; the rest of the effect is not read"});
        stopped_ = true;
    }
}

void ReshadeCursor::warning(const SourceLocation& where, const std::string& element, const std::string& message) {
    diagnostics_.push_back({Diagnostic::Severity::Warning, where, element, message});
}

}  // namespace rmfx
