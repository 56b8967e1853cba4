#include "frontend/reshade/ReshadePreprocessor.h"

#include "frontend/reshade/ReshadeExpression.h"
#include "frontend/reshade/ReshadeMacros.h"
#include "frontend/reshade/ReshadeTokens.h"
#include "frontend/shader/ShaderPreprocessor.h"

#include "io/media/MediaResolver.h"

#include <algorithm>
#include <map>
#include <set>

namespace rmfx {
namespace {

constexpr int kMaxIncludeDepth = 32;
constexpr size_t kMaxIncludes = 4096;
constexpr size_t kMaxBytesRead = size_t(16) << 20;
constexpr size_t kMaxOutputBytes = size_t(16) << 20;

using Kind = PpToken::Kind;

size_t skipSpace(const PpTokens& tokens, size_t k) {
    while (k < tokens.size() && tokens[k].isSpace()) ++k;
    return k;
}

PpTokens tail(const PpTokens& tokens, size_t k) {
    return PpTokens(tokens.begin() + static_cast<std::ptrdiff_t>(std::min(k, tokens.size())), tokens.end());
}

// The text of a string literal without its quotes (escapes kept as written).
std::string unquoted(const std::string& literal) {
    if (literal.size() >= 2 && literal.front() == '"' && literal.back() == '"') return literal.substr(1, literal.size() - 2);
    return literal;
}

std::string trimmedText(const PpTokens& tokens) {
    std::string text = joinTokens(tokens);
    const size_t first = text.find_first_not_of(" \t\f\v\r");
    if (first == std::string::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\f\v\r") - first + 1);
}

bool shownInReshadeUi(const std::string& name) {
    return name.size() >= 8 && name[0] != '_' && name.rfind("BUFFER_", 0) != 0 && name.rfind("RESHADE_", 0) != 0 &&
           name.find("INCLUDE_") == std::string::npos;
}

struct Conditional {
    bool parentActive = true;
    bool taken = false;   // a branch of this #if was active
    bool active = false;  // the current branch is
    bool seenElse = false;
    SourceLocation where;
    std::string directive;  // "#if", "#ifdef", "#ifndef" (for "unterminated")
    std::string guard;      // NAME of `#ifndef NAME`, whose `#define NAME` is the effect's default
};

struct FileState {
    std::string name;  // as origins and __FILE__ give it (#line may change it)
    std::filesystem::path folder;
    std::filesystem::path key;  // weakly canonical, for recursion and #pragma once
    std::vector<LogicalLine> lines;
    size_t next = 0;
    int lineDelta = 0;  // #line
    std::vector<Conditional> conditionals;

    bool active() const { return conditionals.empty() || conditionals.back().active; }
    SourceLocation at(int physical) const { return {name, physical + lineDelta}; }
};

// Whether a logical line is a directive: '#' first, blanks aside.
bool isDirective(const LogicalLine& line) {
    const size_t first = line.text.find_first_not_of(" \t\f\v\r");
    return first != std::string::npos && line.text[first] == '#' && line.text.compare(first, 2, "##") != 0;
}

class Run {
public:
    Run(const ReshadeInput& input, Diagnostics& diagnostics, PreprocessedReshade& out)
        : input_(input), diagnostics_(diagnostics), out_(out) {}

    void start() {
        defineFromSettings();
        std::error_code ignored;
        std::optional<std::string> text = input_.code;
        if (!text && std::filesystem::file_size(input_.file, ignored) > kMaxBytesRead && !ignored)
            return error({input_.file.string(), 0}, "", "the effect file is larger than " + std::to_string(kMaxBytesRead >> 20) + " MiB");
        if (!text) text = readShaderFile(input_.file);
        if (!text) return error({input_.file.string(), 0}, "", "cannot read the effect file");
        if (text->size() > kMaxBytesRead)
            return error({input_.file.string(), 0}, "", "the effect file is larger than " + std::to_string(kMaxBytesRead >> 20) + " MiB");
        FileState file;
        file.name = input_.file.string();
        file.folder = input_.file.parent_path();
        file.key = std::filesystem::weakly_canonical(input_.file, ignored);
        out_.files.push_back(input_.file);
        bytesRead_ = text->size();
        process(file, *text, 0);
        collectDefinitions();
    }

private:
    void report(Diagnostic::Severity severity, const SourceLocation& where, const std::string& element,
                const std::string& message) {
        diagnostics_.push_back({severity, where, element, message});
    }
    void error(const SourceLocation& where, const std::string& element, const std::string& message) {
        report(Diagnostic::Severity::Error, where, element, message);
    }
    void stop(const SourceLocation& where, const std::string& element, const std::string& message) {
        error(where, element, message);
        stopped_ = true;
    }

    void defineFromSettings() {
        auto predefine = [&](const std::string& name, const std::string& value, ReshadeMacro::Origin origin,
                             const std::string& element) {
            ParsedDefinition parsed = parseDefinition(tokenize(name + " " + value));
            if (!parsed.macro || parsed.macro->name != name || parsed.macro->functionLike) {
                error({}, element, "'" + name + "' is no macro name");
                return;
            }
            parsed.macro->origin = origin;
            if (!macros_.define(std::move(*parsed.macro)))
                report(Diagnostic::Severity::Warning, {}, element,
                       "'" + name + "' is already defined by ReShade; the value given is ignored");
        };
        for (const auto& [name, value] : predefinedMacros(input_.settings))
            predefine(name, value, ReshadeMacro::Origin::Predefined, "");
        if (input_.settings.compatibilityMacros)
            for (const LogicalLine& line : splitLogicalLines(reshadeCompatibilityMacros())) {
                PpTokens tokens = tokenize(line.text);
                ParsedDefinition parsed = parseDefinition(tail(tokens, skipSpace(tokens, 2)));
                parsed.macro->origin = ReshadeMacro::Origin::Predefined;
                macros_.define(std::move(*parsed.macro));
            }
        for (const std::string& define : input_.settings.defines) {
            auto [name, value] = splitDefine(define);
            predefine(name, value, ReshadeMacro::Origin::User, "define " + define);
        }
    }

    void emit(std::string text, SourceLocation where) {
        if (out_.code.size() + text.size() > kMaxOutputBytes) {
            if (!stopped_) stop(where, "", "the preprocessed effect grows past " + std::to_string(kMaxOutputBytes >> 20) + " MiB");
            return;
        }
        out_.code += text;
        out_.code += '\n';
        out_.lineOrigins.push_back(std::move(where));
    }
    void blanks(const FileState& file, int firstPhysical, int count) {
        for (int i = 0; i < count && !stopped_; ++i) emit("", file.at(firstPhysical + i));
    }

    void process(FileState& file, const std::string& text, int depth) {
        int unterminated = 0;
        file.lines = splitLogicalLines(text, &unterminated);
        if (unterminated) report(Diagnostic::Severity::Warning, file.at(unterminated), "", "unterminated /* comment");
        while (file.next < file.lines.size() && !stopped_) {
            const LogicalLine& line = file.lines[file.next++];
            if (isDirective(line)) directive(file, line, depth);
            else if (!file.active()) blanks(file, line.line, line.span);
            else textLine(file, line);
        }
        if (stopped_) return;
        for (const Conditional& open : file.conditionals) error(open.where, open.directive, "unterminated " + open.directive);
    }

    void textLine(FileState& file, const LogicalLine& line) {
        int span = line.span;
        MoreLines more = [&](PpTokens& tokens, bool onlyOpeningCall) {
            if (file.next >= file.lines.size() || isDirective(file.lines[file.next])) return false;
            const std::string& text = file.lines[file.next].text;
            const size_t first = text.find_first_not_of(" \t\f\v\r");
            if (onlyOpeningCall && (first == std::string::npos || text[first] != '(')) return false;
            const LogicalLine& next = file.lines[file.next++];
            span += next.span;
            PpToken lineBreak;
            lineBreak.kind = Kind::Space;
            lineBreak.text = " ";
            tokens.push_back(std::move(lineBreak));
            PpTokens nextTokens = tokenize(next.text);
            tokens.insert(tokens.end(), nextTokens.begin(), nextTokens.end());
            return true;
        };
        const SourceLocation where = file.at(line.line);
        std::vector<ExpansionProblem> problems;
        PpTokens expanded = expandMacros(tokenize(line.text), macros_, {file.name, where.line}, &more, problems);
        reportExpansion(problems, where);
        std::string text = joinTokens(expanded);
        text.erase(text.find_last_not_of(" \t\f\v\r") + 1);
        emit(std::move(text), where);
        blanks(file, line.line + 1, span - 1);
    }

    void reportExpansion(const std::vector<ExpansionProblem>& problems, const SourceLocation& where) {
        for (const ExpansionProblem& p : problems)
            report(p.error ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning, where,
                   p.macro.empty() ? "" : "macro " + p.macro, p.message);
    }

    PpTokens expandLine(const PpTokens& tokens, const SourceLocation& where, bool protectDefined = false) {
        std::vector<ExpansionProblem> problems;
        PpTokens expanded = expandMacros(tokens, macros_, {where.file, where.line, protectDefined}, nullptr, problems);
        reportExpansion(problems, where);
        return expanded;
    }

    void directive(FileState& file, const LogicalLine& line, int depth) {
        const PpTokens tokens = tokenize(line.text);
        size_t k = skipSpace(tokens, skipSpace(tokens, 0) + 1);
        const SourceLocation where = file.at(line.line);
        if (k == tokens.size()) return blanks(file, line.line, line.span);  // "#" alone
        const std::string name = tokens[k].kind == Kind::Identifier ? tokens[k].text : std::string();
        const std::string element = "#" + (name.empty() ? tokens[k].text : name);
        const PpTokens rest = tail(tokens, skipSpace(tokens, k + 1));
        if (name == "if" || name == "ifdef" || name == "ifndef" || name == "elif" || name == "else" || name == "endif") {
            conditional(file, name, rest, where, element);
        } else if (!file.active()) {
            if (name == "define") noteSkippedDefault(file, rest);
        } else if (name == "include") {
            blanks(file, line.line, line.span);  // the directive's own line first, then what it includes
            return include(file, rest, where, depth);
        } else if (name == "define") {
            define(file, rest, where);
        } else if (name == "undef") {
            if (rest.empty() || rest[0].kind != Kind::Identifier) error(where, element, "macro name expected");
            else if (rest[0].text == "defined") report(Diagnostic::Severity::Warning, where, element, "macro name 'defined' is reserved");
            else macros_.undefine(rest[0].text);
        } else if (name == "error") {
            stop(where, element, messageText(rest));
        } else if (name == "warning") {
            report(Diagnostic::Severity::Warning, where, element, messageText(rest));
        } else if (name == "pragma") {
            pragma(file, rest, where);
        } else if (name == "line") {
            blanks(file, line.line, line.span);
            return lineDirective(file, line, expandLine(rest, where), where);
        } else {
            error(where, element, "unrecognized preprocessing directive '" + (name.empty() ? tokens[k].text : name) + "'");
        }
        blanks(file, line.line, line.span);
    }

    static std::string messageText(const PpTokens& rest) {
        const std::string text = trimmedText(rest);
        if (rest.size() >= 1 && rest[0].kind == Kind::String && skipSpace(rest, 1) == rest.size()) return unquoted(rest[0].text);
        return text;
    }

    void conditional(FileState& file, const std::string& name, const PpTokens& rest, const SourceLocation& where,
                     const std::string& element) {
        auto& stack = file.conditionals;
        if (name == "if" || name == "ifdef" || name == "ifndef") {
            Conditional c;
            c.parentActive = file.active();
            c.where = where;
            c.directive = element;
            bool value = false;
            if (c.parentActive) {
                if (name == "if") {
                    value = evaluate(rest, where, element, file);
                } else if (rest.empty() || rest[0].kind != Kind::Identifier) {
                    error(where, element, "macro name expected");
                } else {
                    const std::string& macro = rest[0].text;
                    value = macros_.isDefined(macro) == (name == "ifdef");
                    noteTested(macro, where);
                    if (name == "ifndef") c.guard = macro;
                }
            }
            c.active = c.parentActive && value;
            c.taken = c.active;
            stack.push_back(std::move(c));
            return;
        }
        if (stack.empty()) return error(where, element, "missing #if for " + element);
        Conditional& c = stack.back();
        if (name == "endif") return stack.pop_back();
        if (c.seenElse) return error(where, element, element + " is not allowed after #else");
        c.guard.clear();
        if (name == "else") {
            c.seenElse = true;
            c.active = c.parentActive && !c.taken;
        } else {
            c.active = c.parentActive && !c.taken && evaluate(rest, where, element, file);
        }
        c.taken = c.taken || c.active;
    }

    // Records a macro an active #ifdef / #ifndef tested, as ReShade's used_macro_definitions does:
    // one not defined yet, or defined by ReShade or the user.
    void noteTested(const std::string& name, const SourceLocation& where) {
        const ReshadeMacro* macro = macros_.find(name);
        if (macro && macro->origin == ReshadeMacro::Origin::File) return;
        if (MacroTable::isBuiltIn(name)) return;
        if (tested_.emplace(name, where).second) testedOrder_.push_back(name);
    }

    // `#define NAME value` right inside a skipped `#ifndef NAME` (the user defined NAME): the
    // effect's default, for the overlay.
    void noteSkippedDefault(const FileState& file, const PpTokens& rest) {
        if (file.conditionals.empty()) return;
        const Conditional& c = file.conditionals.back();
        if (!c.parentActive || c.guard.empty() || c.active) return;
        ParsedDefinition parsed = parseDefinition(rest);
        if (parsed.macro && parsed.macro->name == c.guard && !parsed.macro->functionLike)
            defaults_.emplace(c.guard, parsed.macro->text());
    }

    // `defined X`, `defined(X)` and `exists "file"` replaced by 1 or 0 in `rest`, into `replaced`;
    // false (after an error) when one is malformed.
    bool replaceTests(const PpTokens& rest, PpTokens& replaced, const SourceLocation& where, const std::string& element,
                      const FileState& file) {
        for (size_t k = 0; k < rest.size(); ++k) {
            const PpToken& t = rest[k];
            if (t.kind != Kind::Identifier || (t.text != "defined" && t.text != "exists")) {
                replaced.push_back(t);
                continue;
            }
            size_t at = skipSpace(rest, k + 1);
            const bool parenthesized = at < rest.size() && rest[at].isPunct("(");
            if (parenthesized) at = skipSpace(rest, at + 1);
            PpToken value;
            value.kind = Kind::Number;
            if (t.text == "defined") {
                if (at == rest.size() || rest[at].kind != Kind::Identifier) {
                    error(where, element, "macro name expected after 'defined'");
                    return false;
                }
                value.text = macros_.isDefined(rest[at].text) ? "1" : "0";
            } else {
                // exists "file", exists("file"), exists(MACRO): the operand may be a macro.
                size_t end = at + 1;
                if (parenthesized) {
                    int nesting = 0;
                    for (end = at; end < rest.size(); ++end) {
                        if (rest[end].isPunct("(")) ++nesting;
                        if (rest[end].isPunct(")") && nesting-- == 0) break;
                    }
                }
                PpTokens operand = expandLine(PpTokens(rest.begin() + static_cast<std::ptrdiff_t>(std::min(at, rest.size())),
                                                       rest.begin() + static_cast<std::ptrdiff_t>(std::min(end, rest.size()))),
                                              where);
                const size_t s = skipSpace(operand, 0);
                if (s == operand.size() || operand[s].kind != Kind::String) {
                    error(where, element, "expected \"file\" after 'exists'");
                    return false;
                }
                value.text = locate(unquoted(operand[s].text), file) ? "1" : "0";
                at = end - 1;
            }
            if (parenthesized) {
                at = skipSpace(rest, at + 1);
                if (at == rest.size() || !rest[at].isPunct(")")) {
                    error(where, element, "missing ')' after '" + t.text + "'");
                    return false;
                }
            }
            replaced.push_back(std::move(value));
            k = at;
        }
        return true;
    }

    bool evaluate(const PpTokens& rest, const SourceLocation& where, const std::string& element, const FileState& file) {
        // The tests first, their operands not expanded; then again, for those that macros gave
        // (`#define HAS_X defined(X)`), whose operands the expansion left alone as ReShade does.
        PpTokens replaced, expanded, tested;
        if (!replaceTests(rest, replaced, where, element, file)) return false;
        expanded = expandLine(replaced, where, true);
        if (!replaceTests(expanded, tested, where, element, file)) return false;
        ExpressionValue result = evaluateExpression(tested);
        if (!result.error.empty()) error(where, element, result.error);
        return result.error.empty() && result.value != 0;
    }

    // Where `#include "name"` in `file` leads: its folder, then the include paths. As every file
    // reference in rmfx (io/media/MediaResolver.h): backslashes separate, and a name whose case
    // differs from the file's is found (effects are written on Windows: "Reshade.fxh").
    std::optional<std::filesystem::path> locate(const std::string& name, const FileState& file) {
        std::vector<std::filesystem::path> bases{file.folder.empty() ? std::filesystem::path(".") : file.folder};
        bases.insert(bases.end(), input_.settings.includePaths.begin(), input_.settings.includePaths.end());
        const MediaReference reference = MediaReference::parse(name);
        if (reference.components.empty() || reference.windowsAbsolute) return std::nullopt;
        if (reference.posixAbsolute) bases = {"/"};
        for (std::filesystem::path base : bases) {
            if (base.empty()) base = ".";
            std::string ambiguity;
            if (auto found = walkIgnoringCase(base, reference.components, &ambiguity)) {
                std::filesystem::path path = (base / *found).lexically_normal();
                if (file.folder.empty() && base == ".") path = *found;
                return path;
            }
        }
        return std::nullopt;
    }

    void include(FileState& file, PpTokens rest, const SourceLocation& where, int depth) {
        const std::string element = "#include";
        std::string name;
        size_t s = skipSpace(rest, 0);
        if (s < rest.size() && rest[s].isPunct("<")) {
            const std::string text = joinTokens(rest);
            const size_t open = text.find('<'), close = text.find('>', open + 1);
            if (close != std::string::npos) name = text.substr(open + 1, close - open - 1);
        } else {
            if (s == rest.size() || rest[s].kind != Kind::String) {
                rest = expandLine(rest, where);
                s = skipSpace(rest, 0);
            }
            if (s < rest.size() && rest[s].kind == Kind::String) name = unquoted(rest[s].text);
        }
        if (name.empty()) return error(where, element, "expected \"file\" or <file> after #include");
        if (++includes_ > kMaxIncludes)
            return stop(where, element, "more than " + std::to_string(kMaxIncludes) + " includes (is a file included over and over?)");
        if (depth + 1 > kMaxIncludeDepth)
            return stop(where, element, "includes nested more than " + std::to_string(kMaxIncludeDepth) + " deep at \"" + name + "\"");
        std::optional<std::filesystem::path> found = locate(name, file);
        if (!found) {
            std::string looked = file.folder.empty() ? "." : file.folder.string();
            for (const std::filesystem::path& p : input_.settings.includePaths) looked += ", " + (p.empty() ? "." : p.string());
            return error(where, element, "cannot find \"" + name + "\" (looked in " + looked + ")");
        }
        std::error_code ignored;
        FileState child;
        child.key = std::filesystem::weakly_canonical(*found, ignored);
        if (child.key == file.key || std::find(open_.begin(), open_.end(), child.key) != open_.end())
            return error(where, element, "recursive #include of \"" + name + "\"");
        if (once_.count(child.key)) return;
        // The size is checked before the file is read, so a huge file is never loaded whole.
        const uintmax_t size = std::filesystem::file_size(*found, ignored);
        if (!ignored && bytesRead_ + size > kMaxBytesRead)
            return stop(where, element, "the effect's includes read more than " + std::to_string(kMaxBytesRead >> 20) + " MiB");
        std::optional<std::string> text = readShaderFile(*found);
        if (!text) return error(where, element, "cannot read \"" + found->string() + "\"");
        if ((bytesRead_ += text->size()) > kMaxBytesRead)
            return stop(where, element, "the effect's includes read more than " + std::to_string(kMaxBytesRead >> 20) + " MiB");
        if (std::find(out_.files.begin(), out_.files.end(), *found) == out_.files.end()) out_.files.push_back(*found);
        child.name = found->string();
        child.folder = found->parent_path();
        open_.push_back(file.key);
        process(child, *text, depth + 1);
        open_.pop_back();
    }

    void define(FileState& file, const PpTokens& rest, const SourceLocation& where) {
        ParsedDefinition parsed = parseDefinition(rest);
        if (!parsed.macro) return error(where, "#define", parsed.error);
        ReshadeMacro& macro = *parsed.macro;
        macro.origin = ReshadeMacro::Origin::File;
        macro.where = where;
        const std::string name = macro.name;
        const std::string text = macro.text();
        if (const ReshadeMacro* existing = macros_.find(name)) {
            std::string first = existing->origin == ReshadeMacro::Origin::File
                                    ? existing->where.file + ":" + std::to_string(existing->where.line)
                                : existing->origin == ReshadeMacro::Origin::User ? "the user's definitions"
                                                                                : "ReShade";
            return error(where, "#define " + name, "redefinition of '" + name + "' (defined before by " + first + ")");
        }
        macros_.define(std::move(macro));
        if (!file.conditionals.empty() && file.conditionals.back().guard == name) defaults_.emplace(name, text);
    }

    void pragma(FileState& file, const PpTokens& rest, const SourceLocation& where) {
        if (rest.empty() || rest[0].kind != Kind::Identifier) return error(where, "#pragma", "pragma name expected");
        const std::string name = rest[0].text;
        const PpTokens arguments = tail(rest, skipSpace(rest, 1));
        if (name == "once") {
            once_.insert(file.key);
        } else if (name == "message") {
            PpTokens expanded = expandLine(arguments, where);
            std::string text;
            bool strings = !expanded.empty();
            for (const PpToken& t : expanded) {
                if (t.kind == Kind::String) text += unquoted(t.text);
                else if (!t.isSpace()) strings = false;
            }
            out_.messages.push_back({where, strings ? text : trimmedText(expanded)});
        } else if (name == "reshade" || name == "warning") {
            out_.pragmas.push_back({where, name, trimmedText(expandLine(arguments, where))});
        } else {
            report(Diagnostic::Severity::Warning, where, "#pragma " + name, "unknown pragma ignored");
        }
    }

    void lineDirective(FileState& file, const LogicalLine& line, const PpTokens& rest, const SourceLocation& where) {
        const size_t n = skipSpace(rest, 0);
        if (n == rest.size() || rest[n].kind != Kind::Number ||
            rest[n].text.find_first_not_of("0123456789") != std::string::npos || rest[n].text.size() > 9)
            return error(where, "#line", "#line takes a line number");
        const size_t f = skipSpace(rest, n + 1);
        if (f < rest.size() && rest[f].kind != Kind::String) return error(where, "#line", "#line takes a line number and a \"file\"");
        if (f < rest.size()) file.name = unquoted(rest[f].text);
        file.lineDelta = std::stoi(rest[n].text) - (line.line + line.span);
    }

    void collectDefinitions() {
        for (const std::string& name : testedOrder_) {
            const ReshadeMacro* macro = macros_.find(name);
            if (!macro || macro->functionLike) continue;
            ReshadeDefinition d;
            d.name = name;
            d.value = macro->text();
            auto found = defaults_.find(name);
            d.defaultValue = found != defaults_.end() ? found->second
                             : macro->origin == ReshadeMacro::Origin::File ? d.value
                                                                           : "";
            d.where = tested_.at(name);
            d.fromUser = macro->origin == ReshadeMacro::Origin::User;
            d.shownInUi = shownInReshadeUi(name);
            out_.definitions.push_back(std::move(d));
        }
        std::sort(out_.definitions.begin(), out_.definitions.end(),
                  [](const ReshadeDefinition& a, const ReshadeDefinition& b) { return a.name < b.name; });
    }

    const ReshadeInput& input_;
    Diagnostics& diagnostics_;
    PreprocessedReshade& out_;
    MacroTable macros_;
    std::vector<std::filesystem::path> open_;  // the files whose includes are being read
    std::set<std::filesystem::path> once_;
    std::map<std::string, SourceLocation> tested_;
    std::vector<std::string> testedOrder_;
    std::map<std::string, std::string> defaults_;
    size_t includes_ = 0;
    size_t bytesRead_ = 0;
    bool stopped_ = false;
};

}  // namespace

SourceLocation PreprocessedReshade::origin(int line) const {
    if (lineOrigins.empty()) return {};
    const size_t index = static_cast<size_t>(std::clamp(line, 1, static_cast<int>(lineOrigins.size()))) - 1;
    return lineOrigins[index];
}

PreprocessedReshade preprocessReshade(const ReshadeInput& input, Diagnostics& diagnostics) {
    PreprocessedReshade out;
    Run(input, diagnostics, out).start();
    return out;
}

}  // namespace rmfx
