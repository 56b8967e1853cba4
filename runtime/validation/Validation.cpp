#include "validation/Validation.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <set>
#include <thread>

#include "core/LibraryLoading.h"
#include "frontend/shader/PassProgram.h"
#include "graph/PassGraph.h"
#include "graph/UniformBinding.h"
#include "model/EffectSelection.h"
#include "validation/GlslangCheck.h"

namespace rmfx {
namespace {

class Validator {
public:
    Validator(const Workspace& ws, const ValidationOptions& options, Diagnostics& out)
        : ws_(ws), options_(options), out_(&out), all_(out) {}

    // Each pass's checks are gathered in its own list: the glslang compiles of all passes run
    // between the checks before and after them, on every core, and the lists join in pass order.
    void run(CheckedPrograms* handOver) {
        checkUniqueNames();
        checkTargets();
        checkTextureReadConditions();
        checkInputs();
        checkOutput();
        checkEffects();
        checkSemantics();
        std::set<std::string> all;
        for (const Effect& e : ws_.effects) all.insert(e.name);
        prelude_ = effectPrelude(ws_, all);
        std::vector<PassCheck> checks(ws_.passes.size());
        for (size_t i = 0; i < ws_.passes.size(); ++i) {
            out_ = &checks[i].found;
            checkPass(ws_.passes[i], checks[i]);
        }
        if (options_.compileShaders) compileAll(checks);
        for (size_t i = 0; i < ws_.passes.size(); ++i) {
            out_ = &checks[i].found;
            if (checks[i].program && checks[i].compiled) checkProgram(ws_.passes[i], checks[i]);
            all_.insert(all_.end(), checks[i].found.begin(), checks[i].found.end());
        }
        out_ = &all_;
        Diagnostics order = checkPassOrder(ws_);
        all_.insert(all_.end(), order.begin(), order.end());
        if (handOver) {
            handOver->prelude = prelude_;
            for (size_t i = 0; i < checks.size(); ++i)
                if (checks[i].program && (!options_.compileShaders || (checks[i].compiled && *checks[i].compiled)))
                    handOver->programs.emplace(static_cast<int>(i), std::move(*checks[i].program));
        }
    }

private:
    // A pass's program as assembled, and what glslang made of it.
    struct PassCheck {
        Diagnostics found;
        std::optional<PassProgramSource> program;
        std::vector<std::string> vertexInputs;
        std::optional<Result<std::vector<ActiveUniform>>> compiled;
    };

    void error(const SourceLocation& where, const std::string& element, const std::string& message) {
        out_->push_back({Diagnostic::Severity::Error, where, element, message});
    }
    void warning(const SourceLocation& where, const std::string& element, const std::string& message) {
        out_->push_back({Diagnostic::Severity::Warning, where, element, message});
    }
    // "color (rgb)" and "color (rgba)" tell the two colour types apart.
    static std::string typeWithWidth(ValueType type) {
        if (type == ValueType::Color3) return "color (rgb)";
        if (type == ValueType::Color4) return "color (rgba)";
        return valueTypeName(type);
    }
    static std::string at(const SourceLocation& where) { return "line " + std::to_string(where.line); }

    // tag(item): the element the item was declared with ("float", "cubemap", …).
    template <class T, class Tag>
    void unique(const std::vector<T>& items, const char* kind, Tag tag) {
        std::map<std::string, SourceLocation> seen;
        for (const T& item : items) {
            auto [it, fresh] = seen.emplace(item.name, item.where);
            if (!fresh)
                error(item.where, "<" + std::string(tag(item)) + " name=\"" + item.name + "\">",
                      std::string("duplicate ") + kind + " name '" + item.name + "' (first declared at " +
                          at(it->second) + ")");
        }
    }

    void checkUniqueNames() {
        unique(ws_.variables, "variable", [](const Variable& v) { return valueTypeName(v.value.type); });
        unique(ws_.textures, "texture", [&](const Texture& t) {
            if (t.files.empty() && ws_.findInput(t.name)) return "input";
            return textureElementName(t.kind);
        });
        unique(ws_.targets, "target", [](const RenderTarget&) { return "target"; });
        unique(ws_.passes, "pass", [](const Pass&) { return "pass"; });
        unique(ws_.snippets, "code snippet", [](const CodeSnippet&) { return "code"; });
        if (ws_.output.target.empty())
            if (const RenderTarget* t = ws_.findTarget(Workspace::implicitOutputName))
                error(t->where, "<target name=\"output\">",
                      "the name 'output' is taken by the implicit output target; rename the target, or make it the "
                      "output with <output target=\"output\"/>");
    }

