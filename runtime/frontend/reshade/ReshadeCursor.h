#pragma once
// The ReShade FX parser's walk over the tokens of preprocessed code (ReshadeLexer.h): looking
// ahead, taking what is expected, and reporting a problem at the user's file and line
// (PreprocessedReshade::origin). Used by ReshadeParser.cpp, ReshadeObjects.cpp,
// ReshadeTechniques.cpp and ReshadeConstant.cpp.
//
// A limit makes the tokens from some index on read as the end, so that a part (an initializer up
// to its ';') can be read on its own. After kMaxErrors errors the cursor stands at the end, so a
// broken file gives a bounded list.

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Diagnostic.h"
#include "frontend/reshade/ReshadeLexer.h"
#include "frontend/reshade/ReshadePreprocessor.h"

namespace rmfx {

class ReshadeCursor {
public:
    static constexpr size_t kMaxErrors = 100;

    ReshadeCursor(const PreprocessedReshade& source, std::vector<ReshadeToken> tokens, Diagnostics& diagnostics);

    const ReshadeToken& peek(size_t ahead = 0) const;
    std::string_view text(const ReshadeToken& token) const;
    std::string_view peekText(size_t ahead = 0) const { return text(peek(ahead)); }
    // The next token (or the one `ahead` after it) is an identifier or punctuator spelled `spelling`.
    bool is(std::string_view spelling, size_t ahead = 0) const;
    bool isKind(ReshadeToken::Kind kind, size_t ahead = 0) const { return peek(ahead).kind == kind; }
    bool atEnd() const { return peek().kind == ReshadeToken::Kind::End; }

    const ReshadeToken& next();  // the next token, stepping over it (never past the end)
    const ReshadeToken& previous() const;
    bool accept(std::string_view spelling);
    // Takes `spelling`, or reports "expected 'S', found 'X'" (a missing ';' or ')' at the line of
    // the token before, where it belongs) and returns false.
    bool expect(std::string_view spelling, const std::string& element);
    // Takes an identifier, or reports "expected WHAT, found 'X'".
    std::optional<std::string> expectIdentifier(const std::string& element, std::string_view what);

    SourceLocation where(const ReshadeToken& token) const { return source_.origin(token.line); }
    SourceLocation here() const { return where(peek()); }
    // "'x'", or "the end of the file".
    std::string describe(const ReshadeToken& token) const;

    // An error; the same error (place, element and message) twice in a row is kept once.
    void error(const SourceLocation& where, const std::string& element, const std::string& message);
    // Reads everything after as the end, with no more errors: a bound was passed.
    void abandon() { stopped_ = abandoned_ = true; }
    void warning(const SourceLocation& where, const std::string& element, const std::string& message);
    bool failed() const { return errors_ > 0; }
    size_t errorCount() const { return errors_; }

    size_t position() const { return position_; }
    void seek(size_t position) { position_ = position; }
    size_t limit() const { return limit_; }
    void setLimit(size_t limit) { limit_ = limit; }
    size_t size() const { return tokens_.size(); }
    const ReshadeToken& token(size_t index) const { return tokens_[std::min(index, tokens_.size() - 1)]; }
    const std::string& code() const { return source_.code; }

private:
    const PreprocessedReshade& source_;
    std::vector<ReshadeToken> tokens_;  // ends with End
    Diagnostics& diagnostics_;
    size_t position_ = 0;
    size_t limit_;
    size_t errors_ = 0;
    size_t lastError_ = SIZE_MAX;  // index in diagnostics_ of the last error reported
    bool stopped_ = false;      // too many errors: everything reads as the end
    bool abandoned_ = false;
    mutable ReshadeToken end_;  // what peek gives at the limit
};

}  // namespace rmfx
