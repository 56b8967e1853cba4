#include "frontend/shader/GlslangProcess.h"

#include <mutex>

#include <glslang/Public/ShaderLang.h>

namespace rmfx {

void initializeGlslangOnce() {
    static std::once_flag flag;
    std::call_once(flag, [] { glslang::InitializeProcess(); });
}

}  // namespace rmfx
