#pragma once
// Radiance's shared-exponent packing of HDR colour into bytes, arranged so that an 8-bit RGB PNG
// carries it: how the replay report (run/ReplayReport.h) gives its page linear values to expose.

#include "model/Image.h"

namespace rmfx {

// Radiance's RGBE packing of an image's colour (alpha dropped) as an 8-bit RGB image twice as
// tall: rows [0, h) hold the mantissas, rows [h, 2h) the shared exponent in every channel, so a
// page can decode it exactly (an opaque PNG keeps its bytes through a canvas). Negative, NaN and
// infinite values become 0, values above 255.5 · 2^119 (about 1.7e38) that. Values are stored as
// byte / 255.
Image packRgbe(const Image& image);
// A value decoded from a packed pixel: (m + 0.5) · 2^(e − 136), and 0 when m or e is 0 (Radiance
// decodes m = 0 as half a step; a report shows a channel that is 0 as 0).
double unpackRgbe(int mantissa, int exponent);

}  // namespace rmfx