    void checkTargets() {
        for (const RenderTarget& t : ws_.targets) {
            if (!t.formatVariable.empty())
                checkChoiceVariable(t, "format-by", t.formatVariable, t.formats.size(), "format",
                                    selectTargetFormat(t, valueOf(t.formatVariable)).has_value());
            if (!t.scaleVariable.empty())
                checkChoiceVariable(t, "scale-by", t.scaleVariable, t.scales.size(), "scale",
                                    selectTargetSize(t, valueOf(t.scaleVariable)).has_value());
        }
    }

    // read-when="VARIABLE=VALUE": a declared variable, and a value of its type.
    void checkTextureReadConditions() {
        for (const Texture& t : ws_.textures) {
            if (t.readWhenVariable.empty()) continue;
            const std::string element = "<" + std::string(textureElementName(t.kind)) + " name=\"" + t.name + "\">";
            const Variable* v = ws_.findVariable(t.readWhenVariable);
            if (!v) {
                error(t.where, element, "read-when names '" + t.readWhenVariable + "', which is not a declared variable");
                continue;
            }
            if (Result<Value> value = parseValue(v->value.type, t.readWhenValue); !value)
                error(t.where, element, "read-when: '" + t.readWhenValue + "' is not a value of " + typeWithWidth(v->value.type) +
                                            " variable '" + v->name + "' (" + at(v->where) + "): " + value.error());
        }
    }

    // An input that replaces a target needs a pass that puts its image there; one that replaces
    // nothing is required, and unused it is a mistake worth a warning.
    void checkInputs() {
        for (const ImageInput& input : ws_.inputs) {
            std::string element = "<input name=\"" + input.name + "\">";
            bool sampled = false;
            for (const Pass& p : ws_.passes)
                for (const Sampler& s : p.samplers) sampled = sampled || s.texture == input.name;
            if (!input.replaces.empty() && !ws_.findTarget(input.replaces)) {
                error(input.where, element, "replaces target '" + input.replaces + "', which is not declared (" +
                                                ws_.describeTargets() + ")");
            } else if (!input.replaces.empty() && !sampled) {
                error(input.where, element, "replaces target '" + input.replaces + "', but no pass samples input '" +
                                                input.name + "': nothing would put the image into '" + input.replaces + "'");
            } else if (!sampled) {
                warning(input.where, element, "no pass samples input '" + input.name + "': an image given for it is not used");
            }
        }
    }

    const Value* valueOf(const std::string& name) const {
        const Variable* v = ws_.findVariable(name);
        return v ? &v->value : nullptr;
    }

    // format-by / scale-by: an int variable with one option per choice, whose value picks one.
    void checkChoiceVariable(const RenderTarget& t, const char* attribute, const std::string& variable, size_t choices,
                             const std::string& noun, bool picksOne) {
        std::string element = "<target name=\"" + t.name + "\">";
        const Variable* v = ws_.findVariable(variable);
        if (!v) {
            error(t.where, element, std::string(attribute) + " names '" + variable + "', which is not a declared variable");
            return;
        }
        if (v->value.type != ValueType::Int) {
            error(t.where, element, std::string(attribute) + " variable '" + v->name + "' (" + at(v->where) + ") is a " +
                                        valueTypeName(v->value.type) + "; it must be an int");
            return;
        }
        std::string count = std::to_string(choices);
        if (!v->options.empty() && v->options.size() != choices)
            error(t.where, element, noun + " lists " + count + " " + noun + "s, but variable '" + v->name + "' (" +
                                        at(v->where) + ") has " + std::to_string(v->options.size()) + " options: give one " +
                                        noun + " per option");
        else if (!picksOne)
            error(t.where, element, "variable '" + v->name + "' = " + std::to_string(v->value.asInt()) + " picks none of the " +
                                        count + " " + noun + "s (values 0 to " + std::to_string(choices - 1) + ")");
    }

