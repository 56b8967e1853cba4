#include "io/media/MediaArguments.h"

#include <cstdint>
#include <cstdlib>
#include <filesystem>

#include "io/image/ImageMemoryLimit.h"

namespace rmfx {

std::optional<std::string> takeMediaArgument(const std::vector<std::string>& args, size_t& i, MediaOptions& media) {
    const std::string& arg = args[i];
    if (arg == "--sandbox" || arg == "--no-sandbox") {
        media.sandbox = arg == "--sandbox";
        return "";
    }
    if (arg == "--missing-media" || arg.rfind("--missing-media=", 0) == 0) {
        std::string value;
        if (arg.size() > std::string("--missing-media").size()) {
            value = arg.substr(std::string("--missing-media=").size());
        } else {
            if (i + 1 >= args.size()) return "--missing-media needs 'error' or 'placeholder'";
            value = args[++i];
        }
        if (value == "error") media.missing = MissingMedia::Error;
        else if (value == "placeholder") media.missing = MissingMedia::Placeholder;
        else return "--missing-media: '" + value + "' is neither 'error' nor 'placeholder'";
        return "";
    }
    if (arg == "--max-image-memory") {
        if (i + 1 >= args.size()) return "--max-image-memory needs MiB";
        const std::string& value = args[++i];
        char* end = nullptr;
        const double mib = std::strtod(value.c_str(), &end);
        if (value.empty() || *end || !(mib >= 1.0 && mib <= 1048576.0))
            return "--max-image-memory: expected MiB a decoded image may take, 1 to 1048576, got '" + value + "'";
        setImageMemoryLimit(static_cast<std::uint64_t>(mib * 1048576.0));
        return "";
    }
    if (arg != "--media") return std::nullopt;
    if (i + 1 >= args.size() || args[i + 1].empty()) return "--media needs a folder";
    const std::string& folder = args[++i];
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error)) return "--media: '" + folder + "' is not a folder";
    media.searchPath.emplace_back(folder);
    return "";
}

}  // namespace rmfx
