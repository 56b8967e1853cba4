// WorkspaceDependencies: every file a workspace reads, classified, with the passes and textures
// each one feeds: shaders and their nested includes (relative to the including file, to the
// workspace folder, through inline code), snippets (no file), images of textures and cube maps,
// model files; disabled passes and missing files.

#include <algorithm>

#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceDependencies.h"
#include "frontend/workspace/WorkspaceParser.h"
#include "tests/support/TestSupport.h"

namespace rmfx::test {
namespace {

namespace fs = std::filesystem;
using Names = std::vector<std::string>;

class WorkspaceDependenciesTest : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(dir_ / "glsl" / "lib");
        dir_.write("glsl/a.frag", "#include \"common.glsl\"\nout vec4 c; void main() { c = vec4(f()); }\n");
        dir_.write("glsl/b.frag", "#include \"lib/deep.glsl\"\n#include \"common.glsl\"\nout vec4 c; void main() { c = vec4(f()); }\n");
        // Found relative to the including file first (glsl/), then in the workspace folder.
        dir_.write("glsl/common.glsl", "#pragma once\n#include \"lib/deep.glsl\"\nfloat f() { return g(); }\n");
        dir_.write("glsl/lib/deep.glsl", "#pragma once\n#include \"snippet.glsl\"\nfloat g() { return h(); }\n");
        dir_.write("top.glsl", "float top() { return 1.0; }\n");
        dir_.write("glsl/d.frag", "out vec4 c; void main() { c = vec4(1); }\n");
        dir_.write("glsl/m.frag", "out vec4 c; void main() { c = vec4(1); }\n");
        std::string xml = R"(<workspace version="1" name="deps">
  <code name="snippet.glsl"><![CDATA[float h() { return 0.5; }]]></code>
  <texture name="Mask" file="media/mask.png"/>
  <texture name="Mask2" file="media/mask.png"/>
  <cubemap name="Sky">
    <face side="+x" file="px.exr"/> <face side="-x" file="nx.exr"/>
    <face side="+y" file="py.exr"/> <face side="-y" file="ny.exr"/>
    <face side="+z" file="pz.exr"/> <face side="-z" file="nz.exr"/>
  </cubemap>
  <pass name="a"><shader stage="fragment" file="glsl/a.frag"/></pass>
  <pass name="b"><shader stage="fragment" file="glsl/b.frag"/></pass>
  <pass name="inline"><shader stage="fragment"><![CDATA[
#include "top.glsl"
out vec4 c; void main() { c = vec4(top()); }
]]></shader></pass>
  <pass name="disabled" enabled="false"><shader stage="fragment" file="glsl/d.frag"/></pass>
  <pass name="model"><draw file="models/thing.obj"/><shader stage="fragment" file="glsl/m.frag"/></pass>
  <pass name="missing"><shader stage="fragment" file="glsl/gone.frag"/></pass>
</workspace>
)";
        fs::path file = dir_.write("ws.xml", xml);
        Result<Workspace> parsed = parseWorkspaceFile(file);
        ASSERT_TRUE(parsed.ok()) << formatAll(parsed.diagnostics());
        ws_ = std::move(*parsed);
        deps_ = findWorkspaceDependencies(ws_);
    }

    // The entry for a path relative to the scratch folder; fails the test when there is none.
    const FileDependency& entry(const std::string& relative) {
        const FileDependency* d = deps_.find(dir_ / relative);
        static const FileDependency none;
        if (!d) ADD_FAILURE() << relative << " is not among the dependencies";
        return d ? *d : none;
    }

    ScratchDir dir_;
    Workspace ws_;
    WorkspaceDependencies deps_;
};

TEST_F(WorkspaceDependenciesTest, TheWorkspaceFileComesFirst) {
    ASSERT_FALSE(deps_.files.empty());
    EXPECT_EQ(deps_.files.front().kind, DependencyKind::Workspace);
    EXPECT_EQ(deps_.files.front().file, fs::weakly_canonical(dir_ / "ws.xml"));
}

