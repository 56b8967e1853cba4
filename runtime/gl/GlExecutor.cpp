#include "gl/GlExecutor.h"

#include <algorithm>
#include <map>
#include <optional>

#include <epoxy/gl.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "frontend/shader/PassProgram.h"
#include "gl/FixedFunctionState.h"
#include "gl/GlContentSkip.h"
#include "gl/GlErrors.h"
#include "gl/GlFormats.h"
#include "gl/GlHealthCheck.h"
#include "gl/GlLimits.h"
#include "gl/GlMeshCache.h"
#include "gl/GlPassBindings.h"
#include "gl/GlPassTimers.h"
#include "gl/GlProgramBuild.h"
#include "gl/GlRenderState.h"
#include "gl/GlRenderTargets.h"
#include "gl/GlTextureCache.h"
#include "gl/GpuPass.h"

namespace rmfx {
namespace {

glm::mat4 modelMatrix(const DrawCall& draw) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), draw.translate);
    m = glm::rotate(m, glm::radians(draw.rotateDegrees.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(draw.rotateDegrees.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(draw.rotateDegrees.x), glm::vec3(1, 0, 0));
    return glm::scale(m, draw.scale);
}

void append(Diagnostics& to, const Diagnostics& from) { to.insert(to.end(), from.begin(), from.end()); }

Diagnostic workspaceError(const Workspace& ws, const std::string& element, const std::string& message) {
    return {Diagnostic::Severity::Error, {ws.path.string(), 0}, element, message};
}

int lastWriter(const Workspace& ws, const std::string& target) {
    for (int i = static_cast<int>(ws.passes.size()) - 1; i >= 0; --i)
        if (ws.passes[static_cast<size_t>(i)].enabled && ws.passTargetName(ws.passes[static_cast<size_t>(i)]) == target) return i;
    return -1;
}

}  // namespace

struct GlExecutor::Impl {
    std::shared_ptr<const Workspace> workspace;
    const Workspace& ws;
    FramePlan plan;
    int maxTargetSize = 0;  // the context's: no target side beyond it
    std::map<std::string, Value> values;  // uniform slots point into it: nodes never move
    bool compatibility = false;  // the workspace's profile, checked against the context in create()
    GlRenderTargets targets;
    GlTextureCache textures;
    GlMeshCache meshes;
    std::vector<std::unique_ptr<GpuPass>> passes;  // compiled: every pass some combination of switches runs

    FrameVariant current;           // of the current switches
    bool variablesChanged = true;   // since selectVariant last read the switches
    std::vector<GpuPass*> schedule; // the passes the current graph runs
    std::vector<std::string> lastFramePasses;
    GlPassTimers timers;
    std::unique_ptr<GlContentSkip> contentSkip;  // null without an effect with a source, or when off
    // Content skip's consumers compiled without the effects they read (ContentSkipPlan::Consumer),
    // by pass index with the effects left out; and for each schedule position, the one it draws.
    std::map<int, std::pair<std::set<std::string>, std::unique_ptr<GpuPass>>> withoutEffects;
    std::vector<const GpuPass*> withoutEffectsAt;
    std::unique_ptr<GlHealthCheck> healthCheck;  // with FramePlanOptions::checkHealth
    std::optional<FrameHealth> lastHealth;
    std::vector<HealthFinding> firstFindings;  // of each kind, since the first frame

    // The health of the frames whose results are in (all that ended, when `wait`), in order.
    void takeHealth(bool wait) {
        if (!healthCheck) return;
        for (FrameHealth& frame : healthCheck->finishedFrames(wait)) {
            for (const HealthFinding& f : frame.findings)
                if (std::none_of(firstFindings.begin(), firstFindings.end(), [&](const HealthFinding& k) { return k.kind == f.kind; }))
                    firstFindings.push_back(f);
            lastHealth = std::move(frame);
        }
        std::sort(firstFindings.begin(), firstFindings.end(),
                  [](const HealthFinding& a, const HealthFinding& b) { return a.kind < b.kind; });
    }
    glm::dvec2 mouse{0.0};
    glm::ivec3 mouseButtons{0};

    explicit Impl(std::shared_ptr<const Workspace> w) : workspace(std::move(w)), ws(*workspace) {}

    GpuPass* compiledPass(int index) const {
        for (auto& p : passes)
            if (p->index == index) return p.get();
        return nullptr;
    }

