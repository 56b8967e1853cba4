#include "io/xml/XmlTagScanner.h"

#include <algorithm>
#include <charconv>

#include "core/Diagnostic.h"

namespace rmfx::xml {

const AttributeSpan* StartTag::attribute(std::string_view attributeName) const {
    for (const AttributeSpan& a : attributes)
        if (a.name == attributeName) return &a;
    return nullptr;
}

namespace {

struct Malformed {
    size_t offset = 0;
    std::string message;
};

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
bool endsName(char c) { return isSpace(c) || c == '/' || c == '>' || c == '=' || c == '<' || c == '"' || c == '\''; }

class Scanner {
public:
    explicit Scanner(std::string_view text) : t_(text) {}

    // False with `problem()` set at the first malformed construct.
    bool scan(std::vector<StartTag>& tags) {
        std::vector<int> open;  // indices of the elements not yet closed
        while ((i_ = t_.find('<', i_)) != std::string_view::npos) {
            size_t lt = i_;
            bool ok = true;
            if (startsWith("<!--")) {
                i_ += 4;
                ok = skipPast("-->", lt, "a comment (<!--)");
            } else if (startsWith("<![CDATA[")) {
                i_ += 9;
                ok = skipPast("]]>", lt, "a CDATA section");
            } else if (startsWith("<?")) {
                i_ += 2;
                ok = skipPast("?>", lt, "a processing instruction (<?)");
            } else if (startsWith("<!DOCTYPE")) {
                ok = skipDoctype(lt);
            } else if (startsWith("<!")) {
                ok = fail(lt, "unexpected markup '<!' (only comments, CDATA and a DOCTYPE start so)");
            } else if (startsWith("</")) {
                ok = endTag(lt, tags, open);
            } else {
                StartTag tag;
                ok = startTag(lt, open, tag);
                if (ok) {
                    tags.push_back(std::move(tag));
                    if (!tags.back().selfClosing) open.push_back(static_cast<int>(tags.size()) - 1);
                }
            }
            if (!ok) return false;
        }
        if (!open.empty()) {
            const StartTag& last = tags[open.back()];
            return fail(last.begin, "<" + last.name + "> is never closed (</" + last.name + "> expected)");
        }
        return true;
    }

    const Malformed& problem() const { return problem_; }

    int lineAt(size_t offset) {
        if (offset < lineOffset_) lineOffset_ = 0, line_ = 1;
        line_ += static_cast<int>(std::count(t_.begin() + lineOffset_, t_.begin() + offset, '\n'));
        lineOffset_ = offset;
        return line_;
    }

private:
    bool fail(size_t offset, std::string message) {
        problem_ = {offset, std::move(message)};
        return false;
    }

    bool startsWith(std::string_view s) const { return t_.substr(i_, s.size()) == s; }

    // Moves past `terminator`, which must follow; else the construct opened at `opened` is unterminated.
    bool skipPast(std::string_view terminator, size_t opened, const char* what) {
        size_t end = t_.find(terminator, i_);
        if (end == std::string_view::npos)
            return fail(opened, std::string(what) + " is never closed ('" + std::string(terminator) + "' expected)");
        i_ = end + terminator.size();
        return true;
    }

    void skipSpace() {
        while (i_ < t_.size() && isSpace(t_[i_])) ++i_;
    }

    std::string readName() {
        size_t start = i_;
        while (i_ < t_.size() && !endsName(t_[i_])) ++i_;
        return std::string(t_.substr(start, i_ - start));
    }

    bool skipDoctype(size_t opened) {
        i_ += 9;  // <!DOCTYPE
        int subset = 0;  // inside [ ... ], declarations may hold '>'
        while (i_ < t_.size()) {
            char c = t_[i_];
            size_t at = i_;
            bool ok = true;
            if (c == '"' || c == '\'') {
                ++i_;
                ok = skipPast(t_.substr(at, 1), at, "a quoted string in the DOCTYPE");
            } else if (subset && startsWith("<!--")) {
                ok = skipPast("-->", at, "a comment (<!--)");
            } else if (subset && startsWith("<?")) {
                ok = skipPast("?>", at, "a processing instruction (<?)");
            } else {
                if (c == '[') ++subset;
                else if (c == ']' && subset) --subset;
                else if (c == '>' && !subset) {
                    ++i_;
                    return true;
                }
                ++i_;
            }
            if (!ok) return false;
        }
        return fail(opened, "the DOCTYPE is never closed ('>' expected)");
    }

    bool endTag(size_t lt, const std::vector<StartTag>& tags, std::vector<int>& open) {
        i_ += 2;
        std::string name = readName();
        skipSpace();
        if (i_ >= t_.size() || t_[i_] != '>')
            return fail(lt, "the end tag </" + name + " is never closed ('>' expected)");
        ++i_;
        if (open.empty()) return fail(lt, "end tag </" + name + "> without a start tag");
        const StartTag& opener = tags[open.back()];
        if (opener.name != name)
            return fail(lt, "end tag </" + name + "> does not match <" + opener.name + "> (line " +
                                std::to_string(opener.line) + ")");
        open.pop_back();
        return true;
    }

