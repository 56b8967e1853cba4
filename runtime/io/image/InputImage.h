#pragma once
// Reading a user's image to feed an effect (`rmfx render --input FILE`): whatever the file holds
// becomes linear RGBA float, and every conversion on the way is said in a note.
//
// - Integer files (8- and 16-bit PNG, JPEG, TIFF…) are display-referred: colour is decoded with
//   the sRGB transfer function; alpha is kept as it is. Float and half files are taken as linear
//   and kept unchanged.
// - 1 channel is grey (R = G = B, alpha 1); 2 channels are grey and alpha; 3 channels get alpha 1;
//   channels beyond the chosen R, G, B, A are not read.
// - Alpha is as the file stores it (PNG straight, EXR premultiplied by convention); nothing is
//   premultiplied or divided on the way in.
// - NaN, infinite and negative values are kept (the effects sanitise their inputs) and counted
//   in a note.
// - Multi-part and multi-layer OpenEXR files: a layer is a group of channels sharing a prefix
//   (`ViewLayer.Combined.R`, `diffuse.G`); a part is a subimage, named by the file. See
//   readInputImage for which one is read.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/Result.h"
#include "model/Image.h"

namespace rmfx {

struct InputImage {
    Image image;                     // 4 channels, linear, straight or premultiplied as the file had it
    std::string layer;               // the part or layer read; "" for a file with no parts or layers
    std::vector<std::string> notes;  // sentences for the user, each naming the file
};

constexpr int kMaxInputSide = 16384;

// Reads `file`. `layer` names a part or a layer (exactly, or by its last components: "Combined"
// for "ViewLayer.Combined"); a part's name reads that part as if it were the whole file. Without
// one: the plain R, G, B[, A] channels of the first part that has them; else a layer named
// Combined (any prefix); else the file's only layer. Several layers and none of those, or an
// unknown name, is an error listing the layers and parts there are.
// An image wider or taller than maxSide (data or display window) is refused from its header,
// before any pixel is read. Errors name the file.
Result<InputImage> readInputImage(const std::filesystem::path& file, const std::string& layer = "",
                                  int maxSide = kMaxInputSide);

// Splits "FILE:layer" into the file and the layer at the last ':', only when the part before it
// names an existing file or ends in .exr and the whole argument is not itself an existing file:
// "C:\\shots\\a.png" and plain names come back whole, with an empty layer.
std::pair<std::filesystem::path, std::string> splitLayerSuffix(const std::string& argument);

// The image at width x height, filtered with OpenImageIO's "triangle" filter (widened when
// shrinking). The triangle has no negative lobes, unlike Lanczos or Catmull-Rom: a bright HDR
// pixel spreads into its neighbours without ringing into negative values around it.
Result<Image> resampleImage(const Image& image, int width, int height);

}  // namespace rmfx