    // Points every sampler of the texture at its GL object (after it was loaded anew).
    void bindTexture(const std::string& name) {
        const unsigned object = textures.object(name);
        for (auto& p : passes)
            for (SamplerSlot& slot : p->samplers)
                if (!slot.target && slot.sampler->texture == name) slot.texture = object;
    }

    GpuPass* findPass(const std::string& name) const {
        for (auto& p : passes)
            if (p->pass->name == name) return p.get();
        return nullptr;
    }

    // Follows the effect switches: the schedule of the graph of the current combination.
    void selectVariant() {
        if (current.graph && !variablesChanged) return;
        variablesChanged = false;
        std::set<std::string> off = rmfx::switchedOffEffects(ws, plan.askedEffects, values);
        if (current.graph && off == current.switchedOff) return;
        current = plan.variant(off);
        schedule.clear();
        for (int index : current.graph->schedule)
            if (GpuPass* p = compiledPass(index)) schedule.push_back(p);
        if (contentSkip) contentSkip->usePlan(*current.contentSkip, targets);
        planSkippedDraws();
    }

    // How content skip draws the schedule: whether one condition may span an effect's passes, and
    // which passes it draws a second way (ContentSkipPlan::Consumer).
    void planSkippedDraws() {
        withoutEffectsAt.assign(schedule.size(), nullptr);
        if (!contentSkip) return;
        // The check's own draws after a pass must not fall under an effect's condition; passes
        // that count what they write are skipped together with what they count.
        contentSkip->setSpanning(!healthCheck || std::all_of(schedule.begin(), schedule.end(),
                                                             [](const GpuPass* p) { return p->health.found; }));
        std::map<size_t, std::set<const GpuTarget*>> sampled;
        if (!healthCheck)  // the check looks at every pass as compiled
            for (const ContentSkipPlan::Consumer& c : current.contentSkip->consumers)
                if (const GpuPass* without = passWithout(*schedule[c.position], c.effects)) {
                    withoutEffectsAt[c.position] = without;
                    std::set<const GpuTarget*>& read = sampled[c.position];
                    for (const SamplerSlot& slot : without->samplers)
                        if (slot.target) read.insert(slot.target);
                }
        contentSkip->setSampledWithoutEffects(sampled);
    }

    // The pass compiled with `effects` left out, when that changes its code; null otherwise, or
    // when it does not build (it is then drawn as compiled, reading the cleared targets).
    const GpuPass* passWithout(const GpuPass& gp, const std::set<std::string>& effects) {
        auto& [builtWithout, built] = withoutEffects[gp.index];
        if (builtWithout == effects) return built.get();  // null: tried, and it reads none of them
        builtWithout = effects;
        built.reset();
        std::set<std::string> asked;
        for (const std::string& e : plan.askedEffects)
            if (!effects.count(e)) asked.insert(e);
        auto program = buildPassProgram(ws, *gp.pass, effectPrelude(ws, asked));
        if (!program) return nullptr;
        // The prelude defines every macro once; a shader that reads none of them is the same.
        bool reads = false;
        for (const std::string& e : effects) {
            const std::string macro = effectMacro(e);
            const size_t first = program->fragmentCode.find(macro);
            reads = reads || (first != std::string::npos && program->fragmentCode.find(macro, first + 1) != std::string::npos);
        }
        if (!reads) return nullptr;
        built = withProgram(gp, std::move(program->program), std::move(program->initializedUniforms));
        return built.get();
    }

    // Plans the targets for the current values and allocates them; errors leave the old ones.
    Result<void> allocateTargets(glm::ivec2 viewport) {
        auto planned = planFrameTargets(ws, plan, viewport, values, maxTargetSize);
        if (!planned) return Result<void>::failure(planned.takeDiagnostics());
        plan.targets = std::move(*planned);
        return targets.allocate(plan.targets);
    }

    // A pass ready to draw, or null with the diagnostics saying why.
    std::unique_ptr<GpuPass> buildPass(int index, bool targetsAllocated, Diagnostics& d) {
        const Pass& pass = ws.passes[static_cast<size_t>(index)];
        auto gp = std::make_unique<GpuPass>();
        gp->pass = &pass;
        gp->index = index;
        gp->target = targets.find(ws.passTargetName(pass));
        auto mesh = meshes.meshFor(ws, pass.draw);
        append(d, mesh.diagnostics());
        gp->model = modelMatrix(pass.draw);
        auto program = buildPassProgram(ws, pass, plan.prelude);
        append(d, program.diagnostics());
        // Without memory (the targets failed to allocate: already reported) or not declared at all.
        bool targetMissing = !gp->target || !gp->target->resource;
        if (targetsAllocated && targetMissing)
            d.push_back({Diagnostic::Severity::Error, pass.where, passLabel(pass),
                         "target '" + ws.passTargetName(pass) + "' is not declared"});
        if (!program || !mesh || targetMissing) return nullptr;
        gp->mesh = *mesh;
        if (!useProgram(*gp, std::move(*program), d)) return nullptr;
        return gp;
    }

