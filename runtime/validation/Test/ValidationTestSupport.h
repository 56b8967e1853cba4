#pragma once
// What the validation tests share: a workspace written into a scratch folder and loaded, its
// diagnostics split into errors and warnings, each formatted whole ("file:line: error: ...").

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx::test::validation_test {

using Lines = std::vector<std::string>;

// A fragment shader on one line that compiles and uses nothing.
inline const std::string kPlainShader = "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>";

struct Loaded {
    std::string path;       // the workspace file, as diagnostics name it
    std::string folder;     // its folder, with a trailing separator
    Result<Workspace> result;
    Lines errors, warnings;
};

// Writes the workspace as fx.xml into the scratch folder (or `sub`folder of it) and loads it.
inline Loaded load(const test::ScratchDir& dir, const std::string& xml, const std::string& sub = "") {
    auto path = dir.write(sub.empty() ? "fx.xml" : sub + "/fx.xml", xml);
    Loaded out{path.string(), path.parent_path().string() + "/", loadWorkspace(path), {}, {}};
    for (const Diagnostic& d : out.result.diagnostics()) {
        (d.severity == Diagnostic::Severity::Error ? out.errors : out.warnings).push_back(d.format());
    }
    if (hasErrors(out.result.diagnostics())) {
        EXPECT_FALSE(out.result.ok());
    }
    return out;
}

}  // namespace rmfx::test::validation_test
