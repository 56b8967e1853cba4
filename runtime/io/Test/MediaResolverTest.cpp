// Which file each reference names (backslashes, case, the media search path), and the sandbox
// that refuses references leading outside the workspace folder and the media folders.

#include "io/media/MediaResolver.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/common.hpp>
#include <gtest/gtest.h>

#include "frontend/workspace/WorkspaceDependencies.h"
#include "io/media/MediaArguments.h"
#include "io/mesh/BuiltinMeshes.h"
#include "tests/support/TestSupport.h"
#include "validation/WorkspaceLoader.h"

namespace rmfx {
namespace {

namespace fs = std::filesystem;
using Lines = std::vector<std::string>;
using test::lines;

const std::string kShader = "    <shader stage=\"fragment\">out vec4 c; void main() { c = vec4(1.0); }</shader>";

// A workspace whose line 2 names `reference` as a texture file.
std::string textureWorkspace(const std::string& reference) {
    return lines({"<workspace version=\"1\">", "  <texture name=\"t\" file=\"" + reference + "\"/>", "  <pass name=\"p\">",
                  kShader, "  </pass>", "</workspace>"});
}

Result<Workspace> load(const fs::path& file, MediaOptions media = {}) {
    ValidationOptions options;
    options.compileShaders = false;  // resolution and #includes are checked all the same
    WorkspaceLoadOptions load;
    load.media = std::move(media);
    return loadWorkspace(file, options, load);
}

Lines errors(const Result<Workspace>& loaded) {
    Lines out;
    for (const Diagnostic& d : loaded.diagnostics())
        if (d.severity == Diagnostic::Severity::Error) out.push_back(d.format());
    return out;
}

MediaOptions sandbox(std::vector<fs::path> searchPath = {}) { return {std::move(searchPath), true}; }

// A file and the name it was found by (relative to the workspace folder, or absolute).
std::string resolve(MediaResolver& r, const std::string& reference) {
    MediaResolver::Found found = r.resolve(reference, "image file");
    return found.file ? found.file->generic_string() : "error: " + found.error;
}

}  // namespace

TEST(MediaReference, SplitsOnBothSeparatorsAndKnowsWindowsAbsolutePaths) {
    MediaReference r = MediaReference::parse("..\\..\\Media\\Textures/./Fieldstone.tga");
    EXPECT_EQ(r.components, (Lines{"..", "..", "Media", "Textures", "Fieldstone.tga"}));
    EXPECT_FALSE(r.absolute());
    EXPECT_EQ(r.trailing(), (Lines{"Media", "Textures", "Fieldstone.tga"}));
    MediaReference drive = MediaReference::parse("C:\\Program Files\\ATI Research Inc\\Media\\Quad.3ds");
    EXPECT_TRUE(drive.windowsAbsolute);
    EXPECT_EQ(drive.components, (Lines{"Program Files", "ATI Research Inc", "Media", "Quad.3ds"}));
    MediaReference unc = MediaReference::parse("\\\\server\\share\\Media\\Quad.3ds");
    EXPECT_TRUE(unc.windowsAbsolute);
    EXPECT_EQ(unc.components, (Lines{"share", "Media", "Quad.3ds"}));
    EXPECT_TRUE(MediaReference::parse("/etc/passwd").posixAbsolute);
}

TEST(MediaResolver, BackslashesAndCaseFindTheFileRelativeToTheWorkspace) {
    test::ScratchDir dir;
    dir.write("Media/Textures/Fieldstone.tga", "x");
    dir.write("GL2/ws.xml", "");  // "GL2/.." needs GL2
    MediaResolver r(dir / "GL2", {});
    EXPECT_EQ(resolve(r, "..\\Media\\Textures\\Fieldstone.tga"), "../Media/Textures/Fieldstone.tga");
    // The file's real spelling is what is stored.
    EXPECT_EQ(resolve(r, "..\\MEDIA\\textures\\fieldSTONE.TGA"), "../Media/Textures/Fieldstone.tga");
}

TEST(MediaResolver, TwoNamesThatDifferOnlyInCaseAreAnErrorUnlessSpelledExactly) {
    test::ScratchDir dir;
    for (const char* name : {"ws/tex/a.png", "ws/tex/A.png"}) dir.write(name, name);
    MediaResolver r(dir / "ws", {});
    EXPECT_EQ(resolve(r, "tex\\A.png"), "tex/A.png");
    EXPECT_EQ(resolve(r, "tex/a.png"), "tex/a.png");
    EXPECT_EQ(resolve(r, "TEX\\a.PNG"), "error: image file 'TEX\\a.PNG' is ambiguous: 'a.PNG' matches 'A.png', 'a.png' in " +
                                            (dir / "ws/tex").string() +
                                            " when case is ignored; rename one, or write the exact spelling");
}

TEST(MediaResolver, SearchPathByTrailingComponentsLongestFirstThenByFileName) {
    test::ScratchDir dir;
    const std::string install =
        "C:\\Program Files\\ATI Research Inc\\RenderMonkey 1.82\\Examples\\Media\\Models\\ScreenAlignedQuad.3ds";
    dir.write("Examples/Media/Models/ScreenAlignedQuad.3ds", "quad");
    dir.write("Examples/Media/Old/ScreenAlignedQuad.3ds", "decoy");  // same name elsewhere: only trailing components tell
    dir.write("Examples/Media/Textures/Deep/Er/Fieldstone.tga", "stone");
    dir.write("effects/ws.xml", "");
    const fs::path examples = dir / "Examples", media = dir / "Examples/Media";

    MediaResolver byExamples(dir / "effects", {{examples}, false});
    EXPECT_EQ(resolve(byExamples, install), (media / "Models/ScreenAlignedQuad.3ds").string());
    MediaResolver byMedia(dir / "effects", {{dir / "nothing-here", media}, false});
    EXPECT_EQ(resolve(byMedia, install), (media / "Models/ScreenAlignedQuad.3ds").string());
    // Finally by file name, ignoring case, in the media folders and their subfolders.
    EXPECT_EQ(resolve(byMedia, "..\\..\\Media\\Textures\\FIELDSTONE.tga"),
              (media / "Textures/Deep/Er/Fieldstone.tga").string());
    // A name found twice by file name alone is an error naming both.
    EXPECT_EQ(resolve(byMedia, "elsewhere\\screenalignedquad.3ds"),
              "error: image file 'elsewhere\\screenalignedquad.3ds' is ambiguous: the file name "
              "'screenalignedquad.3ds' matches " +
                  (media / "Models/ScreenAlignedQuad.3ds").string() + ", " +
                  (media / "Old/ScreenAlignedQuad.3ds").string() + " under the media folder " + media.string() +
                  "; write more of its path, or give a narrower --media folder");
    // Copies of one file, byte for byte, are that file: the first of them in path order.
    dir.write("Examples/Media/Models/Teapot.3ds", "teapot");
    dir.write("Examples/Media/Copy/Teapot.3ds", "teapot");
    MediaResolver copies(dir / "effects", {{media}, false});
    EXPECT_EQ(resolve(copies, "C:\\RM\\Teapot.3ds"), (media / "Copy/Teapot.3ds").string());
    dir.write("Examples/Media/Copy/Teapot.3ds", "teapoT");
    MediaResolver differing(dir / "effects", {{media}, false});
    EXPECT_EQ(resolve(differing, "C:\\RM\\Teapot.3ds").rfind("error: image file 'C:\\RM\\Teapot.3ds' is ambiguous", 0), 0u);
}

TEST(MediaResolver, TheWorkspaceFolderComesFirstThenTheMediaFoldersInOrder) {
    test::ScratchDir dir;
    dir.write("one/x.png", "1");
    dir.write("two/x.png", "2");
    dir.write("two/y.png", "2");
    dir.write("ws/y.png", "ws");
    MediaResolver r(dir / "ws", {{dir / "one", dir / "two"}, false});
    EXPECT_EQ(resolve(r, "x.png"), (dir / "one/x.png").string());
    EXPECT_EQ(resolve(r, "y.png"), "y.png");
}

TEST(MediaResolver, NotFoundNamesTheReferenceItsLineAndElementAndEveryPlaceLooked) {
    test::ScratchDir dir;
    dir.write("media/readme.txt", "");
    fs::path ws = dir.write("ws/fx.xml", textureWorkspace("..\\Tex\\Missing.png"));
    Result<Workspace> l = load(ws, {{dir / "media"}, false});
    EXPECT_FALSE(l.ok());
    EXPECT_EQ(errors(l), (Lines{ws.string() + ":2: error: <texture name=\"t\">: image file '..\\Tex\\Missing.png' not found: "
                                              "looked for " + (dir / "Tex/Missing.png").string() +
                                              " (ignoring case); in " + (dir / "media").string() +
                                              " by trailing components (Tex/Missing.png); in " +
                                              (dir / "media").string() +
                                              " and its subfolders by file name 'Missing.png' (ignoring case)"}));

    fs::path windows = dir.write("ws/win.xml", textureWorkspace("C:\\RenderMonkey\\Media\\Stone.tga"));
    EXPECT_EQ(errors(load(windows)),
              (Lines{windows.string() + ":2: error: <texture name=\"t\">: image file 'C:\\RenderMonkey\\Media\\Stone.tga' "
                                        "not found: a Windows absolute path is not taken literally, only its trailing "
                                        "components are searched for in the media folders; no media folders were given "
                                        "(add one with --media DIR)"}));
}

TEST(MediaResolver, MissingStockRenderMonkeyModelsBecomeBuiltInMeshesWithAWarning) {
    test::ScratchDir dir;
    auto drawWorkspace = [](const std::string& model) {
        return lines({"<workspace version=\"1\">", "  <pass name=\"p\">", kShader,
                      "    <draw file=\"" + model + "\"/>", "  </pass>", "</workspace>"});
    };
    const std::string quad = "C:\\Program Files\\AMD\\RenderMonkey 1.81\\Examples\\Media\\Models\\ScreenAlignedQuad.3ds";
    fs::path ws = dir.write("ws/quad.xml", drawWorkspace(quad));
    Result<Workspace> l = load(ws);
    ASSERT_TRUE(l.ok()) << formatAll(l.diagnostics());
    EXPECT_EQ(l->passes[0].draw.mesh, BuiltinMesh::Quad);
    EXPECT_EQ(l->passes[0].draw.file, "");
    ASSERT_EQ(l.diagnostics().size(), 1u);
    EXPECT_EQ(l.diagnostics()[0].severity, Diagnostic::Severity::Warning);
    EXPECT_NE(l.diagnostics()[0].format().find(":4: warning: <draw>: model file '" + quad + "' not found"), std::string::npos)
        << l.diagnostics()[0].format();
    EXPECT_NE(l.diagnostics()[0].format().find("drawing rmfx's built-in 'quad' in its place"), std::string::npos);

    EXPECT_EQ(load(dir.write("ws/teapot.xml", drawWorkspace("..\\models\\TEAPOT.3DS")))->passes[0].draw.mesh,
              BuiltinMesh::Teapot);
    // Two passes drawing the same missing stock model: one warning.
    fs::path twice = dir.write("ws/twice.xml", lines({"<workspace version=\"1\">", "  <pass name=\"a\">", kShader,
                                                      "    <draw file=\"" + quad + "\"/>", "  </pass>", "  <pass name=\"b\">",
                                                      kShader, "    <draw file=\"" + quad + "\"/>", "  </pass>", "</workspace>"}));
    Result<Workspace> both = load(twice);
    ASSERT_TRUE(both.ok()) << formatAll(both.diagnostics());
    EXPECT_EQ(both.diagnostics().size(), 1u) << formatAll(both.diagnostics());
    EXPECT_EQ(both->passes[1].draw.mesh, BuiltinMesh::Quad);

    // A stock model that is there is used as it is; any other missing model stays an error.
    dir.write("ws/Sphere.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Result<Workspace> found = load(dir.write("ws/sphere.xml", drawWorkspace("sphere.obj")));
    ASSERT_TRUE(found.ok()) << formatAll(found.diagnostics());
    EXPECT_EQ(found->passes[0].draw.file, "Sphere.obj");
    EXPECT_FALSE(found->passes[0].draw.mesh);
    EXPECT_EQ(errors(load(dir.write("ws/elephant.xml", drawWorkspace("ElephantBody.3ds")))).size(), 1u);

    // Under the sandbox a stock model outside it is refused, not replaced.
    dir.write("elsewhere/Teapot.3ds", "");
    EXPECT_EQ(errors(load(dir.write("ws/out.xml", drawWorkspace("../elsewhere/Teapot.3ds")), sandbox())).size(), 1u);
}

// A stand-in has the size of the stock model it stands for, as measured from the public copies of
// RenderMonkey's media (io/mesh/StockModels.h): its drawn vertices span the stock model's bounding
// box along its largest side, about the same centre. Sphere.3ds: radius 52 about (0.001, 0.001,
// 0.001); Teapot.3ds: x from -74.85 (the handle) to 86.00 (the spout), centre (5.57, 1.14, 0.13).
TEST(MediaResolver, MissingStockModelsStandInAtTheirMeasuredSize) {
    test::ScratchDir dir;
    auto drawnBounds = [&](const std::string& model) {
        fs::path ws = dir.write("ws/" + model + ".xml", lines({"<workspace version=\"1\">", "  <pass name=\"p\">", kShader,
                                                              "    <draw file=\"..\\Media\\Models\\" + model + "\"/>",
                                                              "  </pass>", "</workspace>"}));
        Result<Workspace> l = load(ws);
        EXPECT_TRUE(l.ok()) << formatAll(l.diagnostics());
        EXPECT_TRUE(l->passes[0].draw.stockSize);
        const std::optional<Mesh> mesh = makeDrawnMesh(l->passes[0].draw);
        glm::dvec3 low(1e30), high(-1e30);
        for (const glm::vec3& p : mesh->positions) {
            low = glm::min(low, glm::dvec3(p));
            high = glm::max(high, glm::dvec3(p));
        }
        return std::pair{low, high};
    };
    const auto [sphereLow, sphereHigh] = drawnBounds("Sphere.3ds");
    EXPECT_NEAR(sphereHigh.y, 52.0026, 1e-3);  // the poles: the built-in sphere's tallest extent
    EXPECT_NEAR(sphereLow.y, -52.0006, 1e-3);
    EXPECT_NEAR(0.5 * (sphereLow.x + sphereHigh.x), 0.001, 1e-3);
    const auto [teapotLow, teapotHigh] = drawnBounds("Teapot.3ds");
    EXPECT_NEAR(teapotLow.x, -74.8518, 1e-3);  // x is the teapot's largest side
    EXPECT_NEAR(teapotHigh.x, 85.9982, 1e-3);
    EXPECT_NEAR(0.5 * (teapotLow.y + teapotHigh.y), 0.5 * (-38.2332 + 40.5168), 1e-3);
    EXPECT_NEAR(0.5 * (teapotLow.z + teapotHigh.z), 0.5 * (-49.8711 + 50.1289), 1e-3);
    const auto [quadLow, quadHigh] = drawnBounds("ScreenAlignedQuad.3ds");
    EXPECT_NEAR(quadLow.x, -0.999, 1e-6);
    EXPECT_NEAR(quadHigh.y, 1.001, 1e-6);
    EXPECT_NEAR(quadLow.z, 0.001, 1e-6);
}

// Sphere.3ds (opengles-book-samples' copy) has u = 0.25 on its -x side, 0.5 at -z and 0.75 at +x,
// the other way round from the built-in sphere: its stand-in's u is turned to match, so a texture
// or normal map reads as on the stock model (lazyartist's NormalMapping Test3.rfx).
TEST(MediaResolver, TheSphereStandInsTextureRunsAsTheStockSpheres) {
    test::ScratchDir dir;
    fs::path ws = dir.write("ws/sphere.xml", lines({"<workspace version=\"1\">", "  <pass name=\"p\">", kShader,
                                                    "    <draw file=\"..\\Media\\Models\\Sphere.3ds\"/>", "  </pass>",
                                                    "</workspace>"}));
    Result<Workspace> l = load(ws);
    ASSERT_TRUE(l.ok()) << formatAll(l.diagnostics());
    const std::optional<Mesh> mesh = makeDrawnMesh(l->passes[0].draw);
    ASSERT_TRUE(mesh);
    // The u of the equator vertex nearest each direction.
    auto uToward = [&](glm::dvec3 direction) {
        double best = -2.0, u = -1.0;
        for (size_t i = 0; i < mesh->positions.size(); ++i) {
            const glm::dvec3 p = glm::normalize(glm::dvec3(mesh->positions[i]));
            if (glm::dot(p, direction) > best) best = glm::dot(p, direction), u = mesh->texcoords[i].x;
        }
        return u;
    };
    EXPECT_NEAR(uToward({-1, 0, 0}), 0.25, 0.02);
    EXPECT_NEAR(uToward({0, 0, -1}), 0.5, 0.02);
    EXPECT_NEAR(uToward({1, 0, 0}), 0.75, 0.02);
}

TEST(MediaResolver, WithPlaceholdersMissingTexturesAndModelsGetStandInsAndOneWarningPerFile) {
    test::ScratchDir dir;
    const std::string stone = "C:\\RenderMonkey\\Media\\Textures\\Fieldstone.tga";
    const std::string sky = "C:\\RenderMonkey\\Media\\Cubemaps\\Sky.dds";
    fs::path file = dir.write("ws/fx.xml", lines({
        "<workspace version=\"1\">",
        "  <texture name=\"stone\" file=\"" + stone + "\"/>",
        "  <cubemap name=\"sky\">" + [&] {
            std::string faces;
            for (const char* side : {"+x", "-x", "+y", "-y", "+z", "-z"})
                faces += "<face side=\"" + std::string(side) + "\" file=\"" + sky + "\"/>";
            return faces;
        }() + "</cubemap>",
        "  <pass name=\"a\">", kShader, "    <draw file=\"..\\Models\\MyTorus2.3ds\"/>", "  </pass>",
        "  <pass name=\"b\">", kShader, "    <draw file=\"..\\Models\\MyTorus2.3ds\"/>", "  </pass>",
        "  <pass name=\"c\">", kShader, "    <draw file=\"Elephant.x\"/>", "  </pass>",
        "</workspace>"}));
    // By default each is an error: the texture, six faces, two passes drawing one model, one more model.
    EXPECT_EQ(errors(load(file)).size(), 1u + 6u + 2u + 1u) << formatAll(load(file).diagnostics());

    MediaOptions placeholders;
    placeholders.missing = MissingMedia::Placeholder;
    Result<Workspace> l = load(file, placeholders);
    ASSERT_TRUE(l.ok()) << formatAll(l.diagnostics());
    const Lines warnings = [&] {
        Lines out;
        for (const Diagnostic& d : l.diagnostics()) out.push_back(d.format());
        return out;
    }();
    ASSERT_EQ(warnings.size(), 4u) << formatAll(l.diagnostics());
    EXPECT_NE(warnings[0].find("fx.xml:2: warning: <texture name=\"stone\">: image file '" + stone + "' not found"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("; a magenta and grey checker stands in for the texture (--missing-media placeholder)"), std::string::npos);
    EXPECT_NE(warnings[1].find("fx.xml:3: warning: <cubemap name=\"sky\">"), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[1].find("stands in for the whole cube map"), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[2].find("fx.xml:6: warning: <draw>: model file '..\\Models\\MyTorus2.3ds' not found"), std::string::npos) << warnings[2];
    EXPECT_NE(warnings[2].find("drawing rmfx's built-in 'torus' in its place (--missing-media placeholder)"), std::string::npos);
    EXPECT_NE(warnings[3].find("fx.xml:14: warning: <draw>: model file 'Elephant.x' not found"), std::string::npos) << warnings[3];
    EXPECT_NE(warnings[3].find("built-in 'cube'"), std::string::npos) << warnings[3];

    const Texture* texture = l->findTexture("stone");
    ASSERT_TRUE(texture && texture->supplied);
    EXPECT_TRUE(texture->files.empty());
    EXPECT_EQ(texture->supplied->width, 64);
    EXPECT_FLOAT_EQ(texture->supplied->at(0, 0, 0), 1.0f);  // magenta in the corner, grey beside it
    EXPECT_FLOAT_EQ(texture->supplied->at(0, 0, 1), 0.0f);
    EXPECT_FLOAT_EQ(texture->supplied->at(8, 0, 1), 0.2f);
    const Texture* cube = l->findTexture("sky");
    ASSERT_TRUE(cube && cube->supplied);
    EXPECT_EQ(cube->supplied->width * 3, cube->supplied->height * 4);  // a cross
    EXPECT_EQ(l->passes[0].draw.mesh, BuiltinMesh::Torus);
    EXPECT_EQ(l->passes[1].draw.mesh, BuiltinMesh::Torus);
    EXPECT_EQ(l->passes[2].draw.mesh, BuiltinMesh::Cube);

    // A file that is there but refused by the sandbox is still an error.
    dir.write("elsewhere/stone.png", "");
    MediaOptions strict = sandbox();
    strict.missing = MissingMedia::Placeholder;
    EXPECT_EQ(errors(load(dir.write("ws/out.xml", textureWorkspace("../elsewhere/stone.png")), strict)).size(), 1u);
}

TEST(MediaResolver, PlaceholderMeshesByName) {
    EXPECT_EQ(placeholderMeshFor("C:\\x\\ScreenAlignedQuad.3ds"), BuiltinMesh::Quad);
    EXPECT_EQ(placeholderMeshFor("Models/MyTeapot2.3DS"), BuiltinMesh::Teapot);
    EXPECT_EQ(placeholderMeshFor("SPHERE_hi.obj"), BuiltinMesh::Sphere);
    EXPECT_EQ(placeholderMeshFor("torus.x"), BuiltinMesh::Torus);
    EXPECT_EQ(placeholderMeshFor("GroundPlane.3ds"), BuiltinMesh::Plane);
    EXPECT_EQ(placeholderMeshFor("Elephant.3ds"), BuiltinMesh::Cube);
    EXPECT_EQ(placeholderMeshFor(""), BuiltinMesh::Cube);
}

TEST(MediaResolver, MakeQuadSpansClipSpaceFacingTheViewer) {
    Mesh quad = makeMesh(BuiltinMesh::Quad);
    ASSERT_EQ(quad.vertexCount(), 4u);
    ASSERT_EQ(quad.triangleCount(), 2u);
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(std::abs(quad.positions[i].x), 1.0f);
        EXPECT_EQ(std::abs(quad.positions[i].y), 1.0f);
        EXPECT_EQ(quad.positions[i].z, 0.0f);
        EXPECT_EQ(quad.normals[i], glm::vec3(0, 0, 1));
        EXPECT_EQ(quad.texcoords[i], (glm::vec2(quad.positions[i]) + 1.0f) * 0.5f);  // (0, 0) bottom-left
    }
    // Counter-clockwise seen from +Z.
    glm::vec3 a = quad.positions[quad.indices[0]], b = quad.positions[quad.indices[1]], c = quad.positions[quad.indices[2]];
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
    EXPECT_EQ(builtinMeshFromName("Quad"), BuiltinMesh::Quad);
}

TEST(MediaResolver, ReferencesAreResolvedOnceAndTheAnswerIsWhatEveryoneOpens) {
    test::ScratchDir dir;
    dir.write("Media/Stone.tga", "stone");
    dir.write("ws/Shaders/Main.frag", "out vec4 c; void main() { c = vec4(1.0); }\n");
    dir.write("ws/Models/Rock.obj", "v 0 0 0\n");
    fs::path ws = dir.write("ws/fx.xml", lines({
                                             "<workspace version=\"1\">",
                                             "  <texture name=\"t\" file=\"..\\media\\stone.TGA\"/>",
                                             "  <pass name=\"p\">",
                                             "    <draw file=\"models\\rock.OBJ\"/>",
                                             "    <shader stage=\"fragment\" file=\"SHADERS\\main.frag\"/>",
                                             "  </pass>",
                                             "</workspace>",
                                         }));
    Result<Workspace> l = load(ws);
    ASSERT_TRUE(l.ok()) << formatAll(l.diagnostics());
    EXPECT_EQ(l->textures[0].files[0], "../Media/Stone.tga");
    EXPECT_EQ(l->passes[0].draw.file, "Models/Rock.obj");
    EXPECT_EQ(l->passes[0].shaders[0].file, "Shaders/Main.frag");
    // Hot reload watches the same files.
    WorkspaceDependencies deps = findWorkspaceDependencies(*l);
    EXPECT_TRUE(deps.find(dir / "Media/Stone.tga"));
    EXPECT_TRUE(deps.find(dir / "ws/Models/Rock.obj"));
    EXPECT_TRUE(deps.find(dir / "ws/Shaders/Main.frag"));
}

TEST(MediaResolver, IncludesTakeBackslashesAndIgnoreCaseToo) {
    test::ScratchDir dir;
    dir.write("ws/Common/Util.glsl", "float util() { return 1.0; }\n");
    dir.write("ws/main.frag", lines({"#include \"common\\util.GLSL\"", "out vec4 c; void main() { c = vec4(util()); }"}));
    fs::path ws = dir.write("ws/fx.xml", lines({"<workspace version=\"1\">", "  <pass name=\"p\">",
                                                "    <shader stage=\"fragment\" file=\"main.frag\"/>", "  </pass>",
                                                "</workspace>"}));
    Result<Workspace> l = load(ws);
    ASSERT_TRUE(l.ok()) << formatAll(l.diagnostics());
    EXPECT_TRUE(findWorkspaceDependencies(*l).find(dir / "ws/Common/Util.glsl"));
}

// ---- the sandbox ----

TEST(Sandbox, RefusesDotDotLeadingOutOfTheWorkspaceFolder) {
    test::ScratchDir dir;
    dir.write("secret.png", "s");
    fs::path ws = dir.write("ws/fx.xml", textureWorkspace("..\\secret.png"));
    EXPECT_TRUE(load(ws).ok());  // without the sandbox it loads
    Result<Workspace> l = load(ws, sandbox());
    EXPECT_FALSE(l.ok());
    EXPECT_EQ(errors(l), (Lines{ws.string() + ":2: error: <texture name=\"t\">: image file '..\\secret.png' leads outside "
                                              "the sandbox: it is " + (dir / "secret.png").string() +
                                              ", and the sandbox allows only the workspace folder " + (dir / "ws").string() +
                                              " (give its folder with --media DIR, or run with --no-sandbox)"}));
    // The person running rmfx may allow the folder.
    EXPECT_TRUE(load(ws, sandbox({dir.path()})).ok());
}

TEST(Sandbox, RefusesAbsolutePaths) {
    test::ScratchDir dir;
    fs::path secret = dir.write("outside/secret.png", "s");
    fs::path ws = dir.write("ws/fx.xml", textureWorkspace(secret.string()));
    EXPECT_TRUE(load(ws).ok());
    dir.write("media/readme.txt", "");
    Result<Workspace> l = load(ws, sandbox({dir / "media"}));
    EXPECT_EQ(errors(l), (Lines{ws.string() + ":2: error: <texture name=\"t\">: image file '" + secret.string() +
                                "' leads outside the sandbox: it is " + secret.string() +
                                ", and the sandbox allows only the workspace folder " + (dir / "ws").string() +
                                " and the media folder " + (dir / "media").string() +
                                " (give its folder with --media DIR, or run with --no-sandbox)"}));
    EXPECT_TRUE(load(ws, sandbox({dir / "outside"})).ok());
}

TEST(Sandbox, RefusesSymbolicLinksLeadingOutForEveryKindOfFile) {
    test::ScratchDir dir;
    dir.write("outside/secret.png", "s");
    dir.write("outside/rock.obj", "v 0 0 0\n");
    dir.write("outside/main.frag", "out vec4 c; void main() { c = vec4(1.0); }\n");
    fs::create_directories(dir / "ws");
    fs::create_symlink("../outside/secret.png", dir / "ws/link.png");
    fs::create_symlink(dir / "outside", dir / "ws/models");  // a folder link
    fs::create_symlink("../outside/main.frag", dir / "ws/main.frag");
    fs::path ws = dir.write("ws/fx.xml", lines({
                                             "<workspace version=\"1\">",
                                             "  <texture name=\"t\" file=\"link.png\"/>",
                                             "  <pass name=\"p\">",
                                             "    <draw file=\"models/rock.obj\"/>",
                                             "    <shader stage=\"fragment\" file=\"main.frag\"/>",
                                             "  </pass>",
                                             "</workspace>",
                                         }));
    EXPECT_TRUE(load(ws).ok());
    Result<Workspace> l = load(ws, sandbox());
    const std::string allowed = ", and the sandbox allows only the workspace folder " + (dir / "ws").string() +
                                " (give its folder with --media DIR, or run with --no-sandbox)";
    EXPECT_EQ(errors(l), (Lines{
                             ws.string() + ":2: error: <texture name=\"t\">: image file 'link.png' leads outside the "
                                           "sandbox through a symbolic link: it is " +
                                 (dir / "outside/secret.png").string() + allowed,
                             ws.string() + ":5: error: <shader>: shader file 'main.frag' leads outside the sandbox "
                                           "through a symbolic link: it is " +
                                 (dir / "outside/main.frag").string() + allowed,
                             ws.string() + ":4: error: <draw>: model file 'models/rock.obj' leads outside the sandbox "
                                           "through a symbolic link: it is " +
                                 (dir / "outside/rock.obj").string() + allowed,
                         }));
}

TEST(Sandbox, RefusesAnIncludeThatIsASymbolicLinkLeadingOut) {
    test::ScratchDir dir;
    dir.write("outside/evil.glsl", "float evil;\n");
    dir.write("ws/main.frag", lines({"#include \"evil.glsl\"", "out vec4 c; void main() { c = vec4(1.0); }"}));
    fs::create_symlink("../outside/evil.glsl", dir / "ws/evil.glsl");
    fs::path ws = dir.write("ws/fx.xml", lines({"<workspace version=\"1\">", "  <pass name=\"p\">",
                                                "    <shader stage=\"fragment\" file=\"main.frag\"/>", "  </pass>",
                                                "</workspace>"}));
    for (bool on : {false, true}) {
        Result<Workspace> l = load(ws, {{}, on});
        EXPECT_EQ(errors(l), (Lines{(dir / "ws/main.frag").string() +
                                    ":1: error: #include: \"evil.glsl\" lies outside the workspace folder " +
                                    (dir / "ws").string()}));
    }
}

TEST(Sandbox, AllowsAnIncludeRootOnlyInsideAnAllowedFolder) {
    test::ScratchDir dir;
    dir.write("lib/glsl/common.glsl", "float common_value() { return 1.0; }\n");
    dir.write("lib/variants/main.frag",
              lines({"#include \"glsl/common.glsl\"", "out vec4 c; void main() { c = vec4(common_value()); }"}));
    fs::path ws = dir.write("lib/variants/fx.xml", lines({"<workspace version=\"1\" include-root=\"..\">", "  <pass name=\"p\">",
                                                          "    <shader stage=\"fragment\" file=\"main.frag\"/>",
                                                          "  </pass>", "</workspace>"}));
    EXPECT_TRUE(load(ws).ok());
    Result<Workspace> l = load(ws, sandbox());
    EXPECT_EQ(errors(l), (Lines{ws.string() + ":1: error: <workspace include-root>: include-root " +
                                (dir / "lib").string() + " (" + (dir / "lib").string() +
                                ") lies outside the sandbox, which allows only the workspace folder " +
                                (dir / "lib/variants").string() + " (give it with --media DIR, or run with --no-sandbox)"}));
    EXPECT_TRUE(load(ws, sandbox({dir / "lib"})).ok());
}

TEST(Sandbox, AllowedReferencesStillLoad) {
    test::ScratchDir dir;
    dir.write("ws/tex/a.png", "a");
    dir.write("ws/inc/x.glsl", "float x() { return 1.0; }\n");
    dir.write("ws/main.frag", lines({"#include \"inc/x.glsl\"", "out vec4 c; void main() { c = vec4(x()); }"}));
    dir.write("media/Models/Rock.obj", "v 0 0 0\n");
    fs::create_symlink("tex/a.png", dir / "ws/link.png");  // a link that stays inside is fine
    fs::path ws = dir.write("ws/fx.xml", lines({
                                             "<workspace version=\"1\">",
                                             "  <texture name=\"t\" file=\"tex\\a.png\"/>",
                                             "  <texture name=\"u\" file=\"link.png\"/>",
                                             "  <pass name=\"p\">",
                                             "    <draw file=\"C:\\RenderMonkey\\Media\\Models\\rock.obj\"/>",
                                             "    <shader stage=\"fragment\" file=\"main.frag\"/>",
                                             "  </pass>",
                                             "</workspace>",
                                         }));
    Result<Workspace> l = load(ws, sandbox({dir / "media"}));
    ASSERT_TRUE(l.ok()) << formatAll(l.diagnostics());
    EXPECT_EQ(l->textures[0].files[0], "tex/a.png");
    EXPECT_EQ(l->passes[0].draw.file, (dir / "media/Models/Rock.obj").string());
}

TEST(MediaArguments, MediaSandboxAndNoSandbox) {
    test::ScratchDir dir;
    std::vector<std::string> args{"x.xml", "--media", dir.path().string(), "--sandbox", "--media", "no/such/dir", "--no-sandbox"};
    MediaOptions media;
    size_t i = 0;
    EXPECT_EQ(takeMediaArgument(args, i, media), std::nullopt);
    i = 1;
    EXPECT_EQ(takeMediaArgument(args, i, media), "");
    EXPECT_EQ(i, 2u);
    EXPECT_EQ(media.searchPath, (std::vector<fs::path>{dir.path()}));
    i = 3;
    EXPECT_EQ(takeMediaArgument(args, i, media), "");
    EXPECT_TRUE(media.sandbox);
    i = 4;
    EXPECT_EQ(takeMediaArgument(args, i, media), "--media: 'no/such/dir' is not a folder");
    i = 6;
    EXPECT_EQ(takeMediaArgument(args, i, media), "");
    EXPECT_FALSE(media.sandbox);
    std::vector<std::string> last{"--media"};
    i = 0;
    EXPECT_EQ(takeMediaArgument(last, i, media), "--media needs a folder");
}

TEST(MediaArguments, MissingMedia) {
    MediaOptions media;
    EXPECT_EQ(media.missing, MissingMedia::Error);
    std::vector<std::string> args{"--missing-media", "placeholder", "--missing-media=error", "--missing-media", "maybe",
                                  "--missing-media"};
    size_t i = 0;
    EXPECT_EQ(takeMediaArgument(args, i, media), "");
    EXPECT_EQ(i, 1u);
    EXPECT_EQ(media.missing, MissingMedia::Placeholder);
    i = 2;
    EXPECT_EQ(takeMediaArgument(args, i, media), "");
    EXPECT_EQ(media.missing, MissingMedia::Error);
    i = 3;
    EXPECT_EQ(takeMediaArgument(args, i, media), "--missing-media: 'maybe' is neither 'error' nor 'placeholder'");
    i = 5;
    EXPECT_EQ(takeMediaArgument(args, i, media), "--missing-media needs 'error' or 'placeholder'");
}

}  // namespace rmfx