    // Gives the pass its program, with --check made to count what the pass writes where it can.
    bool useProgram(GpuPass& gp, PassGlProgram built, Diagnostics& d) {
        gp.program = std::move(built.program);
        gp.initializedUniforms = built.initializedUniforms;
        if (!bindProgram(gp, d)) return false;
        if (healthCheck) {
            std::vector<std::string> inputs;  // the samplers its counting version would record
            for (const SamplerSlot& slot : gp.samplers)
                if (healthInputLabel(slot)) inputs.push_back(slot.sampler->uniform);
            if (healthCheck->countsWhileDrawing(sharesItsTargetWithANeighbour(gp), static_cast<int>(inputs.size())))
                countOwnWrites(gp, built, std::move(inputs));
        }
        return true;
    }

    // Whether the pass before or after `gp`, of those that may run, writes the target `gp` writes
    // (a scene drawn model by model; culling by the effect switches aside).
    bool sharesItsTargetWithANeighbour(const GpuPass& gp) const {
        const std::set<int> runnable = plan.runnablePasses();
        auto it = runnable.find(gp.index);
        if (it == runnable.end()) return false;
        const std::string target = ws.passTargetName(*gp.pass);
        auto writesIt = [&](int index) { return ws.passTargetName(ws.passes[static_cast<size_t>(index)]) == target; };
        return (it != runnable.begin() && writesIt(*std::prev(it))) || (std::next(it) != runnable.end() && writesIt(*std::next(it)));
    }

    // The pass's program made to count what it writes, recording the samplers `inputs`
    // (gl/HealthInstrumentation.h); where it cannot, it stays as built and the check inspects its
    // target after it ran.
    void countOwnWrites(GpuPass& gp, const PassGlProgram& built, std::vector<std::string> inputs) {
        auto code = instrumentForHealth(*gp.pass, built.fragmentCode, gp.program.get(), inputs, healthCheck->bufferBinding());
        if (!code) {
            gp.whyNotCounting = code.error();
            return;
        }
        auto relinked = relinkWithFragment(built, *code);
        if (!relinked) {
            const std::string log = relinked.error();
            gp.whyNotCounting = "its counting version does not compile here: " + log.substr(0, log.find('\n'));
            return;
        }
        std::unique_ptr<GpuPass> counting = withProgram(gp, std::move(*relinked), gp.initializedUniforms);
        if (counting) counting->health = findHealthUniforms(counting->program.get());
        if (!counting || !counting->health.found) {
            gp.whyNotCounting = "its counting version does not bind";
            return;
        }
        counting->healthInputs = std::move(inputs);
        gp = std::move(*counting);
    }

    // What `gp` draws, with another program, bound; null when binding fails (what binding the
    // pass's own program said is not said again).
    std::unique_ptr<GpuPass> withProgram(const GpuPass& gp, ProgramHandle program, std::set<std::string> initialized) {
        auto other = std::make_unique<GpuPass>();
        other->pass = gp.pass;
        other->index = gp.index;
        other->target = gp.target;
        other->mesh = gp.mesh;
        other->model = gp.model;
        other->program = std::move(program);
        other->initializedUniforms = std::move(initialized);
        Diagnostics again;
        if (!bindProgram(*other, again) || hasErrors(again)) return nullptr;
        return other;
    }

    // What the health check calls a 2D input of a pass (targets and 2D textures); none for others.
    std::optional<std::string> healthInputLabel(const SamplerSlot& slot) const {
        if (slot.target) return slot.sampler->uniform + " → target '" + slot.target->name + "'";
        const Texture* file = ws.findTexture(slot.sampler->texture);
        if (file && file->kind == TextureKind::Texture2D) return slot.sampler->uniform + " → texture '" + file->name + "'";
        return std::nullopt;
    }

