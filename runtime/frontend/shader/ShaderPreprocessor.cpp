#include "frontend/shader/ShaderPreprocessor.h"

#include "frontend/shader/CompilerLogLine.h"

#include "io/media/MediaResolver.h"

#include <cctype>
#include <charconv>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace rmfx {
namespace {

// Views into `text`, which must outlive them; a trailing '\r' is dropped.
std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return lines;
}

std::string_view trimLeft(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

// "#  include" → "include"; empty when the line is no directive.
std::string directiveName(std::string_view line) {
    line = trimLeft(line);
    if (line.empty() || line.front() != '#') return {};
    line = trimLeft(line.substr(1));
    size_t n = 0;
    while (n < line.size() && std::isalpha(static_cast<unsigned char>(line[n]))) ++n;
    return std::string(line.substr(0, n));
}

// Whitespace as the C locale (and a regex's \s) has it.
std::string_view trimSpace(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// NAME of `#include "NAME"`, spaces allowed around each part and a // comment after; nullopt when
// the line, whose directive is include, has another form. No std::regex: libstdc++'s recurses
// once per character and overflows the stack on a line of some 40000.
std::optional<std::string> includedName(std::string_view line) {
    line = trimSpace(line.substr(line.find('#') + 1));
    line = trimSpace(line.substr(std::string_view("include").size()));
    if (line.size() < 3 || line.front() != '"') return std::nullopt;
    size_t close = line.find('"', 1);
    if (close == std::string_view::npos || close == 1) return std::nullopt;
    std::string_view rest = trimSpace(line.substr(close + 1));
    if (!rest.empty() && rest.substr(0, 2) != "//") return std::nullopt;
    return std::string(line.substr(1, close - 1));
}

// What one shader may expand to through its includes: a file or snippet included over and over
// (each including the next twice, say) would otherwise grow it exponentially. 65536 lines and
// 1 MiB are some 70 times the largest shader rmfx has met with its includes (effects/, tests/rfx/,
// 15 kB); every pass over the code after this one (the HLSL scans, glslang) costs in proportion.
constexpr size_t kMaxIncludes = 4096;
constexpr size_t kMaxExpandedLines = size_t(1) << 16;
constexpr size_t kMaxExpandedBytes = size_t(1) << 20;

class Expander {
public:
    Expander(const ShaderInput& input, Diagnostics& diagnostics, PreprocessedShader& out)
        : input_(input), diagnostics_(diagnostics), out_(out) {}

    void expand(const std::string& text, const std::string& file, int firstLine, const std::filesystem::path& folder,
                int depth) {
        auto lines = splitLines(text);
        for (size_t i = 0; i < lines.size() && !tooLarge_; ++i) {
            // Each line's origin is built once and moved into place: a copy of the file's name
            // per line (a heap block, under ASan a stack trace too) was most of the expansion.
            SourceLocation where{file, firstLine + static_cast<int>(i)};
            currentFile_ = &file;
            currentLine_ = where.line;
            if (++linesRead_ > kMaxExpandedLines || out_.code.size() + lines[i].size() > kMaxExpandedBytes)
                return stopGrowing(where);
            std::string directive = directiveName(lines[i]);
            if (directive == "include") {
                include(lines[i], where, folder, depth);
                currentFile_ = &file;  // back from the included text, whose name may be gone
                currentLine_ = where.line;
            } else if (directive == "pragma" && lines[i].find("once") != std::string::npos) {
                blank(std::move(where));
            } else {
                out_.code.append(lines[i]);
                out_.code += '\n';
                out_.lineOrigins.push_back(std::move(where));
            }
        }
    }

    // The line being expanded (an include's, while its file is looked up).
    SourceLocation current() const { return currentFile_ ? SourceLocation{*currentFile_, currentLine_} : SourceLocation{}; }

    // The top-level shader file, so that a file including itself is caught as a cycle.
    void openTopLevel(const std::filesystem::path& file) {
        stack_.push_back(std::filesystem::weakly_canonical(file));
        names_.push_back(file.filename().string());
    }

private:
    void blank(SourceLocation where) {
        out_.code += "\n";  // keeps line numbers aligned
        out_.lineOrigins.push_back(std::move(where));
    }

    void stopGrowing(const SourceLocation& where) {
        tooLarge_ = true;
        fail(where, "the shader grows past " + std::to_string(kMaxIncludes) + " includes, " +
                        std::to_string(kMaxExpandedLines) + " lines or " + std::to_string(kMaxExpandedBytes >> 20) +
                        " MiB through its includes (is a file included over and over?)");
    }

    void fail(const SourceLocation& where, const std::string& message) {
        diagnostics_.push_back({Diagnostic::Severity::Error, where, "#include", message});
        blank(where);
    }

    void include(std::string_view line, const SourceLocation& where, const std::filesystem::path& folder, int depth) {
        if (++includes_ > kMaxIncludes) return stopGrowing(where);
        std::optional<std::string> included = includedName(line);
        if (!included) return fail(where, "expected #include \"file\"");
        const std::string& name = *included;
        if (depth >= 32) return fail(where, "includes nested more than 32 deep (a cycle?) at \"" + name + "\"");
        if (input_.snippets)
            for (const CodeSnippet& snippet : *input_.snippets)
                if (snippet.name == name)
                    return enter("<snippet>/" + snippet.name, name, snippet.code,
                                 {snippet.where.file, snippet.codeLine}, folder, depth, where, nullptr);
        const Located& located = locate(name, folder);
        if (!located.failure.empty()) return fail(where, located.failure);
        const std::filesystem::path& candidate = located.file;
        std::ifstream in(candidate, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        enter(located.key, name, buffer.str(),
              {candidate.lexically_normal().string(), 1}, candidate.parent_path(), depth, where, &candidate);
    }

    struct Located {
        std::filesystem::path file;
        std::filesystem::path key;  // weakly canonical, for cycles and #pragma once
        std::string failure;        // why `file` is empty
    };

    // Where `#include "name"` in `folder` leads. Remembered: the file system does not change
    // while one shader expands, and a name included thousands of times (a fan-out the limits
    // above stop) would otherwise list its folders each time.
    const Located& locate(const std::string& name, const std::filesystem::path& folder) {
        auto key = std::make_pair(folder.string(), name);
        if (auto known = located_.find(key); known != located_.end()) return known->second;
        Located result;  // remembered only once complete: a file system error leaves nothing behind
        // As every file reference: backslashes separate, case is ignored when the exact name is
        // not there (MediaResolver); an absolute name is taken as it is, for the root check below.
        MediaReference reference = MediaReference::parse(name);
        std::string ambiguity;
        std::vector<std::filesystem::path> bases{folder, input_.root};
        if (reference.absolute()) bases = {reference.posixAbsolute ? "/" : ""};
        for (const std::filesystem::path& base : bases) {
            if (base.empty()) break;
            if (auto found = walkIgnoringCase(base, reference.components, &ambiguity)) {
                result.file = base / *found;
                break;
            }
            if (!ambiguity.empty()) {
                result.failure = "\"" + name + "\" is ambiguous: " + ambiguity;
                return located_.emplace(std::move(key), std::move(result)).first->second;
            }
        }
        if (result.file.empty())
            result.failure = "cannot find \"" + name + "\" (looked in " + folder.string() +
                             (folder == input_.root ? "" : " and " + input_.root.string()) + ")";
        else if (!liesInside(result.file, input_.root))
            result.failure = "\"" + name + "\" lies outside the workspace folder " + input_.root.string();
        if (!result.failure.empty()) result.file.clear();
        else result.key = std::filesystem::weakly_canonical(result.file);
        return located_.emplace(std::move(key), std::move(result)).first->second;
    }

    // Expands an included text unless it is already open (a cycle) or was marked #pragma once;
    // `file` (null for snippets) is recorded among the files the shader depends on.
    void enter(const std::filesystem::path& key, const std::string& name, const std::string& text,
               const SourceLocation& start, const std::filesystem::path& folder, int depth, const SourceLocation& where,
               const std::filesystem::path* file) {
        if (auto cycle = cycleThrough(key, name)) return fail(where, *cycle);
        if (onceFiles_.count(key)) return blank(where);
        if (file) out_.files.push_back(*file);
        for (const auto& l : splitLines(text))
            if (directiveName(l) == "pragma" && l.find("once") != std::string::npos) onceFiles_.insert(key);
        stack_.push_back(key);
        names_.push_back(name);
        expand(text, start.file, start.line, folder, depth + 1);
        stack_.pop_back();
        names_.pop_back();
    }

    // When `key` is already open: "include cycle: "a.glsl" → "b.glsl" → "a.glsl"", the includes that lead back to it.
    std::optional<std::string> cycleThrough(const std::filesystem::path& key, const std::string& name) const {
        for (size_t i = 0; i < stack_.size(); ++i) {
            if (stack_[i] != key) continue;
            std::string chain;
            for (size_t j = i; j < names_.size(); ++j) chain += "\"" + names_[j] + "\" → ";
            return "include cycle: " + chain + "\"" + name + "\"";
        }
        return std::nullopt;
    }

    const ShaderInput& input_;
    Diagnostics& diagnostics_;
    PreprocessedShader& out_;
    std::vector<std::filesystem::path> stack_;  // the files and snippets being included, outermost first
    std::vector<std::string> names_;            // the name each was included by
    std::set<std::filesystem::path> onceFiles_;
    std::map<std::pair<std::string, std::string>, Located> located_;  // by folder and name
    const std::string* currentFile_ = nullptr;  // of the line being expanded (its text's, which outlives it)
    int currentLine_ = 0;
    size_t includes_ = 0;    // #include lines met, whether they expand or fail
    size_t linesRead_ = 0;   // every line of every text expanded, include lines too
    bool tooLarge_ = false;  // past kMaxExpandedLines or kMaxExpandedBytes: the rest is dropped
};

}  // namespace

std::optional<std::string> readShaderFile(const std::filesystem::path& file) {
    std::error_code unreadable;
    if (!std::filesystem::is_regular_file(file, unreadable)) return std::nullopt;
    std::ifstream in(file, std::ios::binary);
    if (!in) return std::nullopt;
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

std::optional<OpeningVersion> openingVersion(const std::string& code) {
    size_t at = code.find_first_not_of(" \t");
    if (at == std::string::npos || code[at] != '#') return std::nullopt;
    at = code.find_first_not_of(" \t", at + 1);
    if (at == std::string::npos || code.compare(at, 7, "version") != 0) return std::nullopt;
    const size_t newline = code.find('\n', at);
    const std::string rest = code.substr(at + 7, newline == std::string::npos ? std::string::npos : newline - at - 7);
    OpeningVersion version;
    version.end = newline == std::string::npos ? code.size() : newline + 1;
    std::istringstream words(rest);
    std::string profile;
    words >> version.number >> profile;
    version.es = profile == "es";
    return version;
}

const char* defaultVersionLine(ShaderDialect dialect) {
    switch (dialect) {
        case ShaderDialect::Glsl: return "#version 450 core";
        case ShaderDialect::GlslEs100: return "#version 100";
        case ShaderDialect::GlslLegacy:
        case ShaderDialect::Hlsl: return "";
    }
    return "";
}

SourceLocation PreprocessedShader::origin(int line) const {
    if (lineOrigins.empty()) return {};
    if (line < 1) return lineOrigins.front();
    if (static_cast<size_t>(line) > lineOrigins.size()) return lineOrigins.back();
    return lineOrigins[line - 1];
}

PreprocessedShader preprocessShader(const ShaderInput& input, Diagnostics& diagnostics) {
    PreprocessedShader body;
    Expander expander(input, diagnostics, body);
    // Code read from a shader file starts at its line 1; inline code starts later in the workspace file.
    try {
        std::error_code unreadable;  // an unreadable top-level file is not one the includes can reach
        if (input.start.line == 1 && std::filesystem::is_regular_file(input.start.file, unreadable))
            expander.openTopLevel(input.start.file);
        expander.expand(input.code, input.start.file, input.start.line, input.folder, 0);
    } catch (const std::filesystem::filesystem_error& e) {
        // A name the file system refuses (a component over 255 bytes, a symlink loop, a folder it
        // may not search): the includes stop there with an error, as for a file not found.
        diagnostics.push_back({Diagnostic::Severity::Error, expander.current(), "#include",
                               "cannot look up \"" + e.path1().filename().string().substr(0, 64) + "\": " + e.code().message()});
    }

    // #version must come first; defines go right after it, mapped to the #version line.
    PreprocessedShader out;
    out.files = std::move(body.files);
    auto lines = splitLines(body.code);
    size_t versionLine = lines.size();
    for (size_t i = 0; i < lines.size(); ++i) {
        std::string d = directiveName(lines[i]);
        if (d == "version") {
            versionLine = i;
            break;
        }
        std::string_view t = trimLeft(lines[i]);
        if (!t.empty() && t.substr(0, 2) != "//") break;  // code before any #version
    }
    SourceLocation versionWhere = versionLine < lines.size() ? body.lineOrigins[versionLine] : input.start;
    if (versionLine < lines.size()) {
        out.code.append(lines[versionLine]);
        out.code += '\n';
        out.lineOrigins.push_back(versionWhere);
    } else if (std::string version = defaultVersionLine(input.dialect); !version.empty()) {
        out.code += version + "\n";
        out.lineOrigins.push_back(versionWhere);
    }
    for (const std::string& define : input.defines) {
        out.code += "#define " + define + "\n";
        out.lineOrigins.push_back(versionWhere);
    }
    for (const std::string& declaration : input.declarations) {
        out.code += declaration + "\n";
        out.lineOrigins.push_back(versionWhere);
    }
    out.code.reserve(out.code.size() + body.code.size());
    out.lineOrigins.reserve(out.lineOrigins.size() + lines.size());
    for (size_t i = 0; i < lines.size(); ++i) {
        if (i == versionLine) {
            out.code += "\n";  // the #version already went first
        } else {
            out.code.append(lines[i]);
            out.code += '\n';
        }
        out.lineOrigins.push_back(std::move(body.lineOrigins[i]));
    }
    return out;
}

Diagnostics mapCompilerLog(const std::string& log, const PreprocessedShader& shader, const SourceLocation& fallback,
                           const std::string& element) {
    // Line numbers too large for an int are past the end of the shader: its last line.
    auto lineNumber = [](std::string_view digits) {
        int n = 0;
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
        return ec == std::errc::result_out_of_range ? std::numeric_limits<int>::max() : n;
    };
    Diagnostics out;
    std::istringstream in(log);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        // A longer line (a huge identifier quoted back, say) keeps its first 4096 bytes.
        constexpr size_t kMaxLogLine = 4096;
        if (line.size() > kMaxLogLine) line = line.substr(0, kMaxLogLine) + "…";
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        Diagnostic d;
        d.element = element;
        if (std::optional<CompilerLogLine> parsed = parseCompilerLogLine(line)) {
            d.severity = parsed->error ? Diagnostic::Severity::Error : Diagnostic::Severity::Warning;
            d.where = shader.origin(lineNumber(parsed->lineDigits));
            d.message = parsed->message;
        } else {
            // glslang's summary lines ("ERROR: 1 compilation errors.  No code generated.") add nothing.
            if (line.find("compilation errors") != std::string::npos || line.find("No code generated") != std::string::npos)
                continue;
            d.where = fallback;
            d.message = line.rfind("ERROR: ", 0) == 0 ? line.substr(7) : line;
            d.severity = line.find("WARNING") == 0 ? Diagnostic::Severity::Warning : Diagnostic::Severity::Error;
        }
        // glslang ends its messages with a space.
        while (!d.message.empty() && (d.message.back() == ' ' || d.message.back() == '\t')) d.message.pop_back();
        out.push_back(std::move(d));
    }
    return out;
}

}  // namespace rmfx
