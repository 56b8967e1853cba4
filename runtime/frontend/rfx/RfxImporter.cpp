#include "frontend/rfx/RfxImporter.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string_view>

#include "core/IdentifierSearch.h"
#include "frontend/rfx/detail/RfxCamera.h"
#include "frontend/rfx/detail/RfxDoctype.h"
#include "frontend/rfx/detail/RfxEffectCatalogue.h"
#include "frontend/rfx/detail/RfxMatrixOrder.h"
#include "frontend/rfx/detail/RfxPassReader.h"
#include "frontend/rfx/detail/RfxRenderStates.h"
#include "io/xml/XmlDocumentParser.h"
#include "io/xml/XmlElementReader.h"

namespace rmfx {
namespace {

using namespace rfx;
using tinyxml2::XMLElement;

bool isPassTag(std::string_view tag) { return tag == "RmGLPass" || tag == "RmGLESPass" || tag == "RmPass"; }
bool isEffectTag(std::string_view tag) {
    return tag == "RmOpenGLEffect" || tag == "RmOpenGLESEffect" || tag == "RmDirectXEffect" || tag == "RmEffectGroup";
}

// The declarations directly under one level (workspace, group or effect); passes, effects and
// editor state are the caller's or nobody's.
Declarations readLevel(const XMLElement* level, const std::string& file, Diagnostics& diagnostics) {
    Declarations d;
    for (const XMLElement* x = level->FirstChildElement(); x; x = x->NextSiblingElement()) {
        std::string_view tag = x->Name();
        if (isPassTag(tag) || isEffectTag(tag) || tag == "RmRegistryBranch" || tag == "RmPlugInData" ||
            tag == "RmCamera")
            continue;
        RfxElement e(x, file, diagnostics);
        if (!readDeclaration(e, d)) e.warning("rmfx does not know <" + std::string(tag) + "> here; ignored");
    }
    return d;
}

// Innermost first: a name declared at several levels is the innermost one's.
template <class T>
void addVisible(std::vector<T>& into, const std::vector<T>& from) {
    for (const T& item : from)
        if (std::none_of(into.begin(), into.end(), [&](const T& x) { return x.name == item.name; })) into.push_back(item);
}

void readCamera(const RfxEffectEntry& effect, const std::string& file, Diagnostics& diagnostics, Workspace& ws) {
    RfxElement e(effect.element, file, diagnostics);
    std::string active = e.text("ACTIVE_CAMERA", false).value_or("");
    const XMLElement* chosen = nullptr;
    for (const XMLElement* c = effect.element->FirstChildElement("RmCamera"); c; c = c->NextSiblingElement("RmCamera"))
        if (!chosen || RfxElement(c, file, diagnostics).name() == active) chosen = c;
    const std::string chosenName = chosen ? RfxElement(chosen, file, diagnostics).name() : "";
    // Without any RmCamera, RenderMonkey showed the effect through its viewer's camera, which
    // ACTIVE_CAMERA then names ("Camera", by default): RfxCameraFraming recovers or frames it.
    if (!active.empty() && chosen && chosenName != active)
        e.warning("ACTIVE_CAMERA '" + active + "' names no <RmCamera> of the effect; using the first one, '" + chosenName + "'");
    const CameraConvention convention = ws.camera.convention;
    if (chosen) ws.camera = orbitFromRmCamera(RfxElement(chosen, file, diagnostics));
    ws.camera.convention = convention;
    // Every other camera, for the passes that look through it (RmCameraReference); a pass that
    // names the active one uses the camera the viewer moves.
    for (const XMLElement* c = effect.element->FirstChildElement("RmCamera"); c; c = c->NextSiblingElement("RmCamera")) {
        if (c == chosen) continue;
        RfxElement camera(c, file, diagnostics);
        if (ws.findCamera(camera.name())) continue;
        ws.cameras.push_back({camera.name(), orbitFromRmCamera(camera)});
        ws.cameras.back().settings.convention = convention;
    }
}

std::string stageName(int stage) {
    return stage >= d3dSamplerStage(0, true) ? "vertex texture stage " + std::to_string(stage - d3dSamplerStage(0, true))
                                             : "stage " + std::to_string(stage);
}

// A sampler with no texture object of its name: in Direct3D it reads what its stage holds, bound
// by a texture object of this pass under another name or left there by a pass before it.
void bindSamplersWithoutObject(ReadPass& p, RfxApi api, const std::map<int, Sampler>& stages, const std::string& file,
                               Diagnostics& diagnostics) {
    std::set<std::string> objectsReadByStage;
    for (const ReadPass::SamplerWithoutObject& s : p.samplersWithoutObject) {
        RfxElement e(s.element, file, diagnostics);
        std::string message = "sampler '" + s.name + "' has no <RmTextureObject NAME=\"" + s.name + "\"> in the pass";
        if (!s.used) {
            e.warning(message + " to say which texture it reads; its shaders do not use it, so it is ignored");
            continue;
        }
        if (api != RfxApi::Direct3D) {
            e.error(message + " to say which texture it reads");
            continue;
        }
        if (!s.stage) {
            e.error(message + " and no REGISTER: rmfx cannot tell which sampler stage it reads");
            continue;
        }
        auto bound = stages.find(*s.stage);
        if (bound == stages.end()) {
            e.error(message + ", and no texture object of the pass or of a pass before it binds " + stageName(*s.stage) +
                    ", the stage it reads (REGISTER)");
            continue;
        }
        Sampler sampler = bound->second;
        objectsReadByStage.insert(sampler.uniform);
        sampler.uniform = s.name;
        sampler.where = e.where();
        p.pass.samplers.push_back(std::move(sampler));
    }
    // A texture object no sampler is named after, read by stage: not a sampler of its own.
    std::erase_if(p.pass.samplers, [&](const Sampler& s) {
        return objectsReadByStage.count(s.uniform) &&
               std::none_of(p.pass.shaders.begin(), p.pass.shaders.end(),
                            [&](const ShaderSource& shader) { return mentionsIdentifier(shader.code, s.uniform); });
    });
}

// RenderMonkey keeps a matrix variable row by row as it shows it, in the column-vector convention
// (a translation in VALUE_3, 7 and 11), and rmfx reads VALUE_0…3 as its first column: right for a
// shader that multiplies mul(M, v) (ColumnVector, uploaded untransposed). For mul(v, M) RenderMonkey
// passed a matrix it did not fill by semantic the way it passed those it did, turned round (the
// shadow-mapping course files' gWorldMatrix, moved by VALUE_7 = -40, lands where they draw it only
// so): a stored matrix that only row-vector HLSL reads is transposed. Semantic ones are filled by
// rmfx; assembly reads registers as rows, like mul(M, v).
void turnStoredMatricesForRowVectors(Workspace& ws) {
    auto readers = [&](const std::string& name, const Pass* only) {
        int rowVector = 0, other = 0;
        for (const Pass& pass : ws.passes) {
            if (only && &pass != only) continue;
            for (const ShaderSource& s : pass.shaders) {
                if (!mentionsIdentifier(s.code, name)) continue;
                (s.dialect == ShaderDialect::Hlsl && s.matrixOrder == HlslMatrixOrder::RowVector ? rowVector : other) += 1;
            }
        }
        return rowVector > 0 && other == 0;
    };
    auto transpose = [](Variable& v) {
        if (v.value.type != ValueType::Mat4 || !v.semantic.empty()) return;
        std::array<float, 16> turned{};
        for (size_t i = 0; i < 16; ++i) turned[i] = v.value.data[(i % 4) * 4 + i / 4];
        std::copy(turned.begin(), turned.end(), v.value.data.begin());
    };
    for (Pass& pass : ws.passes)
        for (Variable& v : pass.constants)
            if (readers(v.name, &pass)) transpose(v);
    for (Variable& v : ws.variables)
        if (readers(v.name, nullptr)) transpose(v);
}

Workspace importEffect(const RfxEffectEntry& effect, const std::filesystem::path& path,
                       const std::filesystem::path& folder, const RfxImportOptions& options, Diagnostics& diagnostics) {
    const std::string file = path.string();
    Workspace ws;
    ws.path = path;
    ws.folder = folder;
    ws.name = effect.path;
    ws.description = std::string("RenderMonkey ") + rfxApiName(effect.api) + " effect '" + effect.path + "'";
    // RenderMonkey shows what shaders write, unconverted, in an 8-bit back buffer.
    ws.output.format = TargetFormat::RGBA8;
    ws.output.transform = DisplayTransform::None;
    ws.output.where = {file, effect.element->GetLineNum()};
    ws.profile = effect.api == RfxApi::OpenGL ? GlProfile::Compatibility : GlProfile::Core;

    Declarations effectLevel = readLevel(effect.element, file, diagnostics);
    Declarations groupLevel = effect.group ? readLevel(effect.group, file, diagnostics) : Declarations{};
    Declarations workspaceLevel = readLevel(effect.workspace, file, diagnostics);
    VisibleScopes scopes;
    scopes.levels = {&effectLevel};
    if (effect.group) scopes.levels.push_back(&groupLevel);
    scopes.levels.push_back(&workspaceLevel);
    for (const Declarations* level : scopes.levels) {
        addVisible(ws.variables, level->variables);
        addVisible(ws.textures, level->textures);
        addVisible(ws.targets, level->targets);
    }
    if (effect.api == RfxApi::Direct3D) {
        // RenderMonkey's Direct3D viewer: left-handed, from -z toward the origin (the View that
        // files saved without moving it holds: identity rotation, the eye 200 units down -z).
        ws.camera.convention = CameraConvention::Direct3D;
        ws.textureSpace = TextureSpace::Direct3D9;
        ws.camera.yawDegrees = 180.0f;
        ws.camera.pitchDegrees = 0.0f;
    }
    readCamera(effect, file, diagnostics, ws);

    // Only Direct3D effects have HLSL (and only they are warned about a missing version).
    std::map<const XMLElement*, HlslMatrixOrder> shaderOrders;
    HlslMatrixOrder hlslMatrices = HlslMatrixOrder::RowVector;
    if (effect.api == RfxApi::Direct3D && options.hlslMatrices) {
        hlslMatrices = *options.hlslMatrices;
    } else if (effect.api == RfxApi::Direct3D) {
        const MatrixOrderEvidence evidence = matrixOrderEvidence(RfxElement(effect.element, file, diagnostics), scopes);
        hlslMatrices = hlslMatrixOrderOf(RfxElement(effect.workspace, file, diagnostics), evidence);
        shaderOrders = shaderMatrixOrders(evidence);
    }
    std::vector<ReadPass> passes;
    for (const XMLElement* x = effect.element->FirstChildElement(); x; x = x->NextSiblingElement())
        if (isPassTag(x->Name())) {
            RfxElement e(x, file, diagnostics);
            std::string_view expected = effect.api == RfxApi::OpenGL ? "RmGLPass" : effect.api == RfxApi::OpenGLES ? "RmGLESPass" : "RmPass";
            if (expected != x->Name()) {
                e.error("a " + std::string(rfxApiName(effect.api)) + " effect takes <" + std::string(expected) + "> passes");
                continue;
            }
            if (auto p = readPass(e, effect.api, scopes, hlslMatrices, shaderOrders)) passes.push_back(std::move(*p));
        }
    // Textures and renderable textures a pass declares itself join the workspace's: rmfx has one
    // namespace for them, so a second declaration of a name with another file is a warning.
    for (const ReadPass& p : passes) {
        for (const Texture& t : p.declared.textures) {
            const Texture* known = ws.findTexture(t.name);
            if (!known) ws.textures.push_back(t);
            else if (known->files != t.files || known->kind != t.kind)
                diagnostics.push_back({Diagnostic::Severity::Warning, t.where, "<pass \"" + p.pass.name + "\">",
                                       "texture '" + t.name + "' is declared again with another file; rmfx keeps the one at " +
                                           known->where.file + ":" + std::to_string(known->where.line)});
        }
        for (const RenderTarget& t : p.declared.targets)
            if (!ws.findTarget(t.name)) ws.targets.push_back(t);
    }
    std::stable_sort(passes.begin(), passes.end(), [](const ReadPass& a, const ReadPass& b) { return a.index < b.index; });
    const Pass* previous = nullptr;
    // Render states carry over in run order from the last pass that runs (RenderMonkey set them on
    // the device and left them there: fur.rfx sets blending in its first shell pass only, for all
    // fifteen). The first pass starts from RenderMonkey's frame state.
    Pass carried;
    rfx::setRenderMonkeyDefaults(carried);
    // Direct3D's front faces are the ones drawn clockwise on the screen.
    if (effect.api == RfxApi::Direct3D) carried.raster.frontCounterClockwise = false;
    bool carriedSeparateAlpha = false;
    std::map<int, Sampler> carriedStages;  // Direct3D: what each sampler stage holds (ReadPass::stageObjects)
    std::set<int> vertexFogWarned;  // lines of the FOGENABLE states warned about
    for (ReadPass& p : passes) {
        p.pass.blend = carried.blend;
        p.pass.depth = carried.depth;
        p.pass.raster = carried.raster;
        p.pass.fog = carried.fog;
        p.pass.alphaTest = carried.alphaTest;
        bool separateAlpha = carriedSeparateAlpha;
        for (const XMLElement* block : p.stateBlocks)
            rfx::applyRenderStateBlock(RfxElement(block, file, diagnostics), effect.api, p.pass, separateAlpha);
        if (p.pass.enabled && p.runnable) {
            carried.blend = p.pass.blend;
            carried.depth = p.pass.depth;
            carried.raster = p.pass.raster;
            carried.fog = p.pass.fog;
            carried.alphaTest = p.pass.alphaTest;
            carriedSeparateAlpha = separateAlpha;
        }
        if (effect.api == RfxApi::Direct3D) rfx::finishD3dRenderStates(p.pass, separateAlpha);
        // Depth buffering off (D3DRS_ZENABLE 0, GL_DepthEnable false) writes no depth either,
        // whatever the write state holds; that state comes back with the next pass that turns
        // depth buffering on (it is carried as set).
        if (!p.pass.depth.test) p.pass.depth.write = false;
        std::map<int, Sampler> stages = carriedStages;
        for (const auto& [stage, sampler] : p.stageObjects) stages[stage] = sampler;
        bindSamplersWithoutObject(p, effect.api, stages, file, diagnostics);
        if (p.pass.enabled && p.runnable) carriedStages = std::move(stages);
        // With a vertex shader, Direct3D's vertex fog is the shader's FOG output, not depth. Said
        // once for the state, though the passes after it carry it.
        if (effect.api == RfxApi::Direct3D && p.pass.enabled && p.pass.fog.enabled && !p.pass.fog.mode && p.pass.fog.vertexFog &&
            vertexFogWarned.insert(p.pass.fog.where.line).second)
            diagnostics.push_back({Diagnostic::Severity::Warning, p.pass.fog.where, "<RmPass NAME=\"" + p.pass.name + "\">",
                                   "vertex fog (D3DRS_FOGVERTEXMODE) takes the vertex shader's FOG output, which rmfx does "
                                   "not blend: drawn without fog (table fog, D3DRS_FOGTABLEMODE, is applied)"});
        if (!p.pass.camera.empty() && !ws.findCamera(p.pass.camera)) {
            // Not among the named ones: the effect's chosen (active) camera, or none at all.
            bool declared = false;
            for (const XMLElement* c = effect.element->FirstChildElement("RmCamera"); c && !declared; c = c->NextSiblingElement("RmCamera"))
                declared = RfxElement(c, file, diagnostics).name() == p.pass.camera;
            if (!declared)
                diagnostics.push_back({Diagnostic::Severity::Warning, p.pass.cameraWhere, "<RmCameraReference NAME=\"" + p.pass.camera + "\">",
                                       "the effect has no <RmCamera NAME=\"" + p.pass.camera + "\">; the pass uses the effect's camera"});
            p.pass.camera.clear();  // the active camera: the one the viewer moves
        }
        // No RmModelReference: rmfx's full-screen triangle (docs/rendermonkey.md).
        if (!p.pass.draw.mesh && p.pass.draw.file.empty()) p.pass.draw.mesh = BuiltinMesh::FullscreenTriangle;
        if (p.pass.shaders.empty() && p.runnable) {
            if (previous) {
                // The program comes with what it reads: samplers and streams, unless the pass
                // names its own.
                p.pass.shaders = previous->shaders;
                if (p.pass.samplers.empty()) p.pass.samplers = previous->samplers;
                if (p.pass.streams.empty()) p.pass.streams = previous->streams;
            } else {
                diagnostics.push_back({Diagnostic::Severity::Error, p.pass.where, "<pass \"" + p.pass.name + "\">",
                                       "it has no shaders and no pass runs before it to lend its program"});
            }
        }
        // A Direct3D pass with a vertex shader and no pixel shader ran with the pixel shader the
        // pass before it left on the device (the assembly fur's shell passes set only a vertex
        // shader), with that pass's samplers unless it names its own.
        const auto hasStage = [](const std::vector<ShaderSource>& shaders, ShaderStage stage) {
            return std::any_of(shaders.begin(), shaders.end(), [&](const ShaderSource& s) { return s.stage == stage; });
        };
        if (effect.api == RfxApi::Direct3D && p.runnable && previous && hasStage(p.pass.shaders, ShaderStage::Vertex) &&
            !hasStage(p.pass.shaders, ShaderStage::Fragment) && hasStage(previous->shaders, ShaderStage::Fragment)) {
            for (const ShaderSource& s : previous->shaders)
                if (s.stage == ShaderStage::Fragment) p.pass.shaders.push_back(s);
            if (p.pass.samplers.empty()) p.pass.samplers = previous->samplers;
        }
        if (!p.runnable && p.pass.enabled)
            diagnostics.push_back({Diagnostic::Severity::Error, p.pass.where, "<pass \"" + p.pass.name + "\">",
                                   "the effect cannot run: " + p.whyNotRunnable + " (disable the pass to run the rest)"});
        if (!p.runnable && !p.pass.enabled) {
            diagnostics.push_back({Diagnostic::Severity::Warning, p.pass.where, "<pass \"" + p.pass.name + "\">",
                                   "disabled, and it could not run: " + p.whyNotRunnable + "; left out of the workspace"});
            continue;
        }
        ws.passes.push_back(std::move(p.pass));
        previous = &ws.passes.back();
    }
    turnStoredMatricesForRowVectors(ws);
    // RenderMonkey clears its back buffer (colour and depth) before every frame: the first pass
    // that draws to the output clears what it does not clear itself, to opaque black and depth 1.
    for (Pass& pass : ws.passes) {
        if (!pass.enabled || !pass.target.empty()) continue;
        if (!pass.clear.color) pass.clear.color = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        if (!pass.clear.depth) pass.clear.depth = 1.0f;
        break;
    }
    // RenderMonkey runs the passes in order, and a renderable texture keeps its contents from one
    // frame to the next: a pass reading one that no pass before it has written this frame reads
    // what the last frame left there (feedback effects "copy back" a later pass's result).
    for (size_t i = 0; i < ws.passes.size(); ++i)
        for (Sampler& s : ws.passes[i].samplers) {
            if (s.target.empty()) continue;
            const bool writtenBefore = std::any_of(ws.passes.begin(), ws.passes.begin() + static_cast<long>(i), [&](const Pass& p) {
                return p.enabled && p.target == s.target;
            });
            if (!writtenBefore) s.previousFrame = true;
        }
    // Texture variables no pass samples are left out: RenderMonkey files keep textures of other
    // effects at the workspace level, and their missing media must not stop this effect.
    std::erase_if(ws.textures, [&](const Texture& t) {
        return std::none_of(ws.passes.begin(), ws.passes.end(), [&](const Pass& p) {
            return std::any_of(p.samplers.begin(), p.samplers.end(), [&](const Sampler& s) { return s.texture == t.name; });
        });
    });
    if (ws.passes.empty())
        diagnostics.push_back({Diagnostic::Severity::Error, {file, effect.element->GetLineNum()}, "<" + std::string(effect.element->Name()) + " NAME=\"" + effect.name + "\">",
                               "the effect has no passes"});
    return ws;
}

}  // namespace

bool isRfxPath(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".rfx";
}

Result<Workspace> importRfxText(const std::string& text, const std::filesystem::path& path,
                                const std::filesystem::path& folder, const RfxImportOptions& options) {
    const std::string file = path.string();
    return xml::parseXmlText(blankDoctype(text), file, "RENDER_MONKEY", [&](const XMLElement* root, Diagnostics& diagnostics) {
        RfxCatalogue catalogue = readCatalogue(root, file, diagnostics);
        const RfxEffectEntry* effect = chooseEffect(catalogue, options.effect, file, diagnostics);
        if (!effect || hasErrors(diagnostics)) return Workspace{};
        return importEffect(*effect, path, folder, options, diagnostics);
    });
}

Result<Workspace> importRfxFile(const std::filesystem::path& path, const RfxImportOptions& options) {
    return xml::parseXmlFile(path, [&](const std::string& text) { return importRfxText(text, path, xml::folderOf(path), options); });
}

Result<std::vector<RfxEffectSummary>> listRfxEffects(const std::filesystem::path& path) {
    using Listed = Result<std::vector<RfxEffectSummary>>;
    Result<std::string> text = xml::readTextFile(path);
    if (!text) return Listed::failure(std::move(text).diagnostics());
    Diagnostics diagnostics;
    tinyxml2::XMLDocument doc;
    const XMLElement* root = xml::parseDocument(doc, blankDoctype(*text), path.string(), "RENDER_MONKEY", diagnostics);
    if (!root) return Listed::failure(std::move(diagnostics));
    RfxCatalogue catalogue = readCatalogue(root, path.string(), diagnostics);
    if (hasErrors(diagnostics)) return Listed::failure(std::move(diagnostics));
    std::vector<RfxEffectSummary> effects;
    for (const RfxEffectEntry& e : catalogue.effects)
        effects.push_back({e.path, rfxApiName(e.api), e.active, e.element->GetLineNum()});
    return Listed(std::move(effects), std::move(diagnostics));
}

}  // namespace rmfx