    bool bindProgram(GpuPass& gp, Diagnostics& d) {
        append(d, bindStreams(gp, compatibility).diagnostics());
        auto bound = bindUniforms(gp, {ws, plan, textures, targets, values});
        append(d, bound.diagnostics());
        return bound.ok();
    }
};

// create() and createReusing(): everything but where the textures come from.
struct GlExecutor::Build {
    static Result<std::unique_ptr<GlExecutor>> run(std::shared_ptr<const Workspace> workspace, glm::ivec2 viewport,
                                                   const FramePlanOptions& options, const TextureReuse& reuse) {
        using Failure = Result<std::unique_ptr<GlExecutor>>;
        const Workspace& ws = *workspace;
        if (viewport.x < 1 || viewport.y < 1)
            return Failure::failure({workspaceError(ws, "", "viewport size " + std::to_string(viewport.x) + "x" +
                                                                std::to_string(viewport.y) + " is empty")});
        drainGlErrors();
        auto impl = std::make_unique<Impl>(std::move(workspace));
        impl->maxTargetSize = queryMaxTargetSize();
        if (Result<void> fits = checkViewportLimits(viewport, {impl->maxTargetSize, options.memoryBudget}, {ws.path.string(), 0});
            !fits)
            return Failure::failure(std::move(fits).diagnostics());
        impl->compatibility = ws.profile == GlProfile::Compatibility;
        if (impl->compatibility) {
            GLint mask = 0;
            glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
            if (!(mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT))
                return Failure::failure({workspaceError(ws, "<workspace>",
                                                        "the workspace asks for a compatibility-profile context (legacy GLSL, "
                                                        "fixed-function matrices), but the current context is a core profile one")});
        }
        impl->values = declaredValues(ws);
        auto planned = planFramePasses(ws, options);
        if (!planned) return Failure::failure(planned.takeDiagnostics());
        impl->plan = std::move(*planned);
        Diagnostics d;
        auto allocated = impl->allocateTargets(viewport);
        append(d, allocated.diagnostics());
        append(d, impl->textures.load(ws, impl->plan.sampledTextures(ws), reuse).diagnostics());
        if (options.checkHealth) {  // before the passes: their programs may count for it
            auto check = GlHealthCheck::create(options.healthCheckMethod);
            if (!check) return Failure::failure({workspaceError(ws, "", check.error())});
            impl->healthCheck = std::move(*check);
        }
        for (int index : impl->plan.runnablePasses())
            if (auto gp = impl->buildPass(index, allocated.ok(), d)) impl->passes.push_back(std::move(gp));
        if (hasErrors(d)) return Failure::failure(std::move(d));
        if (!impl->plan.contentSkip.empty()) {
            auto skip = GlContentSkip::create();
            if (!skip) return Failure::failure({workspaceError(ws, "", skip.error())});
            impl->contentSkip = std::move(*skip);
            impl->contentSkip->setDecision(options.contentSkipDecision);
        }
        impl->selectVariant();
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        std::unique_ptr<GlExecutor> executor(new GlExecutor(std::move(impl)));
        executor->camera_ = OrbitCamera(ws.camera);
        executor->viewport_ = viewport;
        return {std::move(executor), std::move(d)};
    }
};

