#pragma once
// rmfx render --input [NAME=]FILE: the images a run gives a workspace's <input>s, read, checked
// and put into the inputs' textures before any GL object exists.

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

struct InputArgument {
    std::string name;  // the <input>; empty: the workspace's only one
    std::filesystem::path file;
    std::string layer;  // an EXR part or layer ("FILE.exr:layer"); empty: the file's default
    std::string text;   // as the user wrote it, for messages
    // An image given in memory (the Python module's arrays): linear RGBA, taken in place of reading
    // `file`, which is then not read; `text` names it in messages.
    std::shared_ptr<const Image> image;
};

// "scene=shot.exr" names the input; "shot.exr" does not. The text names an input when what comes
// before the first '=' is an identifier and the whole text is not an existing file. A trailing
// ":layer" after an EXR file picks a part or layer (splitLayerSuffix).
InputArgument parseInputArgument(const std::string& text);

struct SuppliedInputs {
    std::set<std::string> given;  // the inputs an image was given for (FramePlanOptions::givenInputs)
    glm::ivec2 viewport{0};       // the size the run renders at
};

// The <input> each argument fills, in order, before any image is read. Errors name the argument:
// an unknown input (listing the workspace's), a name left out where the workspace has several, an
// input given twice.
Result<std::vector<const ImageInput*>> resolveInputArguments(const Workspace& ws, const std::vector<InputArgument>& inputs);

// Reads each image as linear RGBA (readInputImage: how it decoded each file comes back as
// warnings naming it) and puts it into its input's texture. The viewport is `size` when given,
// else the size of the first image that replaces a target (the scene), else the workspace's.
// An image that replaces a target and is not the viewport's size is resampled to it (a triangle
// filter, which puts no negative value beside a bright pixel), and a warning says so. Errors name
// the argument and the file: an unknown input (listing the workspace's), an input given twice, a
// file that cannot be read, an image with a side over `maxSide` (refused from its header).
Result<SuppliedInputs> supplyInputs(Workspace& ws, const std::vector<InputArgument>& inputs,
                                    std::optional<glm::ivec2> size, int maxSide = 16384);

}  // namespace rmfx