    void checkOutput() {
        if (!ws_.output.target.empty() && !ws_.findTarget(ws_.output.target))
            error(ws_.output.where, "<output>", "target '" + ws_.output.target + "' is not declared");
        // The parser reports this on the <workspace> element; a workspace built otherwise has no line.
        if (ws_.passes.empty()) error({ws_.path.string(), 0}, "<workspace>", "no <pass>: nothing to render");
    }

    void checkEffects() {
        unique(ws_.effects, "effect", [](const Effect&) { return "effect"; });
        std::map<std::string, const Effect*> owner;
        for (const Effect& e : ws_.effects) {
            std::string element = "<effect name=\"" + e.name + "\">";
            for (const std::string& p : e.passes) {
                if (!ws_.findPass(p)) {
                    error(e.where, element, "pass '" + p + "' is not declared");
                    continue;
                }
                auto [it, fresh] = owner.emplace(p, &e);
                if (!fresh)
                    error(e.where, element, "pass '" + p + "' already belongs to effect '" + it->second->name + "' (" +
                                                at(it->second->where) + "): a pass belongs to one effect");
            }
            for (const std::string& name : e.switches) {
                const Variable* v = ws_.findVariable(name);
                if (!v)
                    error(e.where, element, "switch '" + name + "' is not a declared variable");
                else if (v->value.type != ValueType::Bool && v->value.type != ValueType::Int &&
                         v->value.type != ValueType::Float)
                    error(e.where, element, "switch '" + name + "' (" + at(v->where) + ") is a " +
                                                valueTypeName(v->value.type) + "; a switch is a bool, int or float");
            }
            if (!e.source.empty()) checkEffectSource(e, element);
            if (!e.source.empty() && !e.gate.empty()) checkEffectGate(e, element);
        }
        if (ws_.output.effects)
            for (const std::string& name : *ws_.output.effects)
                if (!ws_.findEffect(name))
                    error(ws_.output.where, "<output>", "effects: no effect named '" + name + "' is declared");
    }

    // <effect source>: skipping the effect when its source is zero must give what running it gives.
    void checkEffectSource(const Effect& e, const std::string& element) {
        if (!ws_.findTarget(e.source)) {
            error(e.where, element, "source: no render target '" + e.source + "' (" + ws_.describeTargets() + ")");
            return;
        }
        std::set<std::string> previousFrame;  // targets some pass reads as the last frame left them
        for (const Pass& p : ws_.passes)
            for (const Sampler& s : p.samplers)
                if (s.previousFrame) previousFrame.insert(s.target);
        // What the effect may read the source through: targets written before it from the source
        // (hdr_lighting's star_source, a blur of its source 'bright').
        std::set<std::string> fromSource{e.source};
        for (const Pass& p : ws_.passes) {
            if (!p.enabled || e.hasPass(p.name)) continue;
            for (const Sampler& s : p.samplers)
                if (!s.previousFrame && fromSource.count(s.target)) fromSource.insert(ws_.passTargetName(p));
        }
        bool samplesSource = false;
        for (const Pass& p : ws_.passes) {
            if (!p.enabled || !e.hasPass(p.name)) continue;
            const std::string written = ws_.passTargetName(p);
            if (written == e.source) {
                error(e.where, element, "source '" + e.source + "' is written by pass '" + p.name +
                                            "' of the effect itself; the source is what the effect starts from, "
                                            "written before it by passes outside it");
                return;
            }
            for (const Sampler& s : p.samplers) samplesSource = samplesSource || (!s.previousFrame && fromSource.count(s.target));
            if (previousFrame.count(written))
                error(e.where, element, "pass '" + p.name + "' writes '" + written +
                                            "', which is read with frame=\"previous\": a skipped frame could not "
                                            "leave what running it leaves there, so the effect cannot have a source");
            for (const Sampler& s : p.samplers)
                if (s.previousFrame)
                    error(e.where, element, "pass '" + p.name + "' reads '" + s.target +
                                                "' with frame=\"previous\": the effect cannot have a source");
            // What it hands to later passes is cleared to zero when it is skipped: that is only
            // what running it gives when the effect alone writes the target.
            for (const Pass& other : ws_.passes)
                if (other.enabled && !e.hasPass(other.name) && ws_.passTargetName(other) == written) {
                    error(e.where, element, "pass '" + p.name + "' writes '" + written + "', which pass '" + other.name +
                                                "' outside the effect writes too: a skipped effect's targets are cleared "
                                                "to zero, which would lose what '" + other.name + "' wrote");
                    break;
                }
        }
        if (!samplesSource)
            error(e.where, element, "no pass of the effect reads its source '" + e.source +
                                        "', directly or through what passes before it make of it");
        checkCompleteBeforeEffect(e, element, e.source, "source");
    }