GlExecutor::GlExecutor(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlExecutor::~GlExecutor() = default;

Result<std::unique_ptr<GlExecutor>> GlExecutor::create(std::shared_ptr<const Workspace> ws, glm::ivec2 viewport,
                                                       const FramePlanOptions& options) {
    return Build::run(std::move(ws), viewport, options, {});
}

Result<std::unique_ptr<GlExecutor>> GlExecutor::createReusing(std::shared_ptr<const Workspace> ws, glm::ivec2 viewport,
                                                              const FramePlanOptions& options, const GlExecutor& previous,
                                                              const std::vector<std::string>& reusableTextures) {
    const Impl& old = *previous.impl_;
    return Build::run(std::move(ws), viewport, options, {&old.ws, &old.textures, reusableTextures});
}

Result<void> GlExecutor::renderFrame(const FrameClock& clock) {
    Diagnostics d;
    Impl& s = *impl_;
    drainGlErrors();
    s.selectVariant();
    s.targets.startFrame();
    s.timers.beginFrame(s.schedule.size());
    s.lastFramePasses.clear();
    if (s.contentSkip) s.contentSkip->beginFrame();
    if (s.healthCheck) s.healthCheck->beginFrame(frame_, s.schedule.size());
    std::vector<GlHealthCheck::Input> healthInputs;
    const FrameCamera camera(camera_, viewport_);
    const FrameInputs inputs{clock, frame_, &camera, viewport_, s.mouse, s.mouseButtons, &s.current.switchedOff};
    // The named cameras passes look through (RmCameraReference): fixed, built once a frame.
    std::map<std::string, FrameCamera> namedCameras;
    for (const NamedCamera& c : s.ws.cameras) namedCameras.emplace(c.name, FrameCamera(OrbitCamera(c.settings), viewport_));
    for (size_t position = 0; position < s.schedule.size(); ++position) {
        const GpuPass& gp = *s.schedule[position];
        const Pass& pass = *gp.pass;
        GpuTarget& target = *gp.target;
        GpuResource& memory = *target.resource;
        GLuint framebuffer = memory.framebuffers[memory.writeBuffer()].get();
        // Before the pass's condition: the inspections it flushes are of earlier passes.
        if (s.healthCheck) s.healthCheck->beforeWriting(memory.textures[memory.writeBuffer()].get());
        // False: content skip knows already that nothing of the pass is drawn this frame.
        const bool issued = !s.contentSkip || s.contentSkip->beforePass(position);
        healthInputs.clear();
        if (issued) {
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
            glViewport(0, 0, memory.spec.size.x, memory.spec.size.y);
            applyRenderState(pass, s.compatibility, rowsTopFirst(s.ws.textureSpace));
            if (pass.clear.color) glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, glm::value_ptr(*pass.clear.color));
            if (pass.clear.depth) {
                glDepthMask(GL_TRUE);
                glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &*pass.clear.depth);
                glDepthMask(pass.depth.write ? GL_TRUE : GL_FALSE);
            }
            const auto named = pass.camera.empty() ? namedCameras.end() : namedCameras.find(pass.camera);
            const FrameCamera& passCamera = named == namedCameras.end() ? camera : named->second;
            FrameInputs passInputs = inputs;
            passInputs.camera = &passCamera;
            // The pass's draw with `program`: the pass as compiled, or content skip's version of it
            // without the effects it reads.
            auto drawWith = [&](const GpuPass& program) {
                glUseProgram(program.program.get());
                uploadUniforms(program, passInputs);
                if (s.compatibility) loadFixedFunctionState(passCamera.projection, passCamera.view * program.model);
                healthInputs.clear();
                for (const SamplerSlot& slot : program.samplers) {
                    GLuint texture = slot.texture;
                    if (slot.target) {
                        // frame="previous": what the last frame left. The current frame: the buffer a pass
                        // wrote this frame, or, before any pass has, still what the last frame left (the
                        // write buffer of a double-buffered target then holds the frame before that).
                        const GpuTarget& t = *slot.target;
                        const GpuResource& r = *t.resource;
                        bool current = !slot.sampler->previousFrame && t.writtenThisFrame;
                        texture = r.textures[current ? r.writeBuffer() : r.front].get();
                    }
                    glBindTextureUnit(static_cast<GLuint>(slot.unit), texture);
                    glBindSampler(static_cast<GLuint>(slot.unit), slot.samplerObject.get());
                    if (s.healthCheck)
                        if (std::optional<std::string> label = s.healthInputLabel(slot))
                            healthInputs.push_back({slot.sampler->uniform, std::move(*label), texture, slot.unit});
                }
                if (s.healthCheck && program.health.found) {
                    // In the order its shader records them.
                    std::vector<GlHealthCheck::Input> recorded;
                    for (const std::string& sampler : program.healthInputs)
                        for (const GlHealthCheck::Input& input : healthInputs)
                            if (input.sampler == sampler) recorded.push_back(input);
                    s.healthCheck->beforeCountingPass(position, pass.name, target.name, memory.spec.size, memory.spec.format, recorded,
                                                      program.health, s.current.graph->nodes[static_cast<size_t>(gp.index)].loadsTarget);
                }
                program.mesh->draw(program.streams);
            };
            const GpuPass* without = position < s.withoutEffectsAt.size() ? s.withoutEffectsAt[position] : nullptr;
            if (without) {
                for (bool leftOut : {false, true})
                    if (s.contentSkip->beginConsumerDraw(position, leftOut)) {
                        drawWith(leftOut ? *without : gp);
                        s.contentSkip->endConsumerDraw();
                    }
            } else {
                drawWith(gp);
            }
            restoreFilledPolygons(pass, s.compatibility);  // what draws next (the checks, the editor) fills
        }
        target.writtenThisFrame = true;
        s.lastFramePasses.push_back(pass.name);
        if (s.contentSkip) s.contentSkip->afterPass(position);
        if (issued && memory.spec.mipmaps) glGenerateTextureMipmap(memory.textures[memory.writeBuffer()].get());
        // A pass left out on the CPU is reported clean: its inspection is drawn under the failed condition.
        if (s.healthCheck && (!issued || !gp.health.found))
            s.healthCheck->afterPass(position, pass.name, target.name, memory.textures[memory.writeBuffer()].get(),
                                     memory.spec.size, memory.spec.format, healthInputs, gp.whyNotCounting,
                                     s.contentSkip ? s.contentSkip->conditionOf(position) : 0);
        s.timers.passDone(pass.name);
        for (const std::string& e : drainGlErrors())
            d.push_back({Diagnostic::Severity::Error, pass.where, passLabel(pass), e + " while drawing into '" + target.name + "'"});
    }
    if (s.contentSkip) s.contentSkip->endFrame();
    if (s.healthCheck) {
        s.healthCheck->endFrame();
        s.takeHealth(false);
    }
    s.targets.finishFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++frame_;
    return d;
}

