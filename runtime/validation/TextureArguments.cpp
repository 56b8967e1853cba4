#include "validation/TextureArguments.h"

#include <set>
#include <system_error>

namespace rmfx {

Result<TextureArgument> parseTextureArgument(const std::string& text) {
    size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
        return Error{"--texture " + text + ": expected NAME=FILE, or NAME=FILE,FILE,FILE,FILE,FILE,FILE for six cube faces"};
    TextureArgument argument;
    argument.text = text;
    argument.name = text.substr(0, equals);
    std::string rest = text.substr(equals + 1);
    for (size_t start = 0;;) {
        size_t comma = rest.find(',', start);
        std::string file = rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (file.empty()) return Error{"--texture " + text + ": an empty file name in the list"};
        argument.files.emplace_back(file);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return argument;
}

Result<void> replaceTextures(Workspace& ws, const std::vector<TextureArgument>& textures) {
    Diagnostics d;
    auto error = [&](const TextureArgument& a, const std::string& message) {
        d.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "--texture " + a.text, message});
    };
    std::string known;
    for (const Texture& t : ws.textures)
        if (!ws.findInput(t.name)) known += (known.empty() ? "'" : ", '") + t.name + "'";
    known = known.empty() ? "it has no texture read from a file" : "its textures: " + known;
    std::set<std::string> taken;
    for (const TextureArgument& a : textures) {
        Texture* texture = ws.findTexture(a.name);
        if (!texture) {
            error(a, "the workspace has no texture '" + a.name + "' (" + known + ")");
            continue;
        }
        if (ws.findInput(a.name)) {
            error(a, "'" + a.name + "' is an <input>: give its image with --input " + a.name + "=FILE");
            continue;
        }
        if (!taken.insert(a.name).second) {
            error(a, "texture '" + a.name + "' is given twice");
            continue;
        }
        const bool cube = texture->kind == TextureKind::Cube;
        if (!cube && a.files.size() != 1) {
            error(a, "'" + a.name + "' is a " + (texture->kind == TextureKind::Volume ? "volume texture" : "2D texture") +
                         ": give one image, not " + std::to_string(a.files.size()));
            continue;
        }
        if (cube && a.files.size() != 1 && a.files.size() != 6) {
            error(a, "'" + a.name + "' is a cube map: give one image (2:1 longitude/latitude, 4:3 or 3:4 cross, or "
                     "a DDS cube map) or six faces (+x,-x,+y,-y,+z,-z), not " + std::to_string(a.files.size()));
            continue;
        }
        bool missing = false;
        for (const std::filesystem::path& file : a.files) {
            std::error_code ec;
            if (!std::filesystem::is_regular_file(file, ec)) {
                error(a, file.string() + ": no such file");
                missing = true;
            }
        }
        if (missing) continue;
        texture->files.clear();
        texture->fileLocations.clear();
        for (const std::filesystem::path& file : a.files) {
            texture->files.push_back(std::filesystem::absolute(file).lexically_normal().string());
            texture->fileLocations.push_back({"--texture", 0});
        }
        if (cube) texture->layout = a.files.size() == 6 ? CubeLayout::Faces : CubeLayout::FromImage;
        texture->faceSize = 0;
    }
    if (hasErrors(d)) return Result<void>::failure(std::move(d));
    return {};
}

}  // namespace rmfx