TEST_F(WorkspaceDependenciesTest, ShadersAndTheirNestedIncludes) {
    EXPECT_EQ(entry("glsl/a.frag").kind, DependencyKind::Shader);
    EXPECT_EQ(entry("glsl/a.frag").passes, Names{"a"});
    EXPECT_EQ(entry("glsl/b.frag").passes, Names{"b"});
    EXPECT_EQ(entry("glsl/common.glsl").kind, DependencyKind::Include);
    EXPECT_EQ(entry("glsl/common.glsl").passes, (Names{"a", "b"}));
    // Reached from a through common.glsl, from b directly and through common.glsl.
    EXPECT_EQ(entry("glsl/lib/deep.glsl").kind, DependencyKind::Include);
    EXPECT_EQ(entry("glsl/lib/deep.glsl").passes, (Names{"a", "b"}));
    // An include of inline code resolves in the workspace folder.
    EXPECT_EQ(entry("top.glsl").kind, DependencyKind::Include);
    EXPECT_EQ(entry("top.glsl").passes, Names{"inline"});
}

TEST_F(WorkspaceDependenciesTest, TexturesCubeFacesAndModels) {
    EXPECT_EQ(entry("media/mask.png").kind, DependencyKind::Texture);
    EXPECT_EQ(entry("media/mask.png").textures, (Names{"Mask", "Mask2"}));
    for (const char* face : {"px.exr", "nx.exr", "py.exr", "ny.exr", "pz.exr", "nz.exr"}) {
        EXPECT_EQ(entry(face).kind, DependencyKind::Texture) << face;
        EXPECT_EQ(entry(face).textures, Names{"Sky"}) << face;
    }
    EXPECT_EQ(entry("models/thing.obj").kind, DependencyKind::Model);
    EXPECT_EQ(entry("models/thing.obj").passes, Names{"model"});
}

TEST_F(WorkspaceDependenciesTest, EveryFileOnceAndNothingElse) {
    // ws.xml, a, b, common, deep, top, m, gone, mask, six faces, the model; no snippet, no d.frag.
    EXPECT_EQ(deps_.files.size(), 16u);
    std::vector<fs::path> paths = deps_.paths();
    std::sort(paths.begin(), paths.end());
    EXPECT_EQ(std::adjacent_find(paths.begin(), paths.end()), paths.end());
    EXPECT_EQ(deps_.find(dir_ / "glsl/d.frag"), nullptr);  // its pass is disabled
    for (const fs::path& p : paths) EXPECT_EQ(p.string().find("snippet"), std::string::npos) << p;
}

TEST_F(WorkspaceDependenciesTest, MissingFilesAreListedSoThatTheirReturnIsNoticed) {
    EXPECT_EQ(entry("glsl/gone.frag").kind, DependencyKind::Shader);
    EXPECT_EQ(entry("glsl/gone.frag").passes, Names{"missing"});
    EXPECT_EQ(entry("px.exr").kind, DependencyKind::Texture);  // none of the images exists
}

TEST_F(WorkspaceDependenciesTest, FoundHoweverThePathIsSpelt) {
    const FileDependency* viaDots = deps_.find(dir_ / "glsl/lib/../common.glsl");
    ASSERT_NE(viaDots, nullptr);
    EXPECT_EQ(viaDots->passes, (Names{"a", "b"}));
    fs::create_directory_symlink(dir_ / "glsl", dir_ / "link");
    const FileDependency* viaLink = deps_.find(dir_ / "link/a.frag");
    ASSERT_NE(viaLink, nullptr);
    EXPECT_EQ(viaLink->passes, Names{"a"});
    EXPECT_EQ(deps_.find(dir_ / "glsl/nothing.glsl"), nullptr);
}

TEST_F(WorkspaceDependenciesTest, KindNames) {
    EXPECT_STREQ(dependencyKindName(DependencyKind::Include), "include");
    EXPECT_STREQ(dependencyKindName(DependencyKind::Model), "model");
}

}  // namespace
}  // namespace rmfx::test
