#include "frontend/shader/HlslWritableGlobals.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string_view>

#include "core/IdentifierSearch.h"
#include "frontend/shader/HlslBlankedCode.h"

namespace rmfx {
namespace {

struct Global {
    std::string type;         // as written: "float4", "float4x4"
    std::string arraySuffix;  // "[8]" or empty
    std::string name;
    size_t statementEnd = 0;  // offset of the declaration's ';'
};

struct FunctionBody {
    std::string name;     // the function's
    std::string header;   // its signature, from the return type to ')'
    size_t open = 0;      // offset of '{'
    size_t close = 0;     // offset of the matching '}'
};

const std::set<std::string>& modifiers() {
    static const std::set<std::string> m = {"uniform", "extern", "shared", "volatile", "row_major", "column_major",
                                            "precise", "nointerpolation"};
    return m;
}

bool isObjectType(const std::string& type) {
    std::string lower = type;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    return lower.rfind("sampler", 0) == 0 || lower.rfind("texture", 0) == 0 || lower.rfind("rwtexture", 0) == 0 ||
           lower.rfind("buffer", 0) == 0 || lower.rfind("structuredbuffer", 0) == 0;
}

std::vector<std::string> identifiers(std::string_view s) {
    std::vector<std::string> out;
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
    std::vector<std::string> words;
    for (const std::string& w : identifiers(declarators)) {
        if (w == "static" || w == "const" || w == "struct" || w == "typedef" || w == "cbuffer" || w == "tbuffer") return std::nullopt;
        if (!modifiers().count(w)) words.push_back(w);
    }
    if (words.size() != 2 || std::isdigit(static_cast<unsigned char>(words[0][0])) ||
        std::isdigit(static_cast<unsigned char>(words[1][0])) || isObjectType(words[0]))
        return std::nullopt;
    g.type = words[0];
    g.name = words[1];
    g.statementEnd = end;
    return g;
}

// The file-scope globals and the function bodies of blanked code. cbuffer members are left out:
// their copy could not sit beside them.
void scan(const std::string& code, std::vector<Global>& globals, std::vector<FunctionBody>& bodies) {
    size_t start = 0;
    int depth = 0;
    size_t bodyOpen = 0;
    std::string pendingHeader;
    bool inFunction = false;
    for (size_t i = 0; i < code.size(); ++i) {
        const char c = code[i];
        if (c == '{') {
            if (depth == 0) {
                std::string_view statement(code.data() + start, i - start);
                size_t close = statement.rfind(')');
                inFunction = close != std::string_view::npos && statement.find('=') == std::string_view::npos &&
                             statement.find_first_not_of(" \t\r\n:", close + 1) == std::string_view::npos;
                if (!inFunction && close != std::string_view::npos) {
                    // `float4 main(…) : COLOR0 {`: a semantic after the parameters.
                    size_t colon = statement.find(':', close);
                    inFunction = colon != std::string_view::npos && statement.find('=') == std::string_view::npos;
                }
                pendingHeader = std::string(statement);
                bodyOpen = i;
            }
            ++depth;
        } else if (c == '}') {
            if (depth == 0) continue;  // unbalanced: glslang reports it
            if (--depth == 0) {
                if (inFunction) {
                    FunctionBody body;
                    body.header = pendingHeader;
                    size_t paren = pendingHeader.find('(');
                    std::vector<std::string> before = identifiers(std::string_view(pendingHeader).substr(0, paren));
                    body.name = before.empty() ? "" : before.back();
                    body.open = bodyOpen;
                    body.close = i;
                    bodies.push_back(std::move(body));
                }
                inFunction = false;
                // A struct or cbuffer ends with its own ';'; a function body does not.
                start = i + 1;
            }
        } else if (c == ';' && depth == 0) {
            if (auto g = globalDeclaration(std::string_view(code.data() + start, i - start), i)) globals.push_back(std::move(*g));
            start = i + 1;
        }
    }
}

bool isWord(const std::string& code, size_t at, size_t length) {
    return (at == 0 || !isIdentifierChar(code[at - 1])) && (at + length >= code.size() || !isIdentifierChar(code[at + length]));
}

size_t skipSpace(const std::string& code, size_t i) {
    while (i < code.size() && std::isspace(static_cast<unsigned char>(code[i]))) ++i;
    return i;
}

// Whether the use of a name at [at, at + length) is assigned to: followed, after any `.member` or
// `[index]`, by an assignment operator or ++/--, or preceded by ++/--.
bool assignedAt(const std::string& code, size_t at, size_t length, size_t limit) {
    size_t back = at;
    while (back > 0 && std::isspace(static_cast<unsigned char>(code[back - 1]))) --back;
    if (back >= 2 && ((code[back - 1] == '+' && code[back - 2] == '+') || (code[back - 1] == '-' && code[back - 2] == '-')))
        return true;
    size_t i = skipSpace(code, at + length);
    while (i < limit) {
        if (code[i] == '.') {
            i = skipSpace(code, i + 1);
            while (i < limit && isIdentifierChar(code[i])) ++i;
            i = skipSpace(code, i);
        } else if (code[i] == '[') {
            int nesting = 0;
            for (; i < limit; ++i) {
                if (code[i] == '[') ++nesting;
                if (code[i] == ']' && --nesting == 0) break;
            }
            i = skipSpace(code, i + 1);
        } else {
            break;
        }
    }
    if (i >= limit) return false;
    const std::string_view rest(code.data() + i, std::min<size_t>(3, limit - i));
    if (rest.starts_with("++") || rest.starts_with("--")) return true;
    if (rest.starts_with("==")) return false;
    if (rest.starts_with("=")) return true;
    for (const char* op : {"+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>="})
        if (rest.starts_with(op)) return true;
    return false;
}

// Whether a function declares `name` itself (a parameter or a local), which hides the global there.
bool declaresItself(const std::string& code, const FunctionBody& body, const std::string& name) {
    for (const std::string& w : identifiers(body.header.substr(body.header.find('(') == std::string::npos ? 0 : body.header.find('('))))
        if (w == name) return true;
    for (size_t at = code.find(name, body.open); at != std::string::npos && at < body.close; at = code.find(name, at + 1)) {
        if (!isWord(code, at, name.size())) continue;
        size_t back = at;
        while (back > body.open && std::isspace(static_cast<unsigned char>(code[back - 1]))) --back;
        if (back == body.open || !isIdentifierChar(code[back - 1])) continue;
        size_t word = back;
        while (word > body.open && isIdentifierChar(code[word - 1])) --word;
        const std::string previous = code.substr(word, back - word);
        // `float4 name`, `half name`: a type before it. `return name` and the like are uses.
        static const std::set<std::string> notTypes = {"return", "else", "case", "do", "in", "out", "inout"};
        if (!notTypes.count(previous) && !std::isdigit(static_cast<unsigned char>(previous[0]))) return true;
    }
    return false;
}

}  // namespace

HlslWritableGlobals giveWrittenGlobalsACopy(const std::string& source, const std::string& entryPoint) {
    HlslWritableGlobals out;
    out.code = source;
    const std::string code = blankedHlsl(source);
    std::vector<Global> globals;
    std::vector<FunctionBody> bodies;
    scan(code, globals, bodies);
    const FunctionBody* entry = nullptr;
    for (const FunctionBody& b : bodies)
        if (b.name == entryPoint) entry = &b;
    if (!entry) return out;

    // Per global: the bodies that use it as the global (not declaring their own), and whether one writes it.
    std::vector<const Global*> written;
    std::map<std::string, std::vector<const FunctionBody*>> usedIn;
    for (const Global& g : globals) {
        bool writes = false;
        for (const FunctionBody& b : bodies) {
            if (declaresItself(code, b, g.name)) continue;
            usedIn[g.name].push_back(&b);
            for (size_t at = code.find(g.name, b.open); at != std::string::npos && at < b.close; at = code.find(g.name, at + 1))
                if (isWord(code, at, g.name.size()) && assignedAt(code, at, g.name.size(), b.close)) writes = true;
        }
        if (writes && std::none_of(written.begin(), written.end(), [&](const Global* w) { return w->name == g.name; }))
            written.push_back(&g);
    }
    if (written.empty()) return out;

    // Edits from the end backwards, so that earlier offsets stay valid.
    std::vector<std::pair<size_t, std::pair<size_t, std::string>>> edits;  // offset → (length replaced, text)
    std::string copies;
    for (const Global* g : written) {
        const std::string copy = "rm_writable_" + g->name;
        edits.push_back({g->statementEnd + 1, {0, " static " + g->type + " " + copy + g->arraySuffix + ";"}});
        copies += " " + copy + " = " + g->name + ";";
        for (const FunctionBody* b : usedIn[g->name])
            for (size_t at = code.find(g->name, b->open); at != std::string::npos && at < b->close; at = code.find(g->name, at + 1))
                if (isWord(code, at, g->name.size())) edits.push_back({at, {g->name.size(), copy}});
        out.written.push_back(g->name);
        out.lines.push_back(1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<long>(g->statementEnd), '\n')));
    }
    edits.push_back({entry->open + 1, {0, copies}});
    std::sort(edits.begin(), edits.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [at, edit] : edits) out.code.replace(at, edit.first, edit.second);
    return out;
}

}  // namespace rmfx