const Value* GlExecutor::variable(const std::string& name) const {
    auto it = impl_->values.find(name);
    return it == impl_->values.end() ? nullptr : &it->second;
}

Result<void> GlExecutor::setVariable(const std::string& name, const Value& value) {
    Impl& s = *impl_;
    auto it = s.values.find(name);
    if (it == s.values.end()) return Error{"no variable named '" + name + "'"};
    if (it->second.type != value.type)
        return Error{"variable '" + name + "' is a " + valueTypeName(it->second.type) + " (" +
                     std::to_string(componentCount(it->second.type)) + " values), not a " + valueTypeName(value.type)};
    bool reallocate = false;
    for (const RenderTarget& t : s.ws.targets) {
        if (t.formatVariable == name) {
            if (!selectTargetFormat(t, &value)) return Error{formatChoiceError(t, &value)};
            reallocate = reallocate || *selectTargetFormat(t, &value) != *selectTargetFormat(t, &it->second);
        }
        if (t.scaleVariable == name) {
            if (!selectTargetSize(t, &value)) return Error{scaleChoiceError(t, &value)};
            reallocate = reallocate || value.asInt() != it->second.asInt();
        }
    }
    it->second = value;
    s.variablesChanged = true;
    // A new format or size changes which targets can share memory: the plan and its memory start
    // over (every target back to its initial value). Effect switches take effect at the next frame.
    if (reallocate)
        if (auto allocated = s.allocateTargets(viewport_); !allocated)
            return Error{allocated.diagnostics().empty() ? "cannot allocate the targets" : allocated.diagnostics().front().message};
    return {};
}

void GlExecutor::setTimingEnabled(bool enabled) { impl_->timers.setEnabled(enabled); }
const std::vector<PassTiming>& GlExecutor::passTimings() const { return impl_->timers.timings(); }
double GlExecutor::frameGpuMilliseconds() const { return impl_->timers.frameMilliseconds(); }

void GlExecutor::setMouse(glm::vec2 pixels, glm::ivec3 buttons) {
    impl_->mouse = glm::dvec2(pixels);
    impl_->mouseButtons = buttons;
}

Result<Image> GlExecutor::readTarget(const std::string& name) const {
    const Impl& s = *impl_;
    const GpuTarget* t = s.targets.find(name);
    if (!t) return Error{"no render target named '" + name + "'"};
    const TargetPlan& plan = s.plan.targets;
    const PlannedTarget& planned = plan.targets[static_cast<size_t>(plan.find(name))];
    if (!t->resource) {
        std::string why = "target '" + name + "' is not computed: no pass the outputs need writes or reads it";
        if (int writer = lastWriter(s.ws, name); writer >= 0) {
            const PassNode& node = s.current.graph->nodes[static_cast<size_t>(writer)];
            why += " (its writer '" + s.ws.passes[static_cast<size_t>(writer)].name + "' is " + passFateName(node.fate) +
                   ": " + node.why + ")";
        }
        return Error{why + "; ask for it as an output (rmfx render --target " + name + ")"};
    }
    const GpuResource& r = *t->resource;
    if (static_cast<size_t>(r.spec.targets.back()) != static_cast<size_t>(plan.find(name)))
        return Error{"target '" + name + "' shares memory with '" + plan.targets[static_cast<size_t>(r.spec.targets.back())].name +
                     "', which overwrites it later in the frame; ask for it as an output (rmfx render --target " + name +
                     ") to keep it"};
    Image image;
    image.width = planned.size.x;
    image.height = planned.size.y;
    image.channels = gl::channelCount(planned.format) == 1 ? 1 : 4;
    image.highDynamicRange = true;
    std::vector<float> rgba(static_cast<size_t>(image.width) * image.height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(r.textures[r.front].get(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)),
                      rgba.data());  // the newest finished contents
    if (std::string e = firstGlError(); !e.empty()) return Error{e + " reading target '" + name + "'"};
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
    // GL's row 0 is the picture's bottom row, or its top row in a Direct3D texture space.
    const bool topFirst = rowsTopFirst(s.ws.textureSpace);
    for (int y = 0; y < image.height; ++y) {
        const float* src = &rgba[static_cast<size_t>(topFirst ? y : image.height - 1 - y) * image.width * 4];
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < image.channels; ++c) image.at(x, y, c) = src[x * 4 + c];
    }
    return image;
}

