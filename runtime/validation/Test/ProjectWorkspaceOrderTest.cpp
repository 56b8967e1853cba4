// Every workspace of effects/, loaded as rmfx loads it, runs its passes in an order the pass graph
// accepts: no cycles, no target read before a pass writes it (graph/Test/PassGraphTest tests the
// check itself).

#include <filesystem>

#include <gtest/gtest.h>

#include "graph/PassGraph.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

TEST(ProjectWorkspaceOrder, EveryProjectWorkspaceIsInOrder) {
    for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "effects")) {
        if (entry.path().extension() != ".xml") continue;
        Result<Workspace> loaded = loadWorkspace(entry.path(), {false});
        ASSERT_TRUE(loaded.ok()) << entry.path() << formatAll(loaded.diagnostics());
        EXPECT_TRUE(checkPassOrder(*loaded).empty()) << entry.path();
    }
}

}  // namespace
}  // namespace rmfx
