#pragma once
// A name (a case, a target, a compare) made safe as part of a file name: characters other than
// letters, digits, '_', '-' and '.' become '_', and a leading '.' (or nothing) gets a '_' before it.

#include <string>

namespace rmfx {

std::string fileNamePart(const std::string& name);

}  // namespace rmfx