    // Content skip counts `target` (the effect's source or gate) before the effect's first pass:
    // every write of it must come before.
    void checkCompleteBeforeEffect(const Effect& e, const std::string& element, const std::string& target, const std::string& role) {
        const Pass* first = nullptr;
        for (const Pass& p : ws_.passes) {
            if (!p.enabled) continue;
            if (!first && e.hasPass(p.name)) first = &p;
            if (first && !e.hasPass(p.name) && ws_.passTargetName(p) == target) {
                error(e.where, element, "pass '" + p.name + "' writes the " + role + " '" + target + "' after pass '" +
                                            first->name + "' of the effect: whether the effect contributes is decided "
                                            "before its first pass, so the " + role + " must be complete by then");
                return;
            }
        }
    }

    // <effect gate>: counted in place of the source, so it must be complete before the effect's
    // first pass, and be neither the source nor written by the effect. Whether it is zero only where
    // the source will be is the workspace's mathematics, as the source's is.
    void checkEffectGate(const Effect& e, const std::string& element) {
        if (!ws_.findTarget(e.gate)) {
            error(e.where, element, "gate: no render target '" + e.gate + "' (" + ws_.describeTargets() + ")");
            return;
        }
        if (e.gate == e.source) {
            error(e.where, element, "gate '" + e.gate + "' is the source itself: leave 'gate' out to count the source");
            return;
        }
        bool written = false;
        for (const Pass& p : ws_.passes) {
            if (!p.enabled || ws_.passTargetName(p) != e.gate) continue;
            if (e.hasPass(p.name)) {
                error(e.where, element, "gate '" + e.gate + "' is written by pass '" + p.name +
                                            "' of the effect itself; the gate is written before the effect, by passes outside it");
                return;
            }
            written = true;
        }
        if (!written) {
            error(e.where, element, "no pass writes the gate '" + e.gate + "' before the effect");
            return;
        }
        checkCompleteBeforeEffect(e, element, e.gate, "gate");
    }

    // An unknown semantic is no error: RenderMonkey knew a few rmfx does not fill.
    void checkSemantics() {
        auto check = [&](const Variable& v) {
            if (v.semantic.empty() || findSemantic(v.semantic)) return;
            warning(v.where, "<" + std::string(valueTypeName(v.value.type)) + " name=\"" + v.name + "\">",
                    "variable '" + v.name + "' (" + at(v.where) + ") has semantic '" + v.semantic +
                        "', which rmfx does not fill: it keeps its stored value " + formatValue(v.value));
        };
        for (const Variable& v : ws_.variables) check(v);
        for (const Pass& p : ws_.passes)
            for (const Variable& c : p.constants) check(c);
    }