std::vector<std::string> GlExecutor::targetNames() const {
    std::vector<std::string> names;
    for (auto& t : impl_->targets.targets()) names.push_back(t->name);
    return names;
}

glm::ivec2 GlExecutor::targetSize(const std::string& name) const {
    const TargetPlan& plan = impl_->plan.targets;
    int i = plan.find(name);
    return i < 0 ? glm::ivec2(0) : plan.targets[static_cast<size_t>(i)].size;
}

TargetFormat GlExecutor::targetFormat(const std::string& name) const {
    const TargetPlan& plan = impl_->plan.targets;
    int i = plan.find(name);
    return i < 0 ? TargetFormat::RGBA8 : plan.targets[static_cast<size_t>(i)].format;
}

unsigned GlExecutor::targetTexture(const std::string& name) const {
    const GpuTarget* t = impl_->targets.find(name);
    return t && t->resource ? t->resource->textures[t->resource->front].get() : 0;
}

const Workspace& GlExecutor::workspace() const { return impl_->ws; }
const FramePlan& GlExecutor::framePlan() const { return impl_->plan; }
const PassGraph& GlExecutor::graph() const {
    impl_->selectVariant();
    return *impl_->current.graph;
}
const TargetPlan& GlExecutor::targetPlan() const { return impl_->plan.targets; }
const std::set<std::string>& GlExecutor::askedEffects() const { return impl_->plan.askedEffects; }
const std::set<std::string>& GlExecutor::switchedOffEffects() const {
    impl_->selectVariant();
    return impl_->current.switchedOff;
}
const std::vector<std::string>& GlExecutor::passesRun() const { return impl_->lastFramePasses; }

const FrameHealth* GlExecutor::frameHealth(bool wait) const {
    impl_->takeHealth(wait);
    return impl_->lastHealth ? &*impl_->lastHealth : nullptr;
}
const std::vector<HealthFinding>& GlExecutor::firstHealthFindings() const {
    impl_->takeHealth(true);
    return impl_->firstFindings;
}

std::map<std::string, std::set<std::string>> GlExecutor::passesDrawnWithoutSkippedEffects() const {
    const Impl& s = *impl_;
    std::map<std::string, std::set<std::string>> out;
    if (!s.contentSkip) return out;
    for (const ContentSkipPlan::Consumer& c : s.current.contentSkip->consumers)
        if (c.position < s.withoutEffectsAt.size() && s.withoutEffectsAt[c.position])
            out[s.schedule[c.position]->pass->name] = c.effects;
    return out;
}

std::map<std::string, std::set<std::string>> GlExecutor::passesDrawnOnlyForEffects() const {
    const Impl& s = *impl_;
    std::map<std::string, std::set<std::string>> out;
    if (!s.contentSkip) return out;
    for (const ContentSkipPlan::Feeder& f : s.current.contentSkip->feeders) out[s.schedule[f.position]->pass->name] = f.effects;
    return out;
}

std::map<std::string, std::string> GlExecutor::effectsRunningWhateverTheContent() const {
    return impl_->contentSkip ? impl_->current.contentSkip->runningAlways : std::map<std::string, std::string>{};
}

int GlExecutor::passesNotIssuedByContentSkip() const {
    return impl_->contentSkip ? impl_->contentSkip->passesNotIssued() : 0;
}

