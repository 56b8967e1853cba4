#include "frontend/reshade/ReshadeMacros.h"

#include <algorithm>
#include <deque>
#include <filesystem>

namespace rmfx {
namespace {

constexpr size_t kMaxNesting = 256;           // macros inside one another's expansion
constexpr size_t kMaxTokens = size_t(1) << 20;  // tokens one line may grow to
constexpr size_t kMaxExpansions = size_t(1) << 18;
constexpr int kMaxArgumentDepth = 64;  // arguments inside arguments, each expanded on its own

using Kind = PpToken::Kind;

PpTokens trimmed(PpTokens tokens) {
    // Blanks collapsed to one, none at either end.
    PpTokens out;
    for (PpToken& t : tokens) {
        if (t.isSpace() && (out.empty() || out.back().isSpace())) continue;
        if (t.isSpace()) t.text = " ";
        out.push_back(std::move(t));
    }
    while (!out.empty() && out.back().isSpace()) out.pop_back();
    return out;
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// `#param`: the argument's text as a string literal; quotes and backslashes inside its string and
// character literals escaped.
PpToken stringized(const PpTokens& argument) {
    std::string text = "\"";
    for (const PpToken& t : argument) {
        if (t.kind == Kind::String || t.kind == Kind::Char) {
            for (char c : t.text) {
                if (c == '"' || c == '\\') text += '\\';
                text += c;
            }
        } else {
            text += t.text;
        }
    }
    PpToken token;
    token.kind = Kind::String;
    token.text = text + "\"";
    return token;
}

void addHidden(std::vector<int>& hide, const std::vector<int>& more) {
    for (int id : more)
        if (!std::binary_search(hide.begin(), hide.end(), id)) hide.insert(std::upper_bound(hide.begin(), hide.end(), id), id);
}

class Expander {
public:
    Expander(MacroTable& macros, const ExpansionSite& site, std::vector<ExpansionProblem>& problems)
        : macros_(macros), site_(site), problems_(problems) {}

    PpTokens run(std::deque<PpToken> in, const MoreLines* more, int depth) {
        PpTokens out;
        while (!failed_ && !in.empty()) {
            PpToken token = std::move(in.front());
            in.pop_front();
            if (site_.protectDefined && token.is(Kind::Identifier, "defined")) {
                emit(out, std::move(token));
                while (!in.empty() && (in.front().isSpace() || in.front().isPunct("("))) {
                    emit(out, std::move(in.front()));
                    in.pop_front();
                }
                if (!in.empty() && in.front().kind == Kind::Identifier) {
                    emit(out, std::move(in.front()));
                    in.pop_front();
                }
                continue;
            }
            if (token.kind != Kind::Identifier || !substitute(token, in, more, depth)) emit(out, std::move(token));
            if (out.size() + in.size() > kMaxTokens) fail("", "macro expansion grows past " + std::to_string(kMaxTokens) + " tokens on one line");
        }
        return out;
    }

private:
    bool fill(std::deque<PpToken>& in, const MoreLines* more, bool onlyOpeningCall = false) {
        if (!more || !*more) return false;
        PpTokens next;
        if (!(*more)(next, onlyOpeningCall)) return false;
        in.insert(in.end(), std::make_move_iterator(next.begin()), std::make_move_iterator(next.end()));
        return true;
    }

    void emit(PpTokens& out, PpToken token) {
        if (!out.empty() && (token.expanded || out.back().expanded) && wouldGlue(out.back(), token)) {
            PpToken space;
            space.kind = Kind::Space;
            space.text = " ";
            out.push_back(std::move(space));
        }
        out.push_back(std::move(token));
    }

    void fail(const std::string& macro, const std::string& message) {
        if (!failed_) problems_.push_back({true, macro, message});
        failed_ = true;
    }

    // Replaces a macro name at the front of the input with its expansion, pushed back onto the
    // input to be scanned again. False when `name` stays as it is.
    bool substitute(const PpToken& name, std::deque<PpToken>& in, const MoreLines* more, int depth) {
        if (MacroTable::isBuiltIn(name.text)) {
            PpToken value;
            value.expanded = true;
            if (name.text == "__LINE__") {
                value.kind = Kind::Number;
                value.text = std::to_string(site_.line);
            } else {
                std::filesystem::path file(site_.file);
                value.kind = Kind::String;
                value.text = quoted(name.text == "__FILE__"        ? site_.file
                                    : name.text == "__FILE_NAME__" ? file.filename().string()
                                                                   : file.stem().string());
            }
            in.push_front(std::move(value));
            return true;
        }
        const ReshadeMacro* macro = macros_.find(name.text);
        if (!macro) return false;
        const int id = macros_.idOf(name.text);
        if (std::binary_search(name.hide.begin(), name.hide.end(), id)) return false;
        if (name.hide.size() >= kMaxNesting) {
            fail(name.text, "macro recursion too high (more than " + std::to_string(kMaxNesting) + " macros inside one another)");
            return true;
        }
        if (++expansions_ > kMaxExpansions) {
            fail(name.text, "more than " + std::to_string(kMaxExpansions) + " macro expansions on one line");
            return true;
        }
        std::vector<PpTokens> arguments;
        if (macro->functionLike) {
            size_t open = 0;
            while (true) {
                if (open == in.size() && !fill(in, more, true)) return false;
                if (!in[open].isSpace()) break;
                ++open;
            }
            if (!in[open].isPunct("(")) return false;  // a function-like macro's name alone is a name
            in.erase(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(open) + 1);
            if (!collectArguments(*macro, in, more, arguments)) return true;
            if (!argumentCountFits(*macro, arguments)) return true;
        }
        PpTokens body = replace(*macro, arguments, depth);
        std::vector<int> hide = name.hide;
        addHidden(hide, {id});
        for (auto it = body.rbegin(); it != body.rend(); ++it) {
            addHidden(it->hide, hide);
            it->expanded = true;
            in.push_front(std::move(*it));
        }
        return true;
    }

    bool collectArguments(const ReshadeMacro& macro, std::deque<PpToken>& in, const MoreLines* more,
                          std::vector<PpTokens>& arguments) {
        arguments.emplace_back();
        int nesting = 0;
        while (true) {
            if (in.empty() && !fill(in, more)) {
                fail(macro.name, "the arguments of macro '" + macro.name + "' are not closed before the next directive or the end of the file");
                return false;
            }
            PpToken t = std::move(in.front());
            in.pop_front();
            if (t.isPunct("(")) {
                ++nesting;
            } else if (t.isPunct(")")) {
                if (nesting-- == 0) break;
            } else if (t.isPunct(",") && nesting == 0 &&
                       !(macro.variadic && arguments.size() == macro.params.size())) {
                arguments.emplace_back();
                continue;
            }
            arguments.back().push_back(std::move(t));
            if (arguments.back().size() > kMaxTokens) {
                fail(macro.name, "an argument of macro '" + macro.name + "' grows past " + std::to_string(kMaxTokens) + " tokens");
                return false;
            }
        }
        for (PpTokens& a : arguments) a = trimmed(std::move(a));
        if (arguments.size() == 1 && arguments[0].empty() && macro.params.empty()) arguments.clear();
        if (macro.variadic && arguments.size() + 1 == macro.params.size()) arguments.emplace_back();
        return true;
    }

    bool argumentCountFits(const ReshadeMacro& macro, const std::vector<PpTokens>& arguments) {
        if (arguments.size() == macro.params.size()) return true;
        const bool few = arguments.size() < macro.params.size();
        problems_.push_back({false, macro.name,
                             std::string(few ? "not enough" : "too many") + " arguments for function-like macro invocation '" +
                                 macro.name + "' (" + std::to_string(arguments.size()) + " given, " +
                                 std::to_string(macro.params.size()) + " expected); the call is dropped"});
        return false;
    }

    PpTokens replace(const ReshadeMacro& macro, const std::vector<PpTokens>& arguments, int depth) {
        auto parameter = [&](const PpToken& t) -> int {
            if (t.kind != Kind::Identifier) return -1;
            auto it = std::find(macro.params.begin(), macro.params.end(), t.text);
            return it == macro.params.end() ? -1 : static_cast<int>(it - macro.params.begin());
        };
        auto nextSolid = [&](size_t k) {
            while (k < macro.body.size() && macro.body[k].isSpace()) ++k;
            return k;
        };
        std::vector<std::optional<PpTokens>> expandedArguments(arguments.size());
        PpTokens result;
        bool paste = false;  // the last piece was followed by ##
        auto append = [&](PpTokens piece, bool vaArgs) {
            if (paste) {
                paste = false;
                while (!result.empty() && result.back().isSpace()) result.pop_back();
                while (!piece.empty() && piece.front().isSpace()) piece.erase(piece.begin());
                if (piece.empty()) {
                    if (vaArgs && !result.empty() && result.back().isPunct(",")) result.pop_back();
                    return;
                }
                if (!result.empty()) {
                    PpTokens glued = tokenize(result.back().text + piece.front().text);
                    result.pop_back();
                    for (PpToken& g : glued) result.push_back(std::move(g));
                    piece.erase(piece.begin());
                }
            }
            for (PpToken& t : piece) result.push_back(std::move(t));
        };
        for (size_t k = 0; k < macro.body.size(); ++k) {
            const PpToken& t = macro.body[k];
            if (t.isPunct("##")) {
                paste = true;
                continue;
            }
            if (macro.functionLike && t.isPunct("#")) {
                size_t next = nextSolid(k + 1);
                if (next < macro.body.size() && parameter(macro.body[next]) >= 0) {
                    append({stringized(arguments[parameter(macro.body[next])])}, false);
                    k = next;
                    continue;
                }
            }
            const int p = parameter(t);
            if (p < 0) {
                if (t.isSpace() && paste) continue;
                append({t}, false);
                continue;
            }
            const size_t next = nextSolid(k + 1);
            const bool besidePaste = paste || (next < macro.body.size() && macro.body[next].isPunct("##"));
            const bool vaArgs = macro.variadic && static_cast<size_t>(p) + 1 == macro.params.size();
            if (besidePaste) {
                append(arguments[p], vaArgs);
            } else {
                if (!expandedArguments[p]) {
                    if (depth >= kMaxArgumentDepth) {
                        fail(macro.name, "macro arguments nested more than " + std::to_string(kMaxArgumentDepth) + " deep");
                        return {};
                    }
                    expandedArguments[p] = run(std::deque<PpToken>(arguments[p].begin(), arguments[p].end()), nullptr, depth + 1);
                }
                append(*expandedArguments[p], vaArgs);
            }
        }
        return result;
    }

    MacroTable& macros_;
    const ExpansionSite& site_;
    std::vector<ExpansionProblem>& problems_;
    size_t expansions_ = 0;
    bool failed_ = false;
};

}  // namespace

ParsedDefinition parseDefinition(const PpTokens& afterDirective) {
    ParsedDefinition parsed;
    size_t k = 0;
    while (k < afterDirective.size() && afterDirective[k].isSpace()) ++k;
    if (k == afterDirective.size() || afterDirective[k].kind != Kind::Identifier) {
        parsed.error = "macro name expected";
        return parsed;
    }
    ReshadeMacro macro;
    macro.name = afterDirective[k++].text;
    if (macro.name == "defined") {
        parsed.error = "macro name 'defined' is reserved";
        return parsed;
    }
    // Function-like only when '(' follows the name directly.
    if (k < afterDirective.size() && afterDirective[k].isPunct("(")) {
        macro.functionLike = true;
        ++k;
        bool expectName = true;
        while (true) {
            while (k < afterDirective.size() && afterDirective[k].isSpace()) ++k;
            if (k == afterDirective.size()) {
                parsed.error = "missing ')' in the parameters of macro '" + macro.name + "'";
                return parsed;
            }
            const PpToken& t = afterDirective[k++];
            if (t.isPunct(")") && (!expectName || macro.params.empty())) break;
            if (expectName && t.kind == Kind::Identifier) {
                if (std::find(macro.params.begin(), macro.params.end(), t.text) != macro.params.end()) {
                    parsed.error = "duplicate parameter '" + t.text + "' in macro '" + macro.name + "'";
                    return parsed;
                }
                macro.params.push_back(t.text);
                expectName = false;
            } else if (expectName && t.isPunct("...")) {
                macro.variadic = true;
                macro.params.push_back("__VA_ARGS__");
                expectName = false;
            } else if (!expectName && t.isPunct(",") && !macro.variadic) {
                expectName = true;
            } else {
                parsed.error = "unexpected '" + t.text + "' in the parameters of macro '" + macro.name + "'";
                return parsed;
            }
        }
    }
    macro.body = trimmed(PpTokens(afterDirective.begin() + static_cast<std::ptrdiff_t>(k), afterDirective.end()));
    const PpTokens& body = macro.body;
    if (!body.empty() && (body.front().isPunct("##") || body.back().isPunct("##"))) {
        parsed.error = "'##' cannot be at either end of macro '" + macro.name + "'";
        return parsed;
    }
    if (macro.functionLike)
        for (size_t i = 0; i < body.size(); ++i) {
            if (!body[i].isPunct("#")) continue;
            size_t next = i + 1;
            while (next < body.size() && body[next].isSpace()) ++next;
            if (next == body.size() || body[next].kind != Kind::Identifier ||
                std::find(macro.params.begin(), macro.params.end(), body[next].text) == macro.params.end()) {
                parsed.error = "'#' is not followed by a parameter of macro '" + macro.name + "'";
                return parsed;
            }
        }
    parsed.macro = std::move(macro);
    return parsed;
}

const ReshadeMacro* MacroTable::find(const std::string& name) const {
    auto it = macros_.find(name);
    return it == macros_.end() ? nullptr : &it->second;
}

bool MacroTable::define(ReshadeMacro macro) {
    std::string name = macro.name;
    return macros_.emplace(std::move(name), std::move(macro)).second;
}

void MacroTable::undefine(const std::string& name) { macros_.erase(name); }

bool MacroTable::isBuiltIn(const std::string& name) {
    return name == "__LINE__" || name == "__FILE__" || name == "__FILE_NAME__" || name == "__FILE_STEM__";
}

bool MacroTable::isDefined(const std::string& name) const { return isBuiltIn(name) || macros_.count(name) != 0; }

int MacroTable::idOf(const std::string& name) {
    return ids_.emplace(name, static_cast<int>(ids_.size())).first->second;
}

PpTokens expandMacros(PpTokens tokens, MacroTable& macros, const ExpansionSite& site, const MoreLines* more,
                      std::vector<ExpansionProblem>& problems) {
    Expander expander(macros, site, problems);
    return expander.run(std::deque<PpToken>(std::make_move_iterator(tokens.begin()), std::make_move_iterator(tokens.end())),
                        more, 0);
}

}  // namespace rmfx
