#include "io/media/MediaResolver.h"

#include "io/image/PlaceholderImage.h"
#include "io/mesh/StockModels.h"
#include "model/BuiltinMeshNames.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <memory>
#include <cctype>

namespace rmfx {

namespace fs = std::filesystem;

namespace {

// The by-name search stops there: a search folder is a media library, not a whole disk.
constexpr int kIndexDepth = 8;
constexpr size_t kIndexEntries = 100000;

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

std::string joined(const std::vector<std::string>& components, size_t first = 0) {
    std::string out;
    for (size_t i = first; i < components.size(); ++i) out += (out.empty() ? "" : "/") + components[i];
    return out;
}

bool isFile(const fs::path& p) {
    std::error_code ignored;
    return fs::is_regular_file(p, ignored);
}

bool isFolder(const fs::path& p) {
    std::error_code ignored;
    return fs::is_directory(p, ignored);
}

// The path with symbolic links resolved as far as it exists.
fs::path resolved(const fs::path& p) {
    std::error_code error;
    fs::path out = fs::weakly_canonical(fs::absolute(p, error), error);
    return error ? fs::absolute(p, error).lexically_normal() : out;
}

bool inside(const fs::path& file, const fs::path& folder) {
    auto [end, _] = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
    return end == folder.end() || (std::next(end) == folder.end() && end->empty());  // "a/b/" holds "a/b/c"
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

}  // namespace

MediaReference MediaReference::parse(const std::string& text) {
    MediaReference out;
    std::string path = text;
    std::replace(path.begin(), path.end(), '\\', '/');
    if (path.size() >= 2 && std::isalpha(static_cast<unsigned char>(path[0])) && path[1] == ':') {
        out.windowsAbsolute = true;  // C:\… or C:… (drive-relative): never a path on this machine
        path = path.substr(2);
    } else if (path.rfind("//", 0) == 0) {
        out.windowsAbsolute = true;  // \\server\share\…
    } else if (!path.empty() && path[0] == '/') {
        out.posixAbsolute = true;
    }
    size_t start = 0;
    while (start <= path.size()) {
        size_t end = path.find('/', start);
        if (end == std::string::npos) end = path.size();
        std::string part = path.substr(start, end - start);
        if (!part.empty() && part != ".") out.components.push_back(part);
        start = end + 1;
    }
    if (out.windowsAbsolute && text.rfind("\\\\", 0) == 0 && !out.components.empty())
        out.components.erase(out.components.begin());  // the server name
    return out;
}

std::vector<std::string> MediaReference::trailing() const {
    auto last = std::find(components.rbegin(), components.rend(), "..");
    return {last.base(), components.end()};
}

std::optional<fs::path> walkIgnoringCase(const fs::path& base, const std::vector<std::string>& relative,
                                         std::string* ambiguity) {
    if (relative.empty()) return std::nullopt;
    fs::path found;
    for (size_t i = 0; i < relative.size(); ++i) {
        const std::string& name = relative[i];
        if (name == "..") {
            found /= "..";
            continue;
        }
        bool last = i + 1 == relative.size();
        auto fits = [&](const fs::path& p) { return last ? isFile(p) : isFolder(p); };
        fs::path folder = base / found;
        if (fits(folder / name)) {
            found /= name;
            continue;
        }
        std::vector<std::string> matches;
        std::error_code error;
        std::string wanted = lower(name);
        for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
            std::string candidate = it->path().filename().string();
            if (lower(candidate) == wanted && fits(it->path())) matches.push_back(candidate);
        }
        if (matches.size() != 1) {
            if (matches.size() > 1 && ambiguity) {
                std::sort(matches.begin(), matches.end());
                std::string names;
                for (const std::string& m : matches) names += (names.empty() ? "" : ", ") + quoted(m);
                *ambiguity = quoted(name) + " matches " + names + " in " + (folder.lexically_normal().string()) +
                             " when case is ignored; rename one, or write the exact spelling";
            }
            return std::nullopt;
        }
        found /= matches[0];
    }
    if (!isFile(base / found)) return std::nullopt;  // "a/.." names a folder
    return found;
}

bool liesInside(const fs::path& file, const fs::path& folder) { return inside(resolved(file), resolved(folder)); }

namespace {

// Whether two files hold the same bytes (one file linked twice among them).
bool sameContent(const fs::path& a, const fs::path& b) {
    std::error_code error;
    if (fs::equivalent(a, b, error)) return true;
    const auto size = fs::file_size(a, error);
    if (error || fs::file_size(b, error) != size || error) return false;
    std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
    std::array<char, 65536> p{}, q{};
    while (x && y) {
        x.read(p.data(), p.size());
        y.read(q.data(), q.size());
        if (x.gcount() != y.gcount() || !std::equal(p.begin(), p.begin() + x.gcount(), q.begin())) return false;
    }
    return !x.bad() && !y.bad();
}

}  // namespace

MediaResolver::MediaResolver(fs::path workspaceFolder, MediaOptions options)
    : folder_(workspaceFolder.empty() ? fs::path(".") : std::move(workspaceFolder)), options_(std::move(options)) {
    roots_.push_back(resolved(folder_));
    for (const fs::path& dir : options_.searchPath) roots_.push_back(resolved(dir));
}

std::string MediaResolver::describeRoots() const {
    std::string out = "the workspace folder " + roots_[0].string();
    if (roots_.size() > 1) {
        out += " and the media folder" + std::string(roots_.size() > 2 ? "s " : " ");
        for (size_t i = 1; i < roots_.size(); ++i) out += (i > 1 ? ", " : "") + roots_[i].string();
    }
    return out;
}

bool MediaResolver::isAllowed(const fs::path& file) const {
    fs::path real = resolved(file);
    return std::any_of(roots_.begin(), roots_.end(), [&](const fs::path& root) { return inside(real, root); });
}

MediaResolver::Found MediaResolver::checked(fs::path file, const fs::path& opened, const std::string& reference,
                                            const std::string& noun) const {
    if (!options_.sandbox || isAllowed(opened)) return {std::move(file), {}};
    fs::path real = resolved(opened);
    std::error_code ignored;
    fs::path written = fs::absolute(opened, ignored).lexically_normal();
    bool throughLink = std::any_of(roots_.begin(), roots_.end(), [&](const fs::path& r) { return inside(written, r); });
    return {std::nullopt, noun + " " + quoted(reference) + " leads outside the sandbox" +
                              (throughLink ? " through a symbolic link" : "") + ": it is " + real.string() +
                              ", and the sandbox allows only " + describeRoots() +
                              " (give its folder with --media DIR, or run with --no-sandbox)"};
}

const std::multimap<std::string, fs::path>& MediaResolver::indexOf(const fs::path& folder) {
    auto [it, added] = indexes_.try_emplace(folder);
    if (!added) return it->second;
    std::error_code error;
    size_t seen = 0;
    for (fs::recursive_directory_iterator walk(folder, fs::directory_options::skip_permission_denied, error), end;
         !error && walk != end && ++seen <= kIndexEntries; walk.increment(error)) {
        if (walk.depth() >= kIndexDepth) walk.disable_recursion_pending();
        if (isFile(walk->path())) it->second.emplace(lower(walk->path().filename().string()), walk->path());
    }
    return it->second;
}

MediaResolver::Found MediaResolver::resolve(const std::string& reference, const std::string& noun) {
    MediaReference ref = MediaReference::parse(reference);
    if (ref.components.empty()) return {std::nullopt, noun + " " + quoted(reference) + " names no file"};
    std::vector<std::string> looked;
    std::string ambiguity;
    auto ambiguous = [&] { return Found{std::nullopt, noun + " " + quoted(reference) + " is ambiguous: " + ambiguity}; };

    if (ref.posixAbsolute) {
        if (auto found = walkIgnoringCase("/", ref.components, &ambiguity)) {
            fs::path file = (fs::path("/") / *found).lexically_normal();
            return checked(file, file, reference, noun);
        }
        if (!ambiguity.empty()) return ambiguous();
        looked.push_back("for /" + joined(ref.components) + " (ignoring case)");
    } else if (!ref.windowsAbsolute) {
        if (auto found = walkIgnoringCase(folder_, ref.components, &ambiguity))
            return checked(found->lexically_normal(), folder_ / *found, reference, noun);
        if (!ambiguity.empty()) return ambiguous();
        std::error_code ignored;
        fs::path tried = fs::absolute(folder_ / joined(ref.components), ignored).lexically_normal();
        looked.push_back("for " + tried.string() + " (ignoring case)");
    }

    std::vector<std::string> tail = ref.trailing();
    for (const fs::path& dir : options_.searchPath) {
        for (size_t first = 0; first + 1 < tail.size(); ++first) {
            std::vector<std::string> part(tail.begin() + static_cast<long>(first), tail.end());
            if (auto found = walkIgnoringCase(dir, part, &ambiguity)) {
                std::error_code ignored;
                fs::path file = fs::absolute(dir / *found, ignored).lexically_normal();
                return checked(file, file, reference, noun);
            }
            if (!ambiguity.empty()) return ambiguous();
        }
        if (tail.size() < 2) continue;
        std::string tried;
        for (size_t first = 0; first + 1 < tail.size(); ++first) tried += (first ? ", " : "") + joined(tail, first);
        looked.push_back("in " + dir.string() + " by trailing components (" + tried + ")");
    }
    const std::string& name = tail.empty() ? ref.components.back() : tail.back();
    for (const fs::path& dir : options_.searchPath) {
        auto [begin, end] = indexOf(dir).equal_range(lower(name));
        std::vector<fs::path> matches;
        for (auto it = begin; it != end; ++it) matches.push_back(it->second);
        if (matches.size() == 1) {
            std::error_code ignored;
            fs::path file = fs::absolute(matches[0], ignored).lexically_normal();
            return checked(file, file, reference, noun);
        }
        if (matches.size() > 1) {
            std::sort(matches.begin(), matches.end());
            // Copies of one file (a repository keeping RenderMonkey's Teapot.3ds in several
            // folders) are that file: the first is taken.
            if (std::all_of(matches.begin() + 1, matches.end(), [&](const fs::path& m) { return sameContent(matches[0], m); })) {
                std::error_code ignored;
                fs::path file = fs::absolute(matches[0], ignored).lexically_normal();
                return checked(file, file, reference, noun);
            }
            ambiguity = "the file name " + quoted(name) + " matches";
            for (size_t i = 0; i < matches.size(); ++i) ambiguity += (i ? ", " : " ") + matches[i].string();
            ambiguity += " under the media folder " + dir.string() + "; write more of its path, or give a narrower --media folder";
            return ambiguous();
        }
        looked.push_back("in " + dir.string() + " and its subfolders by file name " + quoted(name) + " (ignoring case)");
    }

    std::string message = noun + " " + quoted(reference) + " not found: ";
    if (ref.windowsAbsolute)
        message += "a Windows absolute path is not taken literally, only its trailing components are searched for in "
                   "the media folders";
    else
        message += "looked";
    for (size_t i = 0; i < looked.size(); ++i) message += (i ? "; " : ref.windowsAbsolute ? ": " : " ") + looked[i];
    if (options_.searchPath.empty()) message += "; no media folders were given (add one with --media DIR)";
    return {std::nullopt, message, true};
}

// The reference's file name without its extension, in lower case ("" for none).
static std::string lowerCaseStem(const std::string& reference) {
    MediaReference ref = MediaReference::parse(reference);
    if (ref.components.empty()) return "";
    std::string stem = std::filesystem::path(ref.components.back()).stem().string();
    std::transform(stem.begin(), stem.end(), stem.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return stem;
}

std::optional<BuiltinMesh> stockModelStandIn(const std::string& reference) {
    const std::string stem = lowerCaseStem(reference);
    if (std::optional<StockModel> stock = findStockModel(stem)) return stock->standIn;
    if (stem == "cube") return BuiltinMesh::Cube;  // no public copy measured: sized to the camera
    return std::nullopt;
}

BuiltinMesh placeholderMeshFor(const std::string& reference) {
    if (auto stock = stockModelStandIn(reference)) return *stock;
    const std::string stem = lowerCaseStem(reference);
    for (BuiltinMesh named : {BuiltinMesh::Teapot, BuiltinMesh::Sphere, BuiltinMesh::Torus, BuiltinMesh::Quad, BuiltinMesh::Plane})
        if (stem.find(builtinMeshName(named)) != std::string::npos) return named;
    return BuiltinMesh::Cube;
}

Result<void> resolveWorkspaceMedia(Workspace& ws, const MediaOptions& options, const std::set<std::string>& givenTextures) {
    Diagnostics out;
    MediaResolver resolver(ws.folder, options);
    auto resolve = [&](std::string& reference, const SourceLocation& where, const std::string& element, const char* noun) {
        MediaResolver::Found found = resolver.resolve(reference, noun);
        if (found.file)
            reference = found.file->generic_string();
        else
            out.push_back({Diagnostic::Severity::Error, where, element, found.error});
    };
    const bool placeholders = options.missing == MissingMedia::Placeholder;
    for (Texture& t : ws.textures) {
        if (givenTextures.count(t.name)) continue;
        std::string element = "<" + std::string(textureElementName(t.kind)) + " name=\"" + t.name + "\">";
        std::set<std::string> missing;  // one warning per file, though six faces may name the same
        for (size_t i = 0; i < t.files.size(); ++i) {
            const SourceLocation& where = i < t.fileLocations.size() ? t.fileLocations[i] : t.where;
            MediaResolver::Found found = resolver.resolve(t.files[i], "image file");
            if (found.file) {
                t.files[i] = found.file->generic_string();
            } else if (found.missing && placeholders) {
                if (missing.insert(t.files[i]).second)
                    out.push_back({Diagnostic::Severity::Warning, where, element,
                                   found.error + "; a magenta and grey checker stands in for the " +
                                       (t.kind == TextureKind::Cube     ? "whole cube map"
                                        : t.kind == TextureKind::Volume ? "volume texture"
                                                                        : "texture") +
                                       " (--missing-media placeholder)"});
            } else {
                out.push_back({Diagnostic::Severity::Error, where, element, found.error});
            }
        }
        if (!missing.empty()) {
            t.supplied = std::make_shared<const Image>(placeholderImage(t.kind));
            t.files.clear();
        }
    }
    std::set<std::string> missingModels;  // one warning per file, though many passes draw it
    for (Pass& pass : ws.passes) {
        for (ShaderSource& shader : pass.shaders)
            if (!shader.file.empty()) resolve(shader.file, shader.where, "<shader>", "shader file");
        if (pass.draw.mesh || pass.draw.file.empty()) continue;
        MediaResolver::Found found = resolver.resolve(pass.draw.file, "model file");
        if (found.file) {
            pass.draw.file = found.file->generic_string();
        } else if (auto standIn = found.missing ? stockModelStandIn(pass.draw.file) : std::nullopt) {
            // Effects name RenderMonkey's own media by absolute paths into its install; without
            // them the usual full-screen quad (and the stock teapot…) would stop every such effect.
            if (missingModels.insert(pass.draw.file).second)
                out.push_back({Diagnostic::Severity::Warning, pass.draw.where, "<draw>",
                               found.error + "; drawing rmfx's built-in '" + builtinMeshName(*standIn) + "' in its place"});
            pass.draw.mesh = standIn;
            pass.draw.standIn = true;
            pass.draw.standsInFor = pass.draw.file;
            if (std::optional<StockModel> stock = findStockModel(lowerCaseStem(pass.draw.file))) {
                const MeshPlacement placement = stockModelPlacement(*stock);
                pass.draw.meshScale = placement.scale;
                pass.draw.meshOffset = placement.offset;
                pass.draw.stockSize = true;
                pass.draw.mirrorU = stock->mirrorU;
            }
            pass.draw.file.clear();
        } else if (found.missing && placeholders) {
            const BuiltinMesh standIn = placeholderMeshFor(pass.draw.file);
            if (missingModels.insert(pass.draw.file).second)
                out.push_back({Diagnostic::Severity::Warning, pass.draw.where, "<draw>",
                               found.error + "; drawing rmfx's built-in '" + builtinMeshName(standIn) +
                                   "' in its place (--missing-media placeholder)"});
            pass.draw.mesh = standIn;
            pass.draw.standIn = true;
            pass.draw.standsInFor = pass.draw.file;
            pass.draw.file.clear();
        } else {
            out.push_back({Diagnostic::Severity::Error, pass.draw.where, "<draw>", found.error});
        }
    }
    if (options.sandbox && !ws.includeRoot.empty() && !resolver.isAllowed(ws.includeRoot))
        out.push_back({Diagnostic::Severity::Error, ws.includeRootWhere, "<workspace include-root>",
                       "include-root " + ws.includeRoot.string() + " (" + resolved(ws.includeRoot).string() +
                           ") lies outside the sandbox, which allows only " + resolver.describeRoots() +
                           " (give it with --media DIR, or run with --no-sandbox)"});
    return out;
}

}  // namespace rmfx