const std::map<std::string, std::string>& GlExecutor::contentSkippedEffects(bool wait) {
    static const std::map<std::string, std::string> none;
    return impl_->contentSkip ? impl_->contentSkip->skipped(wait) : none;
}

// Hot reload: each change is built completely before anything of the running build is touched.

Result<void> GlExecutor::recompilePasses(const std::vector<std::string>& passNames) {
    Diagnostics d;
    Impl& s = *impl_;
    drainGlErrors();
    std::vector<std::string> names;
    for (const std::string& name : passNames)
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    std::vector<std::pair<GpuPass*, std::unique_ptr<GpuPass>>> rebuilt;
    for (const std::string& name : names) {
        GpuPass* old = s.findPass(name);
        if (!old && s.ws.findPass(name)) continue;  // culled: nothing compiled to replace
        if (!old) {
            d.push_back(workspaceError(s.ws, "<pass name=\"" + name + "\">", "no enabled pass named '" + name + "' to recompile"));
            continue;
        }
        auto fresh = std::make_unique<GpuPass>();
        fresh->pass = old->pass;
        fresh->index = old->index;
        fresh->target = old->target;
        fresh->mesh = old->mesh;
        fresh->model = old->model;
        auto program = buildPassProgram(s.ws, *fresh->pass, s.plan.prelude);
        append(d, program.diagnostics());
        if (!program) continue;
        s.useProgram(*fresh, std::move(*program), d);
        rebuilt.emplace_back(old, std::move(fresh));
    }
    if (hasErrors(d)) return Result<void>::failure(std::move(d));  // the fresh programs go with `rebuilt`
    for (auto& [old, fresh] : rebuilt) {
        s.withoutEffects.erase(old->index);  // built from the old source
        *old = std::move(*fresh);
    }
    if (!rebuilt.empty()) s.planSkippedDraws();
    return d;
}

Result<void> GlExecutor::reloadTexture(const std::string& name) {
    Impl& s = *impl_;
    const Texture* spec = s.ws.findTexture(name);
    if (!spec) return Result<void>::failure({workspaceError(s.ws, "", "no texture named '" + name + "' to reload")});
    if (!s.textures.holds(name)) return {};  // no pass that can run samples it: nothing loaded
    if (auto reloaded = s.textures.reload(s.ws, *spec); !reloaded) return reloaded;
    s.bindTexture(name);
    return {};
}

Result<void> GlExecutor::replaceInputImage(const std::string& name, std::shared_ptr<const Image> image) {
    Impl& s = *impl_;
    const Texture* spec = s.ws.findTexture(name);
    if (!s.ws.findInput(name) || !spec)
        return Result<void>::failure({workspaceError(s.ws, "", "no input named '" + name + "' to give an image")});
    if (!s.plan.options.givenInputs.count(name))
        return Result<void>::failure({workspaceError(s.ws, "<input name=\"" + name + "\">",
                                                     "input '" + name + "' was given no image when the run began")});
    if (!image || image->empty())
        return Result<void>::failure({workspaceError(s.ws, "<input name=\"" + name + "\">", "an empty image for input '" + name + "'")});
    if (!s.textures.holds(name)) return {};  // no pass that can run samples it
    Texture next = *spec;
    next.supplied = std::move(image);
    if (auto replaced = s.textures.reload(s.ws, next); !replaced) return replaced;
    s.bindTexture(name);
    return {};
}

Result<void> GlExecutor::reloadModel(const std::string& file) {
    Impl& s = *impl_;
    const GlMesh* old = s.meshes.loadedModel(file);
    const Pass* user = nullptr;
    for (const auto& p : s.passes)
        if (!p->pass->draw.mesh && p->pass->draw.file == file) user = p->pass;
    if (!old || !user) return Result<void>::failure({workspaceError(s.ws, "<draw>", "no pass draws model file '" + file + "'")});
    auto fresh = GlMeshCache::loadAgain(s.ws, file, user->draw);
    if (!fresh) return Result<void>::failure(fresh.takeDiagnostics());
    for (auto& p : s.passes)
        if (p->mesh == old) p->mesh = fresh->get();
    s.meshes.replace(file, std::move(*fresh));
    return {};
}

unsigned GlExecutor::passProgram(const std::string& pass) const {
    const GpuPass* p = impl_->findPass(pass);
    return p ? p->program.get() : 0;
}

unsigned GlExecutor::textureObject(const std::string& name) const { return impl_->textures.object(name); }

}  // namespace rmfx
