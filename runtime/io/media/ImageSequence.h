#pragma once
// Frame-numbered file patterns (`--input scene=shot/frame.%04d.exr`, `-o out/frame.####.png`).
//
// A pattern has one frame-number field, in its file name (not in its folder):
//   %d     the frame number as it is: 7, 12, 1234
//   %0Nd   zero-padded to N digits (N = 1..9): %04d gives 0007, 0012, 12345
//   #…#    a run of N '#' is N digits zero-padded (####: 0007), as in Nuke and Blender; a single
//          '#' alone is 4 digits, as oiiotool reads it. oiiotool reads every '#' as 4 digits
//          (## is 8, #### is 16); a run of several '#' here follows the common reading instead.
//   %%     a literal '%'
// Any other '%' stands for itself, except "%Nd" (space-padded), which is an error. A frame
// number wider than the padding is written in full (printf's rule). Frame numbers are 0 or more.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/Result.h"

namespace rmfx {

// A pattern split around its field.
struct FramePattern {
    std::string prefix;  // the text before the field (the folder included), '%%' already made '%'
    std::string suffix;  // the text after it
    int digits = 0;      // zero padding; 0: none (%d)

    std::string fileName(int frame) const;
};

struct SequenceFrame {
    int frame = 0;
    std::filesystem::path path;
};

// True when the text holds a frame-number field (or several, or a space-padded one: those are
// errors parseFramePattern reports).
bool isSequencePattern(const std::string& pattern);

// Errors name the pattern: no field, two fields, "%Nd", a field in the folder part.
Result<FramePattern> parseFramePattern(const std::string& pattern);

// The file name of one frame; a pattern parseFramePattern refuses comes back unchanged.
std::string frameFileName(const std::string& pattern, int frame);

// The existing files of the pattern's folder whose names it produces, sorted by frame number.
// A name whose digits the pattern would not write (frame.12.exr for %04d, frame.007.exr for %d)
// is not one of them. Errors name the pattern: a field error, no folder, no matching file, or a
// gap in the numbering (naming the first missing file and how many frames are missing in all).
Result<std::vector<SequenceFrame>> findSequenceFrames(const std::string& pattern);

// The indices in `frames` (found by findSequenceFrames) of the frames numbered numbers.first to
// numbers.second, both included. Errors: a range backwards, or reaching outside the frames found
// (naming the frames there are).
Result<std::pair<int, int>> selectFrameRange(const std::vector<SequenceFrame>& frames, std::pair<int, int> numbers);

}  // namespace rmfx
