#pragma once
// Workspace enums → OpenGL enums. GL enum values are plain unsigned ints here so the header
// needs no GL include.

#include "model/Workspace.h"

namespace rmfx::gl {

unsigned internalFormat(TargetFormat format);
int channelCount(TargetFormat format);  // 1, 2, 3 or 4
unsigned blendFactor(BlendFactor factor);
unsigned blendEquation(BlendOp op);
unsigned compareFunc(CompareFunc func);
unsigned wrapMode(Wrap wrap);
unsigned minFilter(Filter filter, MipmapMode mipmap);
unsigned magFilter(Filter filter);
// Levels of a full mip chain down to 1x1.
int mipLevels(int width, int height);

}  // namespace rmfx::gl
