#pragma once
// Where statements can be added at the end of a GLSL shader's main (the fixed-function steps
// Direct3D ran after a pixel shader: alpha test, fog).

#include <cstddef>
#include <optional>
#include <string>

namespace rmfx {

// The offset of the `}` closing `void main()`; nullopt when there is none.
std::optional<size_t> endOfMain(const std::string& glsl);

}  // namespace rmfx
