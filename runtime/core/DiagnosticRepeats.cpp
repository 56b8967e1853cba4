#include "core/DiagnosticRepeats.h"

#include <set>
#include <string>

namespace rmfx {

Diagnostics withoutRepeats(Diagnostics later, const Diagnostics& shown) {
    std::set<std::string> seen;
    for (const Diagnostic& d : shown) seen.insert(d.format());
    std::erase_if(later, [&](const Diagnostic& d) { return seen.count(d.format()) > 0; });
    return later;
}

}  // namespace rmfx
