#include "frontend/shader/HlslWritableGlobals.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_set>

#include "core/IdentifierSearch.h"
#include "core/TextEdits.h"
#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {
namespace {

struct Global {
    std::string type;         // as written: "float4", "float4x4"
    std::string arraySuffix;  // "[8]" or empty
    std::string name;
    size_t statementEnd = 0;  // offset of the declaration's ';'
    size_t nameAt = 0;        // offset of its name
};

// Views of the scanned code, which outlives them: a shader expanded to megabytes by its
// includes can have hundreds of thousands of bodies, and a string each was most of the scan.
struct FunctionBody {
    std::string_view name;    // the function's
    std::string_view header;  // its signature, from the return type to ')'
    size_t open = 0;      // offset of '{'
    size_t close = 0;     // offset of the matching '}'
};

const std::set<std::string, std::less<>>& modifiers() {
    static const std::set<std::string, std::less<>> m = {"uniform", "extern", "shared", "volatile", "row_major", "column_major",
                                            "precise", "nointerpolation"};
    return m;
}

bool isObjectType(std::string_view type) {
    auto startsWithIgnoringCase = [&](std::string_view prefix) {
        return type.size() >= prefix.size() && std::equal(prefix.begin(), prefix.end(), type.begin(), [](char p, char t) {
                   return p == std::tolower(static_cast<unsigned char>(t));
               });
    };
    return startsWithIgnoringCase("sampler") || startsWithIgnoringCase("texture") || startsWithIgnoringCase("rwtexture") ||
           startsWithIgnoringCase("buffer") || startsWithIgnoringCase("structuredbuffer");
}

// Views of `s`: a string each, per statement of a shader expanded to megabytes, was a fifth of
// the shader_preprocessor fuzz target's time under ASan.
std::vector<std::string_view> identifiers(std::string_view s) {
    std::vector<std::string_view> out;
    for (size_t i = 0; i < s.size();) {
        if (isIdentifierChar(s[i])) {
            size_t j = i;
            while (j < s.size() && isIdentifierChar(s[j])) ++j;
            out.emplace_back(s.substr(i, j - i));
            i = j;
        } else {
            ++i;
        }
    }
    return out;
}

// The last identifier in `s`; empty when there is none.
std::string_view lastIdentifier(std::string_view s) {
    size_t end = s.size();
    while (end > 0 && !isIdentifierChar(s[end - 1])) --end;
    size_t start = end;
    while (start > 0 && isIdentifierChar(s[start - 1])) --start;
    return s.substr(start, end - start);
}

// `TYPE NAME;`, `TYPE NAME[N] : register(c0);` or `TYPE NAME = default;` at file scope.
std::optional<Global> globalDeclaration(std::string_view text, size_t end) {
    std::string_view left = text.substr(0, text.find('='));
    if (size_t annotation = left.find('<'); annotation != std::string_view::npos) left = left.substr(0, annotation);
    if (size_t colon = left.find(':'); colon != std::string_view::npos) left = left.substr(0, colon);
    if (left.find_first_of("(){}") != std::string_view::npos) return std::nullopt;
    Global g;
    std::string_view declarators = left;
    if (size_t bracket = left.find('['); bracket != std::string_view::npos) {
        size_t close = left.find(']', bracket);
        if (close == std::string_view::npos) return std::nullopt;
        g.arraySuffix = std::string(left.substr(bracket, close - bracket + 1));
        declarators = left.substr(0, bracket);
    }
    std::vector<std::string_view> words;
    for (std::string_view w : identifiers(declarators)) {
        if (w == "static" || w == "const" || w == "struct" || w == "typedef" || w == "cbuffer" || w == "tbuffer") return std::nullopt;
        if (!modifiers().count(w)) words.push_back(w);
    }
    if (words.size() != 2 || std::isdigit(static_cast<unsigned char>(words[0][0])) ||
        std::isdigit(static_cast<unsigned char>(words[1][0])) || isObjectType(words[0]))
        return std::nullopt;
    g.type = std::string(words[0]);
    g.name = std::string(words[1]);
    g.statementEnd = end;
    g.nameAt = end - text.size() + declarators.rfind(g.name);
    return g;
}

// The file-scope globals and the function bodies of blanked code. cbuffer members are left out:
// their copy could not sit beside them.
void scan(const std::string& code, std::vector<Global>& globals, std::vector<FunctionBody>& bodies) {
    size_t start = 0;
    int depth = 0;
    size_t bodyOpen = 0;
    std::string_view pendingHeader;
    bool inFunction = false;
    bool initializer = false;  // the braces of `Wave waves[2] = { … };`, inside its statement
    // Whether the statement since `start` holds a '=' at file scope, kept as the scan goes: an
    // initializer's statement runs on to its ';', and reading it again at each of its '{' was
    // quadratic (`a b = 1{}{}{}…`, 16 kB: 88 ms).
    bool equalsSinceStart = false;
    // From one of the characters below to the next (std::string's search, a library call): a
    // step per byte was most of the scan under the fuzzers' instrumentation, a callback per
    // comparison.
    for (size_t i = code.find_first_of("={};"); i < code.size(); i = code.find_first_of("={};", i + 1)) {
        const char c = code[i];
        if (c == '=' && depth == 0) equalsSinceStart = true;
        if (c == '{') {
            if (depth == 0) {
                initializer = equalsSinceStart;
                inFunction = false;
                // Not an initializer: the statement ends at this brace's '}', so each is read once.
                if (!initializer) {
                    std::string_view statement(code.data() + start, i - start);
                    size_t close = statement.rfind(')');
                    inFunction = close != std::string_view::npos &&
                                 statement.find_first_not_of(" \t\r\n:", close + 1) == std::string_view::npos;
                    // `float4 main(…) : COLOR0 {`: a semantic after the parameters.
                    if (!inFunction && close != std::string_view::npos) inFunction = statement.find(':', close) != std::string_view::npos;
                    if (inFunction) pendingHeader = statement;
                }
                bodyOpen = i;
            }
            ++depth;
        } else if (c == '}') {
            if (depth == 0) continue;  // unbalanced: glslang reports it
            if (--depth == 0) {
                if (inFunction) {
                    FunctionBody body;
                    body.header = pendingHeader;
                    body.name = lastIdentifier(body.header.substr(0, body.header.find('(')));
                    body.open = bodyOpen;
                    body.close = i;
                    bodies.push_back(std::move(body));
                }
                inFunction = false;
                // A struct or cbuffer ends with its own ';'; a function body does not. An
                // initializer's ';' ends the declaration it is part of.
                if (!initializer) {
                    start = i + 1;
                    equalsSinceStart = false;
                }
            }
        } else if (c == ';' && depth == 0) {
            if (auto g = globalDeclaration(std::string_view(code.data() + start, i - start), i)) globals.push_back(std::move(*g));
            start = i + 1;
            equalsSinceStart = false;
        }
    }
}

size_t skipSpace(const std::string& code, size_t i, size_t limit) {
    while (i < limit && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
    return i;
}

// For each '[' the offset of its ']', npos where unmatched: found once, so that following
// `a[a[a[…` from each of its names does not read the rest again. Kept per '[' (in order, so found
// by binary search): a table with an entry per byte of the code, 8 bytes each, took more time to
// fill than the scan.
class MatchingBrackets {
public:
    explicit MatchingBrackets(const std::string& code) {
        std::vector<size_t> open;  // indices into pairs_
        for (size_t i = code.find_first_of("[]"); i < code.size(); i = code.find_first_of("[]", i + 1)) {
            if (code[i] == '[') {
                open.push_back(pairs_.size());
                pairs_.emplace_back(i, std::string::npos);
            } else if (code[i] == ']' && !open.empty()) {
                pairs_[open.back()].second = i;
                open.pop_back();
            }
        }
    }

    // The ']' of the '[' at `at`.
    size_t closeOf(size_t at) const {
        auto found = std::lower_bound(pairs_.begin(), pairs_.end(), at, [](const auto& pair, size_t offset) { return pair.first < offset; });
        return found != pairs_.end() && found->first == at ? found->second : std::string::npos;
    }

private:
    std::vector<std::pair<size_t, size_t>> pairs_;  // each '[' and its ']', by the '['
};

// One function body's identifiers that name a global: each occurrence's offset (a member after
// '.' is not one: `Out.lightDir.x = …` writes the output struct's member, not a global named
// lightDir, as in ATI's SpotlightWithBump), and those the function declares itself (a parameter,
// or a local: a name right after a word that can be a type), which hide the global there. Other
// words are not kept: a shader expanded to megabytes by its includes has hundreds of thousands.
struct BodyWords {
    std::vector<std::pair<std::string_view, size_t>> uses;  // in order, viewing the code
    std::set<std::string, std::less<>> declared;
};

BodyWords bodyWords(const std::string& code, const FunctionBody& body, const std::unordered_set<std::string_view>& globalNames) {
    BodyWords out;
    const size_t paren = body.header.find('(');
    for (std::string_view w : identifiers(body.header.substr(paren == std::string::npos ? 0 : paren)))
        if (globalNames.count(w)) out.declared.emplace(w);
    // `float4 name`, `half name`: a type before it. `return name` and the like are uses.
    static const std::set<std::string, std::less<>> notTypes = {"return", "else", "case", "do", "in", "out", "inout"};
    std::string_view previous;
    size_t previousEnd = std::string::npos;
    for (size_t i = body.open + 1; i < body.close;) {
        if (!isIdentifierChar(code[i])) {
            ++i;
            continue;
        }
        size_t j = i;
        while (j < body.close && isIdentifierChar(code[j])) ++j;
        const std::string_view word(code.data() + i, j - i);
        if (!globalNames.count(word)) {
            previous = word;
            previousEnd = j;
            i = j;
            continue;
        }
        size_t before = i;
        while (before > body.open + 1 && std::isspace(static_cast<unsigned char>(code[before - 1]))) --before;
        const bool member = code[before - 1] == '.' && !std::isdigit(static_cast<unsigned char>(word[0]));
        if (!member) out.uses.emplace_back(word, i);
        if (previousEnd != std::string::npos && skipSpace(code, previousEnd, i) == i && !notTypes.count(previous) &&
            !std::isdigit(static_cast<unsigned char>(previous[0])))
            out.declared.insert(std::string(word));
        previous = word;
        previousEnd = j;
        i = j;
    }
    return out;
}

// Whether the use of a name at [at, at + length) is assigned to: followed, after any `.member` or
// `[index]`, by an assignment operator or ++/--, or preceded by ++/--. `selectorEnd` remembers
// where each chain of selectors ends, so `a.a.a.…` is walked once, not once per name.
class Assignments {
public:
    Assignments(const std::string& code, const MatchingBrackets& brackets) : code_(code), brackets_(brackets) {}

    bool assignedAt(size_t at, size_t length, size_t limit) {
        size_t back = at;
        while (back > 0 && std::isspace(static_cast<unsigned char>(code_[back - 1]))) --back;
        if (back >= 2 && ((code_[back - 1] == '+' && code_[back - 2] == '+') || (code_[back - 1] == '-' && code_[back - 2] == '-')))
            return true;
        const size_t i = selectorsEnd(skipSpace(code_, at + length, limit), limit);
        if (i >= limit) return false;
        const std::string_view rest(code_.data() + i, std::min<size_t>(3, limit - i));
        if (rest.starts_with("++") || rest.starts_with("--")) return true;
        if (rest.starts_with("==")) return false;
        if (rest.starts_with("=")) return true;
        for (const char* op : {"+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="})
            if (rest.starts_with(op)) return true;
        return false;
    }

private:
    size_t selectorsEnd(size_t i, size_t limit) {
        std::vector<size_t> visited;
        while (i < limit && (code_[i] == '.' || code_[i] == '[')) {
            if (auto known = ends_.find(i); known != ends_.end()) {
                i = known->second;
                break;
            }
            visited.push_back(i);
            if (code_[i] == '.') {
                i = skipSpace(code_, i + 1, limit);
                while (i < limit && isIdentifierChar(code_[i])) ++i;
                i = skipSpace(code_, i, limit);
            } else {
                const size_t close = brackets_.closeOf(i);
                i = close == std::string::npos || close >= limit ? limit : skipSpace(code_, close + 1, limit);
            }
        }
        for (size_t v : visited) ends_[v] = i;
        return i;
    }

    const std::string& code_;
    const MatchingBrackets& brackets_;
    std::map<size_t, size_t> ends_;
};

// Line numbers by offset, by binary search over the newlines.
int lineOf(const std::vector<size_t>& newlines, size_t offset) {
    return 1 + static_cast<int>(std::lower_bound(newlines.begin(), newlines.end(), offset) - newlines.begin());
}

}  // namespace

HlslWritableGlobals giveWrittenGlobalsACopy(const std::string& source, const std::string& entryPoint) {
    return giveWrittenGlobalsACopy(source, BlankedHlsl(source), entryPoint);
}

HlslWritableGlobals giveWrittenGlobalsACopy(const std::string& source, const BlankedHlsl& blanked, const std::string& entryPoint) {
    HlslWritableGlobals out;
    out.code = source;
    const std::string& code = blanked.text;
    std::vector<Global> globals;
    std::vector<FunctionBody> bodies;
    scan(code, globals, bodies);
    const FunctionBody* entry = nullptr;
    for (const FunctionBody& b : bodies)
        if (b.name == entryPoint) entry = &b;
    if (!entry) return out;

    // Every step is linear in the code (or n log n): a file of thousands of globals and functions
    // once took the fuzzer's 10 s, one search of the whole code per global and function, and
    // 26 s, a lookup per global and function body.
    const MatchingBrackets brackets(code);
    Assignments assignments(code, brackets);
    // Per name, its uses in the bodies that do not declare one of their own, in order.
    struct Use {
        size_t at;
        size_t bodyClose;
    };
    std::map<std::string, std::vector<Use>, std::less<>> usesOutsideDeclarations;
    std::unordered_set<std::string_view> globalNames;
    for (const Global& g : globals) globalNames.insert(g.name);
    for (const FunctionBody& b : bodies) {
        const BodyWords words = bodyWords(code, b, globalNames);
        for (const auto& [name, at] : words.uses) {
            if (words.declared.count(name)) continue;
            auto uses = usesOutsideDeclarations.find(name);
            if (uses == usesOutsideDeclarations.end()) uses = usesOutsideDeclarations.emplace(std::string(name), std::vector<Use>{}).first;
            uses->second.push_back({at, b.close});
        }
    }
    auto usesOf = [&](const std::string& name) -> const std::vector<Use>* {
        auto found = usesOutsideDeclarations.find(name);
        return found == usesOutsideDeclarations.end() ? nullptr : &found->second;
    };

    // Per global: whether a body that does not declare its own writes it. The first declaration
    // of a name stands for any repeats (glslang reports the redefinition).
    std::set<std::string, std::less<>> seen;
    std::vector<const Global*> written;
    for (const Global& g : globals) {
        if (!seen.insert(g.name).second) continue;
        const std::vector<Use>* uses = usesOf(g.name);
        if (uses && std::any_of(uses->begin(), uses->end(),
                                [&](const Use& u) { return assignments.assignedAt(u.at, g.name.size(), u.bodyClose); }))
            written.push_back(&g);
    }
    if (written.empty()) return out;

    std::vector<size_t> newlines;
    for (size_t i = 0; i < code.size(); ++i)
        if (code[i] == '\n') newlines.push_back(i);
    std::vector<TextEdit> edits;
    std::string copies;
    for (const Global* g : written) {
        const std::string copy = "rm_writable_" + g->name;
        edits.push_back({g->statementEnd + 1, 0, " static " + g->type + " " + copy + g->arraySuffix + ";"});
        copies += " " + copy + " = " + g->name + ";";
        for (const Use& u : *usesOf(g->name)) edits.push_back({u.at, g->name.size(), copy});
        out.written.push_back(g->name);
        out.lines.push_back(lineOf(newlines, g->nameAt));
    }
    // At one offset insertions go first: `main(){gain = …` gets the copies before `gain`.
    edits.push_back({entry->open + 1, 0, copies});
    out.code = applyTextEdits(source, std::move(edits));
    return out;
}

}  // namespace rmfx
