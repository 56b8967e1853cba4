#pragma once
// Which real file each file reference of a workspace names (docs/media.md). References come
// from rmfx's XML and from RenderMonkey imports, which keep FILE_NAME exactly as written:
// backslashes, wrong case, absolute paths into a RenderMonkey install on drive C:. The rules:
//   1. backslashes are separators; a drive letter or other Windows absolute path is never taken
//      literally (only its trailing components are searched for);
//   2. relative references are tried against the workspace folder, each component matched
//      exactly, else ignoring case (two names differing only in case: an error naming both);
//   3. then each folder of the media search path (`--media DIR`), in order, by the trailing
//      components of the reference, longest first;
//   4. finally each search folder and its subfolders by file name, ignoring case.
// With the sandbox on, a file found anywhere must lie (symbolic links resolved) inside the
// workspace folder or a search folder; so must the workspace's include-root.

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

// What a reference that finds no file anywhere becomes (--missing-media).
enum class MissingMedia {
    Error,        // an error naming it (the default)
    Placeholder,  // a warning, and a stand-in: a checker image (io/image/PlaceholderImage), the
                  // built-in mesh named like the model or a cube (placeholderMeshFor)
};

struct MediaOptions {
    // Folders searched after the workspace folder, in order: given by the person running rmfx
    // (--media, a replay manifest), never by the workspace.
    std::vector<std::filesystem::path> searchPath;
    // Refuse references that lead outside the workspace folder and the search path.
    bool sandbox = false;
    MissingMedia missing = MissingMedia::Error;
};

// A reference as written, split into components: backslashes and slashes separate, "." and
// empty components are dropped; `windowsAbsolute`: it began with a drive letter or "\\".
struct MediaReference {
    std::vector<std::string> components;
    bool windowsAbsolute = false;
    bool posixAbsolute = false;

    static MediaReference parse(const std::string& text);
    bool absolute() const { return windowsAbsolute || posixAbsolute; }
    // The components after the last "..": what is searched for in the search path.
    std::vector<std::string> trailing() const;
};

// The path, relative to `base`, that `relative` components lead to, each component matched
// exactly, else ignoring case ("..": the parent); the last must be a regular file. nullopt when
// some component matches nothing; two or more case matches for one component also set
// `ambiguity` to a message naming them.
std::optional<std::filesystem::path> walkIgnoringCase(const std::filesystem::path& base,
                                                      const std::vector<std::string>& relative,
                                                      std::string* ambiguity);

// Whether `file`, symbolic links resolved, lies in `folder` (also resolved) or below it.
bool liesInside(const std::filesystem::path& file, const std::filesystem::path& folder);

// RenderMonkey's stock models that rmfx has built in (ScreenAlignedQuad, Teapot, Sphere, Cube), by
// the reference's file name ignoring case and extension: what stands in for one that is missing.
std::optional<BuiltinMesh> stockModelStandIn(const std::string& reference);

// With --missing-media placeholder, the built-in mesh that stands in for any missing model: the
// one its file name names (teapot, sphere, torus, quad, plane, cube, ignoring case, anywhere in
// the name: "MyTeapot2.3ds" is a teapot), else a cube.
BuiltinMesh placeholderMeshFor(const std::string& reference);

class MediaResolver {
public:
    MediaResolver(std::filesystem::path workspaceFolder, MediaOptions options);

    struct Found {
        std::optional<std::filesystem::path> file;  // relative to the workspace folder when found there, else absolute
        std::string error;                          // why not, when file is empty
        bool missing = false;                       // not found anywhere (rather than refused)
    };
    // `noun` names the kind of file in messages ("image file", "model file", "shader file").
    Found resolve(const std::string& reference, const std::string& noun);

    // The folders the sandbox allows, resolved: the workspace folder, then the search path.
    const std::vector<std::filesystem::path>& allowedRoots() const { return roots_; }
    // "the workspace folder /a and the --media folders /b, /c"
    std::string describeRoots() const;
    bool isAllowed(const std::filesystem::path& file) const;

private:
    Found checked(std::filesystem::path file, const std::filesystem::path& opened, const std::string& reference,
                  const std::string& noun) const;
    // Every regular file under `folder` by lower-case name (bounded walk, built once per folder).
    const std::multimap<std::string, std::filesystem::path>& indexOf(const std::filesystem::path& folder);

    std::filesystem::path folder_;
    MediaOptions options_;
    std::vector<std::filesystem::path> roots_;
    std::map<std::filesystem::path, std::multimap<std::string, std::filesystem::path>> indexes_;
};

// Resolves every file reference of `ws` once, in place: Texture::files, DrawCall::file and
// ShaderSource::file then name the file found (relative to ws.folder when it lies there, else
// absolute), which is what the executor, hot reload and listings use. Each reference that finds
// nothing, finds two files, or (sandbox) leads outside gives an error naming its element. With
// MissingMedia::Placeholder, a texture or model found nowhere gets a stand-in and a warning
// instead: the texture's files are cleared and its `supplied` image is the placeholder.
// `givenTextures`: textures whose files the person running rmfx named (rmfx render --texture),
// taken as they are: not searched for and not sandboxed.
Result<void> resolveWorkspaceMedia(Workspace& ws, const MediaOptions& options,
                                   const std::set<std::string>& givenTextures = {});

}  // namespace rmfx