    void checkPass(const Pass& pass, PassCheck& check) {
        std::string label = passLabel(pass);
        if (!pass.camera.empty() && !ws_.findCamera(pass.camera)) {
            std::string known;
            for (const NamedCamera& c : ws_.cameras) known += (known.empty() ? "" : ", ") + c.name;
            error(pass.cameraWhere.file.empty() ? pass.where : pass.cameraWhere, label,
                  "camera '" + pass.camera + "' is not declared (" +
                      (known.empty() ? std::string("the workspace names no camera: <camera name=\"…\">") : "named cameras: " + known) + ")");
        }
        for (const ShaderSource& s : pass.shaders)
            if (s.dialect == ShaderDialect::GlslLegacy && ws_.profile != GlProfile::Compatibility)
                error(s.where, "<shader>", "legacy GLSL (dialect=\"glsl110\") in " + label +
                                               " needs a compatibility-profile context: <workspace profile=\"compatibility\">");
        if (ws_.profile != GlProfile::Compatibility) {
            const SourceLocation& at = pass.raster.polygonModeWhere.file.empty() ? pass.where : pass.raster.polygonModeWhere;
            if (pass.raster.frontMode != pass.raster.backMode)
                error(at, "<polygon-mode>", label + " draws front and back faces differently, which only a "
                                                    "compatibility-profile context can: <workspace profile=\"compatibility\">");
            if (pass.raster.lineWidth != 1.0f)
                error(at, "<polygon-mode>", label + " draws lines " + formatValue(Value::ofFloat(pass.raster.lineWidth)) +
                                                    " pixels wide, which only a compatibility-profile context can "
                                                    "(core OpenGL draws them 1 pixel wide): <workspace profile=\"compatibility\">");
        }
        if (!pass.target.empty() && !ws_.findTarget(pass.target) &&
            !(pass.target == Workspace::implicitOutputName && ws_.output.target.empty()))
            error(pass.where, label, "target '" + pass.target + "' is not declared");
        std::string writes = ws_.passTargetName(pass);

        std::set<std::string> samplerNames;
        for (const Sampler& s : pass.samplers) {
            std::string element = "<sampler name=\"" + s.uniform + "\">";
            if (!samplerNames.insert(s.uniform).second)
                error(s.where, element, "a second sampler named '" + s.uniform + "' in " + label);
            if (!s.texture.empty()) {
                const Texture* t = ws_.findTexture(s.texture);
                if (!t) error(s.where, element, "texture '" + s.texture + "' is not declared");
                else if (s.mipmap != MipmapMode::None && !t->mipmaps)
                    error(s.where, element, "mipmap filtering, but texture '" + s.texture + "' has mipmaps=\"false\"");
                continue;
            }
            const RenderTarget* t = ws_.findTarget(s.target);
            bool implicit = s.target == Workspace::implicitOutputName && ws_.output.target.empty();
            if (!t && !implicit) {
                error(s.where, element, "target '" + s.target + "' is not declared");
                continue;
            }
            if (s.target == writes && !s.previousFrame)
                error(s.where, element, "pass '" + pass.name + "' samples target '" + s.target +
                                            "', which it also writes (use frame=\"previous\" to read last frame's "
                                            "contents, or a second target)");
            if (s.mipmap != MipmapMode::None && !t)
                error(s.where, element, "mipmap filtering, but the implicit output target has no mipmaps (declare a "
                                        "target with mipmaps=\"true\" and name it in <output target=...>)");
            else if (s.mipmap != MipmapMode::None && !t->mipmaps)
                error(s.where, element, "mipmap filtering, but target '" + s.target + "' is declared without mipmaps=\"true\"");
        }
        for (const Variable& c : pass.constants) {
            if (const Variable* v = ws_.findVariable(c.name); v && v->value.type != c.value.type)
                error(c.where, "<" + std::string(valueTypeName(c.value.type)) + " name=\"" + c.name + "\">",
                      "pass constant '" + c.name + "' is a " + typeWithWidth(c.value.type) + " but variable '" +
                          c.name + "' (" + at(v->where) + ") is a " + typeWithWidth(v->value.type));
        }
        // Every effect asked for, switches deciding: the form that keeps every read of the shader.
        Result<PassProgramSource> program = assemblePassProgram(ws_, pass, prelude_.defines, prelude_.declarations);
        out_->insert(out_->end(), program.diagnostics().begin(), program.diagnostics().end());
        if (program) check.program = std::move(*program);
    }