    bool startTag(size_t lt, const std::vector<int>& open, StartTag& tag) {
        tag.begin = lt;
        tag.line = lineAt(lt);
        tag.depth = static_cast<int>(open.size());
        tag.parent = open.empty() ? -1 : open.back();
        ++i_;
        tag.name = readName();
        if (tag.name.empty()) return fail(lt, "'<' that starts no element (text writes it &lt;)");
        // Built only for a message: a string per tag was a tenth of a scan under ASan.
        auto label = [&tag] { return "<" + tag.name + ">"; };
        while (true) {
            skipSpace();
            if (i_ >= t_.size()) return fail(lt, label() + " is never closed ('>' expected)");
            if (t_[i_] == '>') {
                ++i_;
                break;
            }
            if (t_[i_] == '/') {
                if (i_ + 1 < t_.size() && t_[i_ + 1] == '>') {
                    tag.selfClosing = true;
                    i_ += 2;
                    break;
                }
                return fail(i_, "unexpected '/' in " + label());
            }
            AttributeSpan a;
            a.begin = i_;
            a.name = readName();
            if (a.name.empty()) return fail(i_, "unexpected '" + std::string(1, t_[i_]) + "' in " + label());
            skipSpace();
            if (i_ >= t_.size() || t_[i_] != '=')
                return fail(a.begin, "attribute '" + a.name + "' of " + label() + " has no value ('=' expected)");
            ++i_;
            skipSpace();
            if (i_ >= t_.size() || (t_[i_] != '"' && t_[i_] != '\''))
                return fail(a.begin, "the value of attribute '" + a.name + "' of " + label() + " must be in quotes");
            a.quote = t_[i_];
            a.valueBegin = ++i_;
            // Like tinyxml2, which reads the files, accept '<' inside a value and no space between attributes.
            size_t close = t_.find(a.quote, i_);
            if (close == std::string_view::npos)
                return fail(a.begin, "the value of attribute '" + a.name + "' of " + label() +
                                         " has no closing quote (" + std::string(1, a.quote) + ")");
            a.valueEnd = close;
            i_ = close + 1;
            if (tag.attribute(a.name)) return fail(a.begin, "attribute '" + a.name + "' is given twice in " + label());
            tag.attributes.push_back(std::move(a));
        }
        tag.end = i_;
        return true;
    }

    std::string_view t_;
    size_t i_ = 0;
    size_t lineOffset_ = 0;
    int line_ = 1;
    Malformed problem_;
};

void appendUtf8(std::string& out, unsigned code) {
    if (code < 0x80) {
        out += static_cast<char>(code);
    } else if (code < 0x800) {
        out += static_cast<char>(0xC0 | (code >> 6));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
        out += static_cast<char>(0xE0 | (code >> 12));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (code >> 18));
        out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (code & 0x3F));
    }
}

}  // namespace

Result<std::vector<StartTag>> scanStartTags(std::string_view text, const std::string& file) {
    std::vector<StartTag> tags;
    Scanner scanner(text);
    if (!scanner.scan(tags))
        return Error{Diagnostic{Diagnostic::Severity::Error, {file, scanner.lineAt(scanner.problem().offset)}, "",
                                "malformed XML: " + scanner.problem().message}
                         .format()};
    return tags;
}

std::string decodeAttributeValue(std::string_view raw) {
    static constexpr std::pair<std::string_view, char> named[] = {
        {"lt", '<'}, {"gt", '>'}, {"amp", '&'}, {"quot", '"'}, {"apos", '\''}};
    std::string out;
    for (size_t i = 0; i < raw.size(); ++i) {
        size_t semicolon = raw[i] == '&' ? raw.find(';', i) : std::string_view::npos;
        if (semicolon == std::string_view::npos) {
            out += raw[i];
            continue;
        }
        std::string_view ref = raw.substr(i + 1, semicolon - i - 1);
        bool decoded = false;
        for (const auto& [word, c] : named)
            if (ref == word) {
                out += c;
                decoded = true;
            }
        if (!decoded && ref.size() > 1 && ref[0] == '#') {
            bool hex = ref[1] == 'x';
            std::string_view digits = ref.substr(hex ? 2 : 1);
            unsigned code = 0;
            auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), code, hex ? 16 : 10);
            if (!digits.empty() && ec == std::errc() && end == digits.data() + digits.size() && code > 0 &&
                code <= 0x10FFFF) {
                appendUtf8(out, code);
                decoded = true;
            }
        }
        if (!decoded) {
            out += raw[i];
            continue;
        }
        i = semicolon;
    }
    return out;
}

}  // namespace rmfx::xml
