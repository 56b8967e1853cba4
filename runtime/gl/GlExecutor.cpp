#include "gl/GlExecutor.h"

#include <algorithm>
#include <map>
#include <optional>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "gl/FixedFunctionState.h"
#include "gl/GlErrors.h"
#include "gl/GlExecutorImpl.h"
#include "gl/GlLimits.h"
#include "gl/GlRenderState.h"
#include "gl/GlUniformUpload.h"

namespace rmfx {
namespace {

void append(Diagnostics& to, const Diagnostics& from) { to.insert(to.end(), from.begin(), from.end()); }

Diagnostic workspaceError(const Workspace& ws, const std::string& element, const std::string& message) {
    return {Diagnostic::Severity::Error, {ws.path.string(), 0}, element, message};
}

}  // namespace

// create() and createReusing(): everything but where the textures come from.
struct GlExecutor::Build {
    static Result<std::unique_ptr<GlExecutor>> run(std::shared_ptr<const CompiledFrame> frame, const GlRunSettings& settings,
                                                   const TextureReuse& reuse) {
        using Failure = Result<std::unique_ptr<GlExecutor>>;
        const Workspace& ws = frame->ws();
        const FramePlanOptions& options = frame->plan.options;
        drainGlErrors();
        auto impl = std::make_unique<Impl>(std::move(frame));
        impl->maxTargetSize = queryMaxTargetSize();
        // A frame compiled for larger targets than this context makes is planned again against its limit.
        if (impl->compiled->maxTargetSize > impl->maxTargetSize) {
            const glm::ivec2 viewport = impl->compiled->viewport;
            if (Result<void> fits = checkViewportLimits(viewport, {impl->maxTargetSize, options.memoryBudget}, {ws.path.string(), 0});
                !fits)
                return Failure::failure(std::move(fits).diagnostics());
            auto replanned = planFrameTargets(ws, impl->plan, viewport, impl->values, impl->maxTargetSize);
            if (!replanned) return Failure::failure(replanned.takeDiagnostics());
            impl->plan.targets = std::move(*replanned);
        }
        impl->compatibility = ws.profile == GlProfile::Compatibility;
        if (impl->compatibility) {
            GLint mask = 0;
            glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
            if (!(mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT))
                return Failure::failure({workspaceError(ws, "<workspace>",
                                                        "the workspace asks for a compatibility-profile context (legacy GLSL, "
                                                        "fixed-function matrices), but the current context is a core profile one")});
        }
        Diagnostics d;
        auto allocated = impl->targets.allocate(impl->plan.targets);
        append(d, allocated.diagnostics());
        append(d, impl->textures.load(ws, impl->plan.sampledTextures(ws), reuse).diagnostics());
        if (options.checkHealth) {  // before the passes: their programs may count for it
            auto check = GlHealthCheck::create(settings.healthCheckMethod);
            if (!check) return Failure::failure({workspaceError(ws, "", check.error())});
            impl->healthCheck = std::move(*check);
        }
        for (const auto& [index, source] : impl->compiled->programs)
            if (auto gp = impl->buildPass(index, source, allocated.ok(), d)) impl->passes.push_back(std::move(gp));
        if (hasErrors(d)) return Failure::failure(std::move(d));
        if (!impl->plan.contentSkip.empty()) {
            auto skip = GlContentSkip::create();
            if (!skip) return Failure::failure({workspaceError(ws, "", skip.error())});
            impl->contentSkip = std::move(*skip);
            impl->contentSkip->setDecision(settings.contentSkipDecision);
        }
        if (impl->healthCheck) {
            Impl& s = *impl;
            impl->healthObserver = std::make_unique<GlHealthObserver>(
                *impl->healthCheck, impl->contentSkip.get(), [&s](const SamplerSlot& slot) { return s.healthInputLabel(slot); },
                [&s](const GpuPass& gp) { return s.current.graph->nodes[static_cast<size_t>(gp.index)].loadsTarget; });
            impl->observers.push_back(impl->healthObserver.get());
        }
        if (impl->contentSkip) impl->observers.push_back(impl->contentSkip.get());
        impl->chooseVariant();
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        const glm::ivec2 viewport = impl->compiled->viewport;
        std::unique_ptr<GlExecutor> executor(new GlExecutor(std::move(impl)));
        executor->camera_ = OrbitCamera(ws.camera);
        executor->viewport_ = viewport;
        return {std::move(executor), std::move(d)};
    }
};

GlExecutor::GlExecutor(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlExecutor::~GlExecutor() = default;

Result<std::unique_ptr<GlExecutor>> GlExecutor::create(std::shared_ptr<const CompiledFrame> frame, const GlRunSettings& settings) {
    return Build::run(std::move(frame), settings, {});
}

Result<std::unique_ptr<GlExecutor>> GlExecutor::createReusing(std::shared_ptr<const CompiledFrame> frame, const GlRunSettings& settings,
                                                              const GlExecutor& previous,
                                                              const std::vector<std::string>& reusableTextures) {
    const Impl& old = *previous.impl_;
    return Build::run(std::move(frame), settings, {&old.ws, &old.textures, reusableTextures});
}

Result<std::unique_ptr<GlExecutor>> GlExecutor::create(std::shared_ptr<const Workspace> ws, glm::ivec2 viewport,
                                                       const ExecutorOptions& options) {
    auto frame = compileFrame(std::move(ws), options, viewport, queryMaxTargetSize());
    if (!frame) return Result<std::unique_ptr<GlExecutor>>::failure(frame.takeDiagnostics());
    return create(std::move(*frame), static_cast<const GlRunSettings&>(options));
}

Result<std::unique_ptr<GlExecutor>> GlExecutor::createReusing(std::shared_ptr<const Workspace> ws, glm::ivec2 viewport,
                                                              const ExecutorOptions& options, const GlExecutor& previous,
                                                              const std::vector<std::string>& reusableTextures) {
    auto frame = compileFrame(std::move(ws), options, viewport, queryMaxTargetSize());
    if (!frame) return Result<std::unique_ptr<GlExecutor>>::failure(frame.takeDiagnostics());
    return createReusing(std::move(*frame), static_cast<const GlRunSettings&>(options), previous, reusableTextures);
}

Result<void> GlExecutor::renderFrame(const FrameClock& clock) {
    Diagnostics d;
    Impl& s = *impl_;
    drainGlErrors();
    s.prepareVariant();
    s.renderState.forget();  // whatever drew since the last frame (the editor) left its own
    s.targets.startFrame();
    s.timers.beginFrame(s.schedule.size());
    s.lastFramePasses.clear();
    for (PassObserver* o : s.observers) o->beginFrame(frame_, s.schedule.size());
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
        const ObservedPass observed{position, &gp, memory.textures[memory.writeBuffer()].get()};
        // False from an observer: nothing of the pass is issued this frame (content skip knows it draws nothing).
        bool issued = true;
        for (PassObserver* o : s.observers) issued = o->beforePass(observed) && issued;
        if (issued) {
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
            glViewport(0, 0, memory.spec.size.x, memory.spec.size.y);
            // Observers draw between passes with states of their own.
            if (!s.observers.empty()) s.renderState.forget();
            s.renderState.apply(pass, s.compatibility, rowsTopFirst(s.ws.textureSpace));
            if (pass.clear.color) glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, glm::value_ptr(*pass.clear.color));
            if (pass.clear.depth) {
                s.renderState.depthMask(true);
                glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &*pass.clear.depth);
                s.renderState.depthMask(pass.depth.write);
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
                for (PassObserver* o : s.observers) o->beginDraw(observed, program);
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
                    for (PassObserver* o : s.observers) o->samplerBound(slot, texture);
                }
                for (PassObserver* o : s.observers) o->beforeDraw(observed, program);
                program.mesh->draw(program.streams);
            };
            // A consumer content skip planned a second program for draws it twice, each under the
            // guard of the skip's probe (the plan gives second programs only with content skip on).
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
            s.renderState.restoreFilledPolygons(pass, s.compatibility);  // what draws next (the checks, the editor) fills
        }
        target.writtenThisFrame = true;
        s.lastFramePasses.push_back(pass.name);
        for (PassObserver* o : s.observers) o->afterDraws(observed);
        if (issued && memory.spec.mipmaps) glGenerateTextureMipmap(memory.textures[memory.writeBuffer()].get());
        for (PassObserver* o : s.observers) o->afterPass(observed, issued);
        s.timers.passDone(pass.name);
        for (const std::string& e : drainGlErrors())
            d.push_back({Diagnostic::Severity::Error, pass.where, passLabel(pass), e + " while drawing into '" + target.name + "'"});
    }
    for (PassObserver* o : s.observers) o->endFrame();
    if (s.healthCheck) s.takeHealth(false);
    s.targets.finishFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++frame_;
    return d;
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
    // A new format or size changes which targets can share memory: the plan and its memory start
    // over (every target back to its initial value), planned and allocated before anything is
    // replaced. Effect switches take effect at the next frame.
    if (reallocate) {
        std::map<std::string, Value> next = s.values;
        next[name] = value;
        auto planned = planFrameTargets(s.ws, s.plan, viewport_, next, s.maxTargetSize);
        if (!planned) return Error{planned.diagnostics().empty() ? "cannot plan the targets" : planned.diagnostics().front().message};
        if (auto allocated = s.targets.allocate(*planned); !allocated)
            return Error{allocated.diagnostics().empty() ? "cannot allocate the targets" : allocated.diagnostics().front().message};
        s.plan.targets = std::move(*planned);
    }
    it->second = value;
    s.chooseVariant();
    return {};
}

void GlExecutor::setMouse(glm::vec2 pixels, glm::ivec3 buttons) {
    impl_->mouse = glm::dvec2(pixels);
    impl_->mouseButtons = buttons;
}

}  // namespace rmfx
