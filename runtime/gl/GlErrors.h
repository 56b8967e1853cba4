#pragma once
// glGetError, read once for all: the errors pending, described ("GL_INVALID_OPERATION").

#include <string>
#include <vector>

namespace rmfx {

// Reads every pending GL error, oldest first; none pending: empty. Called before a step to forget
// what came before it, and after to learn what the step caused.
std::vector<std::string> drainGlErrors();

// The oldest of drainGlErrors(), or empty when there was none.
std::string firstGlError();

std::string describeGlError(unsigned error);
std::string describeFramebufferStatus(unsigned status);

}  // namespace rmfx
