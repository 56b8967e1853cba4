#include "compile/CompiledFrame.h"

#include "model/EffectSelection.h"
#include "validation/GlslangCheck.h"

namespace rmfx {
namespace {

// The prelude as compiled with the macros of `effects` false (their uniforms still declared), so
// that the only difference from the compiled program is what the macros decide.
ShaderPrelude withMacrosFalse(const ShaderPrelude& prelude, const std::set<std::string>& effects) {
    ShaderPrelude probe = prelude;
    for (std::string& define : probe.defines)
        for (const std::string& e : effects)
            if (define.rfind(effectMacro(e) + " ", 0) == 0) define = effectMacro(e) + " false";
    return probe;
}

// glslang's preprocessor output by stage text, within one compile: a pass as compiled is compared
// with a probe for every set of effects it may be drawn without.
class PreprocessedStages {
public:
    const Result<std::string>& of(const PassStage& stage) {
        const std::string key = std::to_string(static_cast<int>(stage.stage)) + std::to_string(static_cast<int>(stage.dialect)) +
                                ":" + stage.shader.code;
        auto it = done_.find(key);
        if (it == done_.end()) it = done_.emplace(key, preprocessStage(stage)).first;
        return it->second;
    }

private:
    std::map<std::string, Result<std::string>> done_;
};

// Whether leaving `effects` out changes the pass's code: glslang's preprocessor gives its stages
// with the effects' macros false a different text from the stages as compiled. Where either does
// not preprocess, it is taken to read them (its second program then fails to build and is not
// drawn).
bool readsEffects(const Workspace& ws, const Pass& pass, const ShaderPrelude& prelude, const PassProgramSource& compiled,
                  const std::set<std::string>& effects, PreprocessedStages& preprocessed) {
    Result<PassProgramSource> probe = assemblePassProgram(ws, pass, withMacrosFalse(prelude, effects).defines, prelude.declarations);
    if (!probe || probe->stages.size() != compiled.stages.size()) return true;
    for (size_t i = 0; i < compiled.stages.size(); ++i) {
        const Result<std::string>& a = preprocessed.of(compiled.stages[i]);
        const Result<std::string>& b = preprocessed.of(probe->stages[i]);
        if (!a || !b || *a != *b) return true;
    }
    return false;
}

std::optional<PassProgramSource> programWithoutEffects(const Workspace& ws, const Pass& pass, const FramePlan& plan,
                                                       const PassProgramSource& asCompiled, const std::set<std::string>& effects,
                                                       PreprocessedStages& preprocessed) {
    if (!readsEffects(ws, pass, plan.prelude, asCompiled, effects, preprocessed)) return std::nullopt;
    std::set<std::string> asked;
    for (const std::string& e : plan.askedEffects)
        if (!effects.count(e)) asked.insert(e);
    const ShaderPrelude without = effectPrelude(ws, asked);
    Result<PassProgramSource> source = assemblePassProgram(ws, pass, without.defines, without.declarations);
    if (!source) return std::nullopt;
    return std::move(*source);
}

std::map<std::string, std::set<std::string>> byPassName(const Workspace& ws, const PassGraph& graph,
                                                        const std::map<size_t, std::set<std::string>>& byPosition) {
    std::map<std::string, std::set<std::string>> out;
    for (const auto& [position, effects] : byPosition) out[ws.passes[static_cast<size_t>(graph.schedule[position])].name] = effects;
    return out;
}

// Content skip's second programs for every combination of switches, each pass and set of effects
// assembled and decided once.
void compileProgramsWithoutEffects(CompiledFrame& frame) {
    const Workspace& ws = frame.ws();
    std::map<std::pair<int, std::set<std::string>>, std::optional<PassProgramSource>> made;
    PreprocessedStages preprocessed;
    for (const auto& [off, skip] : frame.plan.contentSkip) {
        const PassGraph& graph = frame.plan.graphs.at(off);
        for (const ContentSkipPlan::Consumer& c : skip.consumers) {
            const int index = graph.schedule[c.position];
            auto [it, fresh] = made.try_emplace({index, c.effects});
            if (fresh) {
                const Result<PassProgramSource>& compiled = frame.programs.at(index);
                if (compiled)
                    it->second = programWithoutEffects(ws, ws.passes[static_cast<size_t>(index)], frame.plan, *compiled, c.effects,
                                                       preprocessed);
            }
            if (it->second) frame.withoutEffects[off][c.position] = {c.effects, *it->second};
        }
    }
}

}  // namespace

std::optional<PassProgramSource> programWithoutEffects(const Workspace& ws, const Pass& pass, const FramePlan& plan,
                                                       const PassProgramSource& asCompiled, const std::set<std::string>& effects) {
    PreprocessedStages preprocessed;
    return programWithoutEffects(ws, pass, plan, asCompiled, effects, preprocessed);
}

const ProgramWithoutEffects* CompiledFrame::programWithout(const std::set<std::string>& switchedOff, size_t position) const {
    auto variant = withoutEffects.find(plan.variant(switchedOff).switchedOff);
    if (variant == withoutEffects.end()) return nullptr;
    auto it = variant->second.find(position);
    return it == variant->second.end() ? nullptr : &it->second;
}

std::map<std::string, std::set<std::string>> CompiledFrame::passesDrawnWithoutSkippedEffects(
    const std::set<std::string>& switchedOff) const {
    const FrameVariant v = plan.variant(switchedOff);
    std::map<size_t, std::set<std::string>> drawn;
    if (auto variant = withoutEffects.find(v.switchedOff); v.graph && variant != withoutEffects.end())
        for (const auto& [position, program] : variant->second) drawn[position] = program.effects;
    return v.graph ? byPassName(ws(), *v.graph, drawn) : std::map<std::string, std::set<std::string>>{};
}

std::map<std::string, std::set<std::string>> CompiledFrame::passesDrawnOnlyForEffects(const std::set<std::string>& switchedOff) const {
    const FrameVariant v = plan.variant(switchedOff);
    std::map<size_t, std::set<std::string>> feeders;
    if (v.contentSkip)
        for (const ContentSkipPlan::Feeder& f : v.contentSkip->feeders) feeders[f.position] = f.effects;
    return v.graph ? byPassName(ws(), *v.graph, feeders) : std::map<std::string, std::set<std::string>>{};
}

std::map<std::string, std::string> CompiledFrame::effectsRunningWhateverTheContent(const std::set<std::string>& switchedOff) const {
    const FrameVariant v = plan.variant(switchedOff);
    return v.contentSkip ? v.contentSkip->runningAlways : std::map<std::string, std::string>{};
}

Result<std::shared_ptr<const CompiledFrame>> compileFrame(std::shared_ptr<const Workspace> ws, const FramePlanOptions& options,
                                                          glm::ivec2 viewport, int maxTargetSize, const CheckedPrograms* checked) {
    using Compiled = Result<std::shared_ptr<const CompiledFrame>>;
    const Workspace& w = *ws;
    if (viewport.x < 1 || viewport.y < 1)
        return Compiled::failure({{Diagnostic::Severity::Error, {w.path.string(), 0}, "",
                                   "viewport size " + std::to_string(viewport.x) + "x" + std::to_string(viewport.y) + " is empty"}});
    auto frame = std::make_shared<CompiledFrame>();
    frame->values = declaredValues(w);
    Result<FramePlan> plan = planFrame(w, options, viewport, frame->values, maxTargetSize);
    if (!plan) return Compiled::failure(plan.takeDiagnostics());
    frame->workspace = std::move(ws);
    frame->viewport = viewport;
    frame->maxTargetSize = maxTargetSize;
    frame->plan = std::move(*plan);
    const ShaderPrelude& prelude = frame->plan.prelude;
    const bool samePrelude = checked && checked->prelude.defines == prelude.defines &&
                             checked->prelude.declarations == prelude.declarations;
    for (int index : frame->plan.runnablePasses()) {
        const auto given = checked ? checked->programs.find(index) : std::map<int, PassProgramSource>::const_iterator{};
        const bool validated = checked && given != checked->programs.end();
        if (validated && samePrelude) {
            frame->programs.emplace(index, given->second);
            continue;
        }
        Result<PassProgramSource> assembled = assemblePassProgram(w, w.passes[static_cast<size_t>(index)], prelude.defines,
                                                                  prelude.declarations);
        // Assembling a pass warns about its files and their text (a missing #version, HLSL without
        // a COLOR0 to fog), which the effects' macro values do not change: validation said it.
        if (validated && assembled) assembled = Result<PassProgramSource>(std::move(*assembled));
        frame->programs.emplace(index, std::move(assembled));
    }
    if (!options.checkHealth) compileProgramsWithoutEffects(*frame);
    return std::shared_ptr<const CompiledFrame>(std::move(frame));
}

FrameExplanationInput explanationOf(const CompiledFrame& frame, const std::set<std::string>& switchedOff) {
    const FrameVariant v = frame.plan.variant(switchedOff);
    FrameExplanationInput in;
    in.ws = &frame.ws();
    in.graph = v.graph;
    in.plan = &frame.plan.targets;
    in.askedEffects = frame.plan.askedEffects;
    in.switchedOffEffects = v.switchedOff;
    in.pooled = frame.plan.options.poolTargets;
    in.contentSkip = frame.plan.options.contentSkip;
    in.frameRan = false;
    in.drawnWithoutSkipped = frame.passesDrawnWithoutSkippedEffects(switchedOff);
    in.drawnOnlyForEffects = frame.passesDrawnOnlyForEffects(switchedOff);
    in.runningWhateverTheContent = frame.effectsRunningWhateverTheContent(switchedOff);
    return in;
}

}  // namespace rmfx
