#include "core/Diagnostic.h"

#include <algorithm>

namespace rmfx {

std::string Diagnostic::format() const {
    std::string out = where.file.empty() ? std::string("<input>") : where.file;
    if (where.line > 0) out += ":" + std::to_string(where.line);
    out += severity == Severity::Error ? ": error: " : ": warning: ";
    if (!element.empty()) out += element + ": ";
    out += message;
    return out;
}

bool hasErrors(const Diagnostics& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::Error; });
}

std::string formatAll(const Diagnostics& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics) out += d.format() + "\n";
    return out;
}

}  // namespace rmfx