    // glslang compiles each distinct program once (passes often share their shaders), on as many
    // threads as there are cores; a program that fails is compiled again for each pass that has
    // it, so that its messages name that pass.
    void compileAll(std::vector<PassCheck>& checks) {
        std::map<std::string, size_t> firstWithText;
        std::vector<size_t> distinct;
        std::vector<std::optional<size_t>> sameAs(checks.size());
        for (size_t i = 0; i < checks.size(); ++i) {
            if (!checks[i].program) continue;
            std::string key;
            for (const PassStage& stage : checks[i].program->stages)
                key += std::to_string(static_cast<int>(stage.dialect)) + ":" + std::to_string(stage.shader.code.size()) + ":" +
                       stage.shader.code;
            auto [it, fresh] = firstWithText.emplace(std::move(key), i);
            if (fresh) distinct.push_back(i);
            else sameAs[i] = it->second;
        }
        auto compile = [&](size_t i) {
            checks[i].compiled = checkPassProgram(*checks[i].program, passLabel(ws_.passes[i]), &checks[i].vertexInputs);
        };
        // Each distinct program on a core of its own; on this thread alone while a library loads on
        // another (a new thread would wait for it: core/LibraryLoading.h).
        const size_t threads = libraryLoadingElsewhere() ? 1
                               : std::min<size_t>(distinct.size(), std::max(1u, std::thread::hardware_concurrency()));
        std::atomic<size_t> next{0};
        auto work = [&] {
            for (size_t n; (n = next.fetch_add(1)) < distinct.size();) compile(distinct[n]);
        };
        std::vector<std::thread> pool;
        for (size_t t = 1; t < threads; ++t) pool.emplace_back(work);
        work();
        for (std::thread& t : pool) t.join();
        for (size_t i = 0; i < checks.size(); ++i) {
            if (!sameAs[i]) continue;
            const PassCheck& first = checks[*sameAs[i]];
            if (*first.compiled) {
                checks[i].compiled = first.compiled;
                checks[i].vertexInputs = first.vertexInputs;
            } else {
                compile(i);
            }
        }
    }

    void checkProgram(const Pass& pass, const PassCheck& check) {
        const std::string label = passLabel(pass);
        const PassProgramSource& program = *check.program;
        const Result<std::vector<ActiveUniform>>& uniforms = *check.compiled;
        const std::vector<std::string>& inputs = check.vertexInputs;
        out_->insert(out_->end(), uniforms.diagnostics().begin(), uniforms.diagnostics().end());
        if (!uniforms) return;
        // Built-in streams are checked by the GL executor, which sees the driver's list of inputs.
        for (const VertexStream& stream : pass.streams)
            if (!stream.shared && !stream.attribute.empty() &&
                std::find(inputs.begin(), inputs.end(), stream.attribute) == inputs.end())
                warning(stream.where, label, "stream to attribute '" + stream.attribute + "' (line " +
                                                 std::to_string(stream.where.line) + "), which the shaders do not read");
        std::set<std::string> active;
        const std::set<std::string> initialized = uniformsWithInitializers(program);
        for (const ActiveUniform& u : *uniforms) {
            active.insert(u.name);
            if (u.name.rfind("rmfx_effect_", 0) == 0 && ws_.findEffect(u.name.substr(12))) continue;
            UniformSource source = resolveUniform(ws_, pass, u.name);
            if (std::holds_alternative<Unbound>(source) && keepsInitialValue(initialized, u.name)) continue;  // keeps its value
            std::string why = bindingMismatch(ws_, pass, source, u.name, u.type, u.arraySize);
            if (why.empty()) continue;
            SourceLocation where = findUniformDeclaration(program, u.name).value_or(pass.where);
            if (unboundUniformIsZero(pass, source, u.type))
                warning(where, label, why + "; Direct3D ran with its constant register unset, so it is fed zero");
            else
                error(where, label, why);
        }
        for (const Sampler& s : pass.samplers)
            if (!active.count(s.uniform))
                warning(s.where, "<sampler name=\"" + s.uniform + "\">",
                        "the shaders of pass '" + pass.name + "' do not use sampler '" + s.uniform + "'");
    }

    const Workspace& ws_;
    const ValidationOptions& options_;
    Diagnostics* out_;  // where error() and warning() write: the pass's own list while passes are checked
    Diagnostics& all_;
    ShaderPrelude prelude_;
};

}  // namespace

Result<void> validateWorkspace(const Workspace& ws, const ValidationOptions& options, CheckedPrograms* handOver) {
    Diagnostics out;
    try {
        Validator(ws, options, out).run(handOver);
    } catch (const std::filesystem::filesystem_error& e) {
        // A file name the file system refuses (a component over 255 bytes, a symlink loop, a folder
        // it may not search) ends validation with an error naming it, not with a crash.
        out.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "",
                       "cannot look up file '" + e.path1().string().substr(0, 300) + "': " + e.code().message()});
    }
    return out;
}

}  // namespace rmfx
