#pragma once

#include <string>

namespace rmfx {

// GPU time of one pass, from timer queries (GL_TIMESTAMP around each pass).
struct PassTiming {
    std::string pass;
    double milliseconds = 0.0;
};

}  // namespace rmfx
