#pragma once
// The command-line options every command that loads workspaces shares (docs/media.md):
//   --media DIR    a folder of the media search path (repeatable, searched in order)
//   --sandbox      refuse references leading outside the workspace folder and the media folders
//   --no-sandbox   the opposite (replay sandboxes by default)
//   --missing-media error|placeholder
//                  what a texture or model found nowhere becomes: an error (the default), or a
//                  stand-in with a warning (MissingMedia::Placeholder)
//   --max-image-memory MiB
//                  the most memory one decoded image may take (io/image/ImageMemoryLimit.h), for
//                  the whole run: an image over it is refused from its header

#include <optional>
#include <string>
#include <vector>

#include "io/media/MediaResolver.h"

namespace rmfx {

// When args[i] is one of the options above, applies it to `media`, moves `i` past its value and
// returns "" (or why it is wrong: "--media needs a folder"); nullopt when args[i] is another option.
// "--missing-media=placeholder" is accepted as well.
std::optional<std::string> takeMediaArgument(const std::vector<std::string>& args, size_t& i, MediaOptions& media);

}  // namespace rmfx
