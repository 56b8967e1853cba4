// The executor's passes made ready to draw: linked, bound, counted for the health check, and drawn
// a second way for content skip; and the switches' combination they are scheduled by.

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/GlExecutorImpl.h"
#include "gl/GlPassBindings.h"

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

}  // namespace

void GlExecutor::Impl::takeHealth(bool wait) {
    if (!healthCheck) return;
    for (FrameHealth& frame : healthCheck->finishedFrames(wait)) {
        for (const HealthFinding& f : frame.findings)
            if (std::none_of(firstFindings.begin(), firstFindings.end(), [&](const HealthFinding& k) { return k.kind == f.kind; }))
                firstFindings.push_back(f);
        lastHealth = std::move(frame);
    }
    std::sort(firstFindings.begin(), firstFindings.end(), [](const HealthFinding& a, const HealthFinding& b) { return a.kind < b.kind; });
}

GpuPass* GlExecutor::Impl::compiledPass(int index) const {
    for (auto& p : passes)
        if (p->index == index) return p.get();
    return nullptr;
}

GpuPass* GlExecutor::Impl::findPass(const std::string& name) const {
    for (auto& p : passes)
        if (p->pass->name == name) return p.get();
    return nullptr;
}

void GlExecutor::Impl::bindTexture(const std::string& name) {
    const unsigned object = textures.object(name);
    for (auto& p : passes)
        for (SamplerSlot& slot : p->samplers)
            if (!slot.target && slot.sampler->texture == name) slot.texture = object;
}

void GlExecutor::Impl::chooseVariant() {
    const std::set<std::string> off = rmfx::switchedOffEffects(ws, plan.askedEffects, values);
    if (current.graph && off == current.switchedOff) return;
    const FrameVariant chosen = plan.variant(off);
    if (current.graph && chosen.graph == current.graph) return;  // more switches than prepared: all on again
    current = chosen;
    schedule.clear();
    for (int index : current.graph->schedule)
        if (GpuPass* p = compiledPass(index)) schedule.push_back(p);
    variantReady = false;
}

void GlExecutor::Impl::prepareVariant() {
    if (variantReady) return;
    variantReady = true;
    if (contentSkip && current.contentSkip) contentSkip->usePlan(*current.contentSkip, targets);
    planSkippedDraws();
}

void GlExecutor::Impl::planSkippedDraws() {
    withoutEffectsAt.assign(schedule.size(), nullptr);
    if (!contentSkip || !current.contentSkip) return;
    // The check's own draws after a pass must not fall under an effect's condition; passes that
    // count what they write are skipped together with what they count.
    contentSkip->setSpanning(!healthCheck || std::all_of(schedule.begin(), schedule.end(),
                                                         [](const GpuPass* p) { return p->health.found; }));
    std::map<size_t, std::set<const GpuTarget*>> sampled;
    if (!healthCheck)  // the check looks at every pass as compiled
        for (const ContentSkipPlan::Consumer& c : current.contentSkip->consumers)
            if (const GpuPass* without = passWithout(c.position, *schedule[c.position], c.effects)) {
                withoutEffectsAt[c.position] = without;
                std::set<const GpuTarget*>& read = sampled[c.position];
                for (const SamplerSlot& slot : without->samplers)
                    if (slot.target) read.insert(slot.target);
            }
    contentSkip->setSampledWithoutEffects(sampled);
}

const GpuPass* GlExecutor::Impl::passWithout(size_t position, const GpuPass& gp, const std::set<std::string>& effects) {
    auto& [builtWithout, built] = withoutEffects[gp.index];
    if (builtWithout == effects) return built.get();  // null: tried, and it reads none of them
    builtWithout = effects;
    built.reset();
    std::optional<PassProgramSource> source;
    if (!readAnew.count(gp.index)) {
        if (const ProgramWithoutEffects* p = compiled->programWithout(current.switchedOff, position)) source = p->source;
    } else if (Result<PassProgramSource> asCompiled = assemblePassProgram(ws, *gp.pass, plan.prelude.defines, plan.prelude.declarations)) {
        source = programWithoutEffects(ws, *gp.pass, plan, *asCompiled, effects);
    }
    if (!source) return nullptr;
    auto program = linkPassProgram(*gp.pass, *source);
    if (!program) return nullptr;
    built = withProgram(gp, std::move(program->program), std::move(program->initializedUniforms));
    return built.get();
}

std::unique_ptr<GpuPass> GlExecutor::Impl::buildPass(int index, const Result<PassProgramSource>& source, bool targetsAllocated,
                                                     Diagnostics& d) {
    const Pass& pass = ws.passes[static_cast<size_t>(index)];
    auto gp = std::make_unique<GpuPass>();
    gp->pass = &pass;
    gp->index = index;
    gp->target = targets.find(ws.passTargetName(pass));
    auto mesh = meshes.meshFor(ws, pass.draw);
    append(d, mesh.diagnostics());
    gp->model = modelMatrix(pass.draw);
    append(d, source.diagnostics());
    std::optional<Result<PassGlProgram>> program;
    if (source) {
        program = linkPassProgram(pass, *source);
        append(d, program->diagnostics());
    }
    // Without memory (the targets failed to allocate: already reported) or not declared at all.
    bool targetMissing = !gp->target || !gp->target->resource;
    if (targetsAllocated && targetMissing)
        d.push_back({Diagnostic::Severity::Error, pass.where, passLabel(pass), "target '" + ws.passTargetName(pass) + "' is not declared"});
    if (!program || !*program || !mesh || targetMissing) return nullptr;
    gp->mesh = *mesh;
    if (!useProgram(*gp, std::move(**program), d)) return nullptr;
    return gp;
}

bool GlExecutor::Impl::useProgram(GpuPass& gp, PassGlProgram built, Diagnostics& d) {
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

bool GlExecutor::Impl::sharesItsTargetWithANeighbour(const GpuPass& gp) const {
    const std::set<int> runnable = plan.runnablePasses();
    auto it = runnable.find(gp.index);
    if (it == runnable.end()) return false;
    const std::string target = ws.passTargetName(*gp.pass);
    auto writesIt = [&](int index) { return ws.passTargetName(ws.passes[static_cast<size_t>(index)]) == target; };
    return (it != runnable.begin() && writesIt(*std::prev(it))) || (std::next(it) != runnable.end() && writesIt(*std::next(it)));
}

void GlExecutor::Impl::countOwnWrites(GpuPass& gp, const PassGlProgram& built, std::vector<std::string> inputs) {
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

std::unique_ptr<GpuPass> GlExecutor::Impl::withProgram(const GpuPass& gp, ProgramHandle program, std::set<std::string> initialized) {
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

std::optional<std::string> GlExecutor::Impl::healthInputLabel(const SamplerSlot& slot) const {
    if (slot.target) return slot.sampler->uniform + " → target '" + slot.target->name + "'";
    const Texture* file = ws.findTexture(slot.sampler->texture);
    if (file && file->kind == TextureKind::Texture2D) return slot.sampler->uniform + " → texture '" + file->name + "'";
    return std::nullopt;
}

bool GlExecutor::Impl::bindProgram(GpuPass& gp, Diagnostics& d) {
    append(d, bindStreams(gp, compatibility).diagnostics());
    auto bound = bindUniforms(gp, {ws, plan, textures, targets, values});
    append(d, bound.diagnostics());
    return bound.ok();
}

}  // namespace rmfx
