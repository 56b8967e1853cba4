#include "gl/GlExecutor.h"

#include <algorithm>
#include <cstring>
#include <set>

#include <epoxy/gl.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "frontend/shader/PassProgram.h"
#include "gl/FixedFunctionState.h"
#include "gl/GlFormats.h"
#include "gl/GlLimits.h"
#include "gl/GlMesh.h"
#include "gl/GlTexture.h"
#include "graph/UniformBinding.h"
#include "io/mesh/BuiltinMeshes.h"
#include "io/mesh/ModelLoader.h"
#include "model/EffectSelection.h"
#include "model/VertexUsageName.h"
#include "validation/GlslangCheck.h"

namespace rmfx {
namespace {

// GL memory of one TargetResource of the plan: shared by the targets whose lifetimes do not overlap.
struct GpuResource {
    TargetResource spec;
    GLuint textures[2] = {0, 0};
    GLuint framebuffers[2] = {0, 0};
    GLuint depth = 0;
    int front = 0;  // buffer with the last finished frame's contents

    int writeBuffer() const { return spec.history ? 1 - front : 0; }
};

struct GpuTarget {
    std::string name;
    const RenderTarget* spec = nullptr;  // null for the implicit output
    GpuResource* resource = nullptr;     // null when the plan does not allocate it
    bool writtenThisFrame = false;
    SourceLocation where;
};

struct UniformSlot {
    GLint location = -1;
    std::string name;
    UniformType type = UniformType::Other;
    UniformSource source;
    std::string effectSwitch;  // rmfx_effect_<name>: whether that effect runs this frame
    const Value* value = nullptr;  // a pass constant's, or the variable's current value
    std::optional<SemanticInfo> semantic;  // filled every frame (Variable::semantic)
};

struct SamplerSlot {
    GLint unit = 0;
    GLuint samplerObject = 0;
    const Sampler* sampler = nullptr;
    GLuint texture = 0;                // for textures
    GpuTarget* target = nullptr;       // for targets
};

struct GpuPass {
    const Pass* pass = nullptr;
    int index = 0;  // in Workspace::passes
    GLuint program = 0;
    GpuTarget* target = nullptr;
    const GlMesh* mesh = nullptr;
    glm::mat4 model{1.0f};
    std::vector<StreamBinding> streams;  // Pass::streams against the program; empty: rmfx's layout
    std::vector<UniformSlot> uniforms;
    std::vector<SamplerSlot> samplers;
    std::set<std::string> initializedUniforms;  // declared with a value: unbound, they keep it
};

std::string describeGlError(GLenum e) {
    switch (e) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "GL error 0x%04x", e);
            return buffer;
        }
    }
}

std::string describeFramebufferStatus(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "incomplete attachment";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "no attachment";
        case GL_FRAMEBUFFER_UNSUPPORTED: return "format combination unsupported by the driver";
        default: return "status 0x" + std::to_string(status);
    }
}

// The camera's matrices, computed once per frame for every pass that uploads them.
struct FrameCamera {
    glm::mat4 view, projection, viewProjection, inverseView, inverseProjection, inverseViewProjection;
    glm::vec3 position;

    FrameCamera(const OrbitCamera& camera, glm::ivec2 viewport)
        : view(camera.view()),
          projection(camera.projection(static_cast<float>(viewport.x) / static_cast<float>(viewport.y))),
          viewProjection(projection * view),
          inverseView(glm::inverse(view)),
          inverseProjection(glm::inverse(projection)),
          inverseViewProjection(glm::inverse(viewProjection)),
          position(camera.position()) {}
};

// <stream usage="texcoord" index="0" attribute="rm_TexCoord0"> (line 12), for messages.
std::string streamLabel(const VertexStream& stream) {
    std::string label = std::string("<stream usage=\"") + vertexUsageName(stream.usage) + "\"";
    if (stream.usage == VertexUsage::TexCoord || stream.usageIndex != 0)
        label += " index=\"" + std::to_string(stream.usageIndex) + "\"";
    if (!stream.attribute.empty()) label += " attribute=\"" + stream.attribute + "\"";
    return label + "> (line " + std::to_string(stream.where.line) + ")";
}

// The compatibility built-in a stream without an attribute feeds; empty for tangents and binormals.
std::string builtinAttributeName(const VertexStream& stream) {
    switch (stream.usage) {
        case VertexUsage::Position: return "gl_Vertex";
        case VertexUsage::Normal: return "gl_Normal";
        case VertexUsage::TexCoord: return "gl_MultiTexCoord" + std::to_string(stream.usageIndex);
        case VertexUsage::Color: return "gl_Color";
        case VertexUsage::Tangent:
        case VertexUsage::Binormal: break;
    }
    return {};
}

glm::dmat4 toDouble(const glm::mat4& m) { return glm::dmat4(m); }

glm::mat4 modelMatrix(const DrawCall& draw) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), draw.translate);
    m = glm::rotate(m, glm::radians(draw.rotateDegrees.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(draw.rotateDegrees.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(draw.rotateDegrees.x), glm::vec3(1, 0, 0));
    return glm::scale(m, draw.scale);
}

}  // namespace

// Timestamps of one frame's passes: queries[0] before the first pass, queries[i + 1] after pass i.
struct TimerFrame {
    std::vector<GLuint> queries;
    std::vector<std::string> passes;
    bool pending = false;
};

struct GlExecutor::Impl {
    const Workspace& ws;
    ExecutorOptions options;
    ResourceLimits limits;
    glm::ivec2 viewport{1};
    std::map<std::string, Value> values;
    std::set<std::string> askedEffects;
    ShaderPrelude prelude;
    FrameRequest request;
    // The graph of every combination of effect switches, built once: switching costs a lookup.
    std::map<std::set<std::string>, PassGraph> graphs;
    std::set<std::string> switchedOff;
    bool variablesChanged = true;       // since selectGraph last read the switches
    const PassGraph* graph = nullptr;   // of the current switches
    std::vector<GpuPass*> schedule;     // the passes the current graph runs
    std::vector<std::string> lastFramePasses;
    TargetPlan plan;
    std::vector<std::unique_ptr<GpuResource>> resources;
    std::vector<std::unique_ptr<GpuTarget>> targets;
    std::map<std::string, GLuint> textures;
    std::map<std::string, std::unique_ptr<GlMesh>> meshes;
    std::vector<std::unique_ptr<GpuPass>> passes;  // compiled: every pass some combination of switches runs
    std::vector<GLuint> samplerObjects;

    bool compatibility = false;  // the workspace's profile, checked against the context in create()
    glm::dvec2 mouse{0.0};
    glm::ivec3 mouseButtons{0};

    bool timing = false;
    TimerFrame timerFrames[3];
    int timerNext = 0;
    std::vector<PassTiming> timings;
    double frameMilliseconds = 0.0;

    explicit Impl(const Workspace& w) : ws(w) {}

    ~Impl() {
        for (TimerFrame& f : timerFrames)
            glDeleteQueries(static_cast<GLsizei>(f.queries.size()), f.queries.data());
        releaseResources();
        for (auto& [name, texture] : textures) glDeleteTextures(1, &texture);
        for (auto& p : passes) glDeleteProgram(p->program);
        glDeleteSamplers(static_cast<GLsizei>(samplerObjects.size()), samplerObjects.data());
    }

    GpuTarget* findTarget(const std::string& name) const {
        for (auto& t : targets)
            if (t->name == name) return t.get();
        return nullptr;
    }

    void error(Diagnostics& d, const SourceLocation& where, const std::string& element, const std::string& message) {
        d.push_back({Diagnostic::Severity::Error, where, element, message});
    }

    GpuPass* compiledPass(int index) const {
        for (auto& p : passes)
            if (p->index == index) return p.get();
        return nullptr;
    }

    // The graphs of every combination of the asked-for effects' switches (all-on first). With
    // more than 10 switched effects, only all on, each one off and all off are prepared.
    bool buildGraphs(Diagnostics& d) {
        auto asked = selectEffects(ws, options.effects);
        if (!asked) {
            error(d, {ws.path.string(), 0}, "", asked.error());
            return false;
        }
        askedEffects = *asked;
        prelude = effectPrelude(ws, askedEffects);
        request.effects = askedEffects;
        request.outputs = options.outputs;
        if (request.outputs.empty()) {  // inspect everything: every target a running pass writes
            std::set<std::string> written;
            for (const Pass& p : ws.passes) {
                const Effect* e = ws.effectOfPass(p.name);
                if (p.enabled && (!e || askedEffects.count(e->name))) written.insert(ws.passTargetName(p));
            }
            for (const RenderTarget& t : ws.targets)
                if (written.count(t.name)) request.outputs.push_back(t.name);
            if (written.count(Workspace::implicitOutputName) && ws.output.target.empty())
                request.outputs.push_back(Workspace::implicitOutputName);
        }
        std::vector<std::string> switched;
        for (const Effect& e : ws.effects)
            if (askedEffects.count(e.name) && !e.switches.empty()) switched.push_back(e.name);
        std::vector<std::set<std::string>> combinations;
        if (switched.size() <= 10) {
            for (unsigned mask = 0; mask < (1u << switched.size()); ++mask) {
                std::set<std::string> off;
                for (size_t k = 0; k < switched.size(); ++k)
                    if (mask & (1u << k)) off.insert(switched[k]);
                combinations.push_back(off);
            }
        } else {
            combinations.push_back({});
            for (const std::string& e : switched) combinations.push_back({e});
            combinations.push_back(std::set<std::string>(switched.begin(), switched.end()));
        }
        bool ok = true;
        for (const std::set<std::string>& off : combinations) {
            FrameRequest r = request;
            r.switchedOff = off;
            Diagnostics found;
            PassGraph g = buildPassGraph(ws, r, found);
            if (hasErrors(found)) {
                std::string when = off.empty() ? "" : " (with effects " + joinNames(off) + " switched off)";
                for (Diagnostic& diagnostic : found) diagnostic.message += when;
                d.insert(d.end(), found.begin(), found.end());
                ok = false;
            }
            graphs.emplace(off, std::move(g));
        }
        return ok;
    }

    // Follows the effect switches: the schedule of the graph of the current combination.
    void selectGraph() {
        if (graph && !variablesChanged) return;
        variablesChanged = false;
        std::set<std::string> off = rmfx::switchedOffEffects(ws, askedEffects, values);
        if (graph && off == switchedOff) return;
        auto it = graphs.find(off);
        if (it == graphs.end()) it = graphs.find({});  // more switches than prepared: run them all
        switchedOff = it->first;
        graph = &it->second;
        schedule.clear();
        for (int index : graph->schedule)
            if (GpuPass* p = compiledPass(index)) schedule.push_back(p);
    }

    int lastWriter(const std::string& target) const {
        for (int i = static_cast<int>(ws.passes.size()) - 1; i >= 0; --i)
            if (ws.passes[static_cast<size_t>(i)].enabled && ws.passTargetName(ws.passes[static_cast<size_t>(i)]) == target) return i;
        return -1;
    }

    void releaseResources() {
        for (auto& r : resources) {
            glDeleteFramebuffers(2, r->framebuffers);
            glDeleteTextures(2, r->textures);
            glDeleteRenderbuffers(1, &r->depth);
        }
        resources.clear();
        for (auto& t : targets) t->resource = nullptr;
    }

    bool allocate(GpuResource& r, const std::string& element, const SourceLocation& where, Diagnostics& d) {
        const TargetResource& spec = r.spec;
        int buffers = spec.history ? 2 : 1;
        int levels = spec.mipmaps ? gl::mipLevels(spec.size.x, spec.size.y) : 1;
        if (spec.depth) {
            glCreateRenderbuffers(1, &r.depth);
            glNamedRenderbufferStorage(r.depth, GL_DEPTH_COMPONENT32F, spec.size.x, spec.size.y);
        }
        bool ok = true;
        for (int i = 0; i < buffers; ++i) {
            glCreateTextures(GL_TEXTURE_2D, 1, &r.textures[i]);
            glTextureStorage2D(r.textures[i], levels, gl::internalFormat(spec.format), spec.size.x, spec.size.y);
            glCreateFramebuffers(1, &r.framebuffers[i]);
            glNamedFramebufferTexture(r.framebuffers[i], GL_COLOR_ATTACHMENT0, r.textures[i], 0);
            if (r.depth) glNamedFramebufferRenderbuffer(r.framebuffers[i], GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, r.depth);
            GLenum status = glCheckNamedFramebufferStatus(r.framebuffers[i], GL_FRAMEBUFFER);
            if (status != GL_FRAMEBUFFER_COMPLETE) {
                error(d, where, element,
                      std::string("framebuffer for format ") + targetFormatName(spec.format) + " " +
                          std::to_string(spec.size.x) + "x" + std::to_string(spec.size.y) +
                          " is incomplete: " + describeFramebufferStatus(status));
                ok = false;
                continue;
            }
            glClearNamedFramebufferfv(r.framebuffers[i], GL_COLOR, 0, glm::value_ptr(spec.initial));
            // A depth test before the first depth clear compares against the farthest depth, not
            // whatever the new storage holds.
            if (r.depth) {
                const float farthest = 1.0f;
                glDepthMask(GL_TRUE);
                glClearNamedFramebufferfv(r.framebuffers[i], GL_DEPTH, 0, &farthest);
            }
        }
        if (GLenum e = glGetError(); e != GL_NO_ERROR) {
            error(d, where, element,
                  describeGlError(e) + " while allocating " + std::to_string(spec.size.x) + "x" +
                      std::to_string(spec.size.y) + " " + targetFormatName(spec.format));
            ok = false;
        }
        return ok;
    }

    // Plans the targets for the graphs of every switch combination and allocates the plan's
    // resources: a target some combination uses gets memory, shared where lifetimes allow.
    bool allocateTargets(Diagnostics& d) {
        std::vector<const PassGraph*> all;
        for (auto& [off, g] : graphs) all.push_back(&g);
        auto valueOf = [&](const std::string& name) -> const Value* {
            auto it = values.find(name);
            return it == values.end() ? nullptr : &it->second;
        };
        for (const RenderTarget& t : ws.targets) {
            std::string element = "<target name=\"" + t.name + "\">";
            if (!selectTargetFormat(t, valueOf(t.formatVariable))) {
                error(d, t.where, element, formatChoiceError(t, valueOf(t.formatVariable)));
                return false;
            }
            if (!selectTargetSize(t, valueOf(t.scaleVariable))) {
                error(d, t.where, element, scaleChoiceError(t, valueOf(t.scaleVariable)));
                return false;
            }
        }
        auto planned = planTargets(ws, all, viewport, values, options.poolTargets && !options.outputs.empty());
        if (!planned) {
            error(d, {ws.path.string(), 0}, "", planned.error());
            return false;
        }
        if (Diagnostics over = checkPlanLimits(*planned, limits, {ws.path.string(), 0}); !over.empty()) {
            d.insert(d.end(), over.begin(), over.end());
            return false;
        }
        releaseResources();
        plan = std::move(*planned);
        if (targets.empty())
            for (const PlannedTarget& p : plan.targets) {
                auto t = std::make_unique<GpuTarget>();
                t->name = p.name;
                t->spec = p.spec;
                t->where = p.where;
                targets.push_back(std::move(t));
            }
        bool ok = true;
        for (const TargetResource& spec : plan.resources) {
            auto r = std::make_unique<GpuResource>();
            r->spec = spec;
            const PlannedTarget& first = plan.targets[static_cast<size_t>(spec.targets.front())];
            ok = allocate(*r, "<target name=\"" + first.name + "\">", first.where, d) && ok;
            for (int t : spec.targets) targets[static_cast<size_t>(t)]->resource = r.get();
            resources.push_back(std::move(r));
        }
        return ok;
    }

    // Only the textures a pass that can run samples.
    bool loadTextures(Diagnostics& d) {
        std::set<std::string> sampled;
        for (auto& [off, g] : graphs)
            for (int index : g.schedule)
                for (const Sampler& s : ws.passes[static_cast<size_t>(index)].samplers)
                    if (!s.texture.empty()) sampled.insert(s.texture);
        bool ok = true;
        for (const Texture& t : ws.textures) {
            if (!sampled.count(t.name)) continue;
            if (takeOverTexture(t)) continue;  // hot reload: a copy of the previous build's
            auto loaded = loadGlTexture(ws, t);
            if (!loaded) {
                error(d, t.where, "", loaded.error());
                ok = false;
                continue;
            }
            textures[t.name] = loaded->name;
        }
        return ok;
    }

    const GlMesh* meshFor(const DrawCall& draw, Diagnostics& d) {
        std::string key = draw.mesh ? std::string("builtin:") + builtinMeshName(*draw.mesh) : "file:" + draw.file;
        if (auto it = meshes.find(key); it != meshes.end()) return it->second.get();
        Mesh mesh;
        if (draw.mesh) {
            mesh = makeMesh(*draw.mesh);
        } else {
            auto loaded = loadModel(ws.folder / draw.file);
            if (!loaded) {
                error(d, draw.where, "<draw>", loaded.error());
                return nullptr;
            }
            mesh = std::move(*loaded);
        }
        auto& slot = meshes[key];
        slot = std::make_unique<GlMesh>(mesh);
        return slot.get();
    }

    GLuint compileProgram(const Pass& pass, Diagnostics& d, std::set<std::string>& initializedUniforms) {
        auto source = assemblePassProgram(ws, pass, prelude.defines, d, prelude.declarations);
        if (!source) return 0;
        initializedUniforms = uniformsWithInitializers(*source);
        std::string label = passLabel(pass);
        GLuint program = glCreateProgram();
        bool ok = true;
        for (const PassStage& stage : source->stages) {
            GLuint shader = glCreateShader(stage.stage == ShaderStage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
            const char* text = stage.shader.code.c_str();
            glShaderSource(shader, 1, &text, nullptr);
            glCompileShader(shader);
            GLint compiled = 0;
            glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
            if (!compiled) {
                GLint length = 0;
                glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
                std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
                glGetShaderInfoLog(shader, length, nullptr, log.data());
                log.resize(std::strlen(log.c_str()));
                auto mapped = mapCompilerLog(log, stage.shader, stage.where, label);
                if (mapped.empty()) mapped.push_back({Diagnostic::Severity::Error, stage.where, label, "shader failed to compile"});
                d.insert(d.end(), mapped.begin(), mapped.end());
                ok = false;
            }
            glAttachShader(program, shader);
            glDeleteShader(shader);
        }
        if (!ok) {
            glDeleteProgram(program);
            return 0;
        }
        // The built-in vertex shaders' attributes, for dialects without layout qualifiers.
        for (GLuint a = 0; a < 3; ++a) glBindAttribLocation(program, a, builtinAttributeLocations[a]);
        glLinkProgram(program);
        GLint linked = 0;
        glGetProgramiv(program, GL_LINK_STATUS, &linked);
        if (!linked) {
            GLint length = 0;
            glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
            std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
            glGetProgramInfoLog(program, length, nullptr, log.data());
            log.resize(std::strlen(log.c_str()));
            error(d, pass.where, label, "shaders failed to link: " + log);
            glDeleteProgram(program);
            return 0;
        }
        return program;
    }

    // Pass::streams against the linked program: a named attribute by its location, an empty one
    // to its compatibility built-in. A stream the program does not read is a warning, then skipped.
    void bindStreams(GpuPass& gp, Diagnostics& d) {
        gp.streams.clear();
        const Pass& pass = *gp.pass;
        if (pass.streams.empty()) return;
        std::set<std::string> inputs;  // active vertex inputs, built-ins included
        GLint count = 0;
        glGetProgramInterfaceiv(gp.program, GL_PROGRAM_INPUT, GL_ACTIVE_RESOURCES, &count);
        for (GLint i = 0; i < count; ++i) {
            char name[256] = {};
            glGetProgramResourceName(gp.program, GL_PROGRAM_INPUT, static_cast<GLuint>(i), sizeof name, nullptr, name);
            inputs.insert(name);
        }
        auto warn = [&](const VertexStream& stream, const std::string& why) {
            d.push_back({Diagnostic::Severity::Warning, stream.where, passLabel(pass), "stream " + streamLabel(stream) + " " + why});
        };
        for (const VertexStream& stream : pass.streams) {
            if (!stream.attribute.empty()) {
                // Validation warns about attributes the shaders do not read; one the driver's
                // optimiser dropped as well is no news.
                GLint location = glGetAttribLocation(gp.program, stream.attribute.c_str());
                if (location < 0) continue;
                gp.streams.push_back({stream.usage, stream.usageIndex, location});
                continue;
            }
            std::string builtin = builtinAttributeName(stream);
            if (builtin.empty()) {
                if (!stream.shared) warn(stream, "names no attribute, and tangents and binormals have no compatibility built-in");
            } else if (!compatibility) {
                warn(stream, "feeds the built-in " + builtin + ", which needs <workspace profile=\"compatibility\">");
            } else if (!inputs.count(builtin)) {
                if (!stream.shared) warn(stream, "feeds the built-in " + builtin + ", which the shaders do not read");
            } else {
                gp.streams.push_back({stream.usage, stream.usageIndex, -1});
            }
        }
    }

    bool bindUniforms(GpuPass& gp, Diagnostics& d) {
        const Pass& pass = *gp.pass;
        GLint count = 0;
        glGetProgramInterfaceiv(gp.program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
        bool ok = true;
        int unit = 0;
        for (GLint i = 0; i < count; ++i) {
            const GLenum props[4] = {GL_TYPE, GL_LOCATION, GL_ARRAY_SIZE, GL_BLOCK_INDEX};
            GLint values[4] = {};
            glGetProgramResourceiv(gp.program, GL_UNIFORM, static_cast<GLuint>(i), 4, props, 4, nullptr, values);
            if (values[3] != -1 || values[1] < 0) continue;  // block members are not rmfx variables
            char nameBuffer[256] = {};
            glGetProgramResourceName(gp.program, GL_UNIFORM, static_cast<GLuint>(i), sizeof nameBuffer, nullptr, nameBuffer);
            std::string name = nameBuffer;
            if (name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0) name.resize(name.size() - 3);
            UniformType type = uniformTypeFromGl(values[0]);
            if (name.rfind("rmfx_effect_", 0) == 0) {  // declared by the effect prelude
                UniformSlot slot;
                slot.location = values[1];
                slot.name = name;
                slot.type = type;
                slot.effectSwitch = name.substr(12);
                gp.uniforms.push_back(std::move(slot));
                continue;
            }
            UniformSource source = resolveUniform(ws, pass, name);
            if (std::holds_alternative<Unbound>(source) && gp.initializedUniforms.count(name)) continue;
            if (std::string why = bindingMismatch(ws, source, name, type, values[2]); !why.empty()) {
                error(d, pass.where, passLabel(pass), why);
                ok = false;
                continue;
            }
            if (const auto* s = std::get_if<BoundSampler>(&source)) {
                SamplerSlot slot;
                slot.unit = unit++;
                slot.sampler = s->sampler;
                glProgramUniform1i(gp.program, values[1], slot.unit);
                if (!s->sampler->texture.empty()) {
                    slot.texture = textures[s->sampler->texture];
                } else {
                    slot.target = findTarget(s->sampler->target);
                    if (!slot.target || !slot.target->resource) {
                        error(d, s->sampler->where, "<sampler name=\"" + name + "\">", unallocatedRead(gp, *s->sampler));
                        ok = false;
                        continue;
                    }
                }
                glCreateSamplers(1, &slot.samplerObject);
                samplerObjects.push_back(slot.samplerObject);
                const Sampler& spec = *s->sampler;
                glSamplerParameteri(slot.samplerObject, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(gl::minFilter(spec.filter, spec.mipmap)));
                glSamplerParameteri(slot.samplerObject, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(gl::magFilter(spec.filter)));
                glSamplerParameteri(slot.samplerObject, GL_TEXTURE_WRAP_S, static_cast<GLint>(gl::wrapMode(spec.wrapS)));
                glSamplerParameteri(slot.samplerObject, GL_TEXTURE_WRAP_T, static_cast<GLint>(gl::wrapMode(spec.wrapT)));
                glSamplerParameteri(slot.samplerObject, GL_TEXTURE_WRAP_R, static_cast<GLint>(gl::wrapMode(spec.wrapT)));
                glSamplerParameterfv(slot.samplerObject, GL_TEXTURE_BORDER_COLOR, glm::value_ptr(spec.border));
                gp.samplers.push_back(slot);
                continue;
            }
            UniformSlot slot;
            slot.location = values[1];
            slot.name = name;
            slot.type = type;
            slot.source = source;
            if (const auto* m = std::get_if<BoundSemantic>(&source)) slot.semantic = m->info;
            else if (const auto* c = std::get_if<BoundConstant>(&source)) slot.value = &c->constant->value;
            else if (const auto* v = std::get_if<BoundVariable>(&source)) slot.value = &this->values.at(v->variable->name);
            gp.uniforms.push_back(std::move(slot));
        }
        return ok;
    }

    // Why a sampler that the compiled shader still uses reads a target with no memory.
    std::string unallocatedRead(const GpuPass& gp, const Sampler& sampler) const {
        std::string head = "pass '" + gp.pass->name + "' samples target '" + sampler.target + "'";
        for (auto& [off, g] : graphs) {
            const PassNode& node = g.nodes[static_cast<size_t>(gp.index)];
            for (const std::string& skipped : node.skippedInputs) {
                if (skipped != sampler.target) continue;
                const Effect* owner = nullptr;
                for (const PassNode& n : g.nodes)
                    if (n.target == skipped && n.effect) owner = n.effect;
                std::string effect = owner ? owner->name : "?";
                return head + ", which only effect '" + effect + "' writes, and that effect is not asked for; guard the "
                       "read with `if (" + effectMacro(effect) + ")` so that it compiles away";
            }
        }
        return head + ", which no scheduled pass writes";
    }

    // A value's first components into a uniform of the given type (a vec3 takes a vec4's xyz).
    static void uploadValue(GLuint program, GLint location, UniformType type, const float* data) {
        switch (type) {
            case UniformType::Float: glProgramUniform1f(program, location, data[0]); break;
            case UniformType::Int:
            case UniformType::Bool: glProgramUniform1i(program, location, static_cast<GLint>(data[0])); break;
            case UniformType::Vec2: glProgramUniform2fv(program, location, 1, data); break;
            case UniformType::Vec3: glProgramUniform3fv(program, location, 1, data); break;
            case UniformType::Vec4: glProgramUniform4fv(program, location, 1, data); break;
            case UniformType::Mat2: glProgramUniformMatrix2fv(program, location, 1, GL_FALSE, data); break;
            case UniformType::Mat3: glProgramUniformMatrix3fv(program, location, 1, GL_FALSE, data); break;
            case UniformType::Mat4: glProgramUniformMatrix4fv(program, location, 1, GL_FALSE, data); break;
            default: break;
        }
    }

    SemanticInputs semanticInputs(const GpuPass& gp, const FrameClock& clock, int frame, const FrameCamera& camera,
                                  const OrbitCameraSettings& lens, glm::ivec2 viewport) const {
        SemanticInputs in;
        in.world = toDouble(gp.model);
        in.view = toDouble(camera.view);
        in.projection = toDouble(camera.projection);
        in.fovYRadians = glm::radians(static_cast<double>(lens.fovYDegrees));
        in.nearPlane = lens.nearPlane;
        in.farPlane = lens.farPlane;
        in.viewport = viewport;
        in.time = clock.time;
        in.deltaTime = clock.deltaTime;
        in.frame = frame;
        in.passIndex = gp.index;
        in.mouse = mouse;
        in.mouseButtons = mouseButtons;
        return in;
    }

    void upload(const GpuPass& gp, const FrameClock& clock, int frame, const FrameCamera& camera,
                const OrbitCameraSettings& lens, glm::ivec2 viewport) {
        std::optional<SemanticInputs> semantics;
        for (const UniformSlot& u : gp.uniforms) {
            if (!u.effectSwitch.empty()) {
                glProgramUniform1i(gp.program, u.location, switchedOff.count(u.effectSwitch) ? 0 : 1);
                continue;
            }
            if (u.semantic) {
                if (!semantics) semantics = semanticInputs(gp, clock, frame, camera, lens, viewport);
                uploadValue(gp.program, u.location, u.type, semanticValue(*u.semantic, *semantics).data.data());
                continue;
            }
            if (u.value) {
                uploadValue(gp.program, u.location, u.type, u.value->data.data());
                continue;
            }
            const auto& p = std::get<BoundPredefined>(u.source);
            glm::vec2 targetSize = gp.target->resource->spec.size;
            auto mat4 = [&](const glm::mat4& m) { glProgramUniformMatrix4fv(gp.program, u.location, 1, GL_FALSE, glm::value_ptr(m)); };
            auto vec2 = [&](glm::vec2 v) { glProgramUniform2f(gp.program, u.location, v.x, v.y); };
            switch (p.info.id) {
                case Predefined::ViewportSize: vec2(glm::vec2(viewport)); break;
                case Predefined::InvViewportSize: vec2(1.0f / glm::vec2(viewport)); break;
                case Predefined::TargetSize: vec2(targetSize); break;
                case Predefined::InvTargetSize: vec2(1.0f / targetSize); break;
                case Predefined::Time: glProgramUniform1f(gp.program, u.location, clock.time); break;
                case Predefined::DeltaTime: glProgramUniform1f(gp.program, u.location, clock.deltaTime); break;
                case Predefined::Frame: glProgramUniform1i(gp.program, u.location, frame); break;
                case Predefined::View: mat4(camera.view); break;
                case Predefined::Projection: mat4(camera.projection); break;
                case Predefined::ViewProjection: mat4(camera.viewProjection); break;
                case Predefined::InvView: mat4(camera.inverseView); break;
                case Predefined::InvProjection: mat4(camera.inverseProjection); break;
                case Predefined::InvViewProjection: mat4(camera.inverseViewProjection); break;
                case Predefined::Model: mat4(gp.model); break;
                case Predefined::ModelViewProjection: mat4(camera.viewProjection * gp.model); break;
                case Predefined::NormalMatrix: {
                    glm::mat3 n = glm::inverseTranspose(glm::mat3(gp.model));
                    glProgramUniformMatrix3fv(gp.program, u.location, 1, GL_FALSE, glm::value_ptr(n));
                    break;
                }
                case Predefined::CameraPosition: {
                    const glm::vec3& c = camera.position;
                    glProgramUniform3f(gp.program, u.location, c.x, c.y, c.z);
                    break;
                }
            }
        }
    }

    // Reads every pending frame whose last timestamp is available, oldest first; waits only when
    // the slot about to be reused is still pending.
    void collectTimings(bool waitForNext) {
        for (int k = 0; k < 3; ++k) {
            TimerFrame& f = timerFrames[(timerNext + k) % 3];
            if (!f.pending) continue;
            GLint available = 0;
            glGetQueryObjectiv(f.queries.back(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available && !(waitForNext && k == 0)) continue;
            std::vector<GLuint64> stamps(f.queries.size());
            for (size_t i = 0; i < f.queries.size(); ++i) glGetQueryObjectui64v(f.queries[i], GL_QUERY_RESULT, &stamps[i]);
            timings.clear();
            for (size_t i = 0; i < f.passes.size(); ++i)
                timings.push_back({f.passes[i], static_cast<double>(stamps[i + 1] - stamps[i]) * 1e-6});
            frameMilliseconds = static_cast<double>(stamps.back() - stamps.front()) * 1e-6;
            f.pending = false;
        }
    }

    TimerFrame* beginTimedFrame(size_t passCount) {
        if (!timing) return nullptr;
        collectTimings(true);
        TimerFrame& f = timerFrames[timerNext];
        timerNext = (timerNext + 1) % 3;
        if (f.queries.size() != passCount + 1) {
            glDeleteQueries(static_cast<GLsizei>(f.queries.size()), f.queries.data());
            f.queries.assign(passCount + 1, 0);
            glCreateQueries(GL_TIMESTAMP, static_cast<GLsizei>(f.queries.size()), f.queries.data());
        }
        f.passes.clear();
        f.pending = true;
        glQueryCounter(f.queries[0], GL_TIMESTAMP);
        return &f;
    }

    void applyState(const Pass& pass) {
        if (pass.blend.enabled) {
            glEnable(GL_BLEND);
            glBlendFuncSeparate(gl::blendFactor(pass.blend.srcColor), gl::blendFactor(pass.blend.dstColor),
                                gl::blendFactor(pass.blend.srcAlpha), gl::blendFactor(pass.blend.dstAlpha));
            glBlendEquationSeparate(gl::blendEquation(pass.blend.colorOp), gl::blendEquation(pass.blend.alphaOp));
            glBlendColor(pass.blend.constant.r, pass.blend.constant.g, pass.blend.constant.b, pass.blend.constant.a);
        } else {
            glDisable(GL_BLEND);
        }
        if (pass.depth.test || pass.depth.write) {
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(pass.depth.test ? gl::compareFunc(pass.depth.func) : GL_ALWAYS);
        } else {
            glDisable(GL_DEPTH_TEST);
        }
        glDepthMask(pass.depth.write ? GL_TRUE : GL_FALSE);
        if (pass.raster.cull == CullFace::None) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
            glCullFace(pass.raster.cull == CullFace::Back ? GL_BACK : GL_FRONT);
        }
        glFrontFace(pass.raster.frontCounterClockwise ? GL_CCW : GL_CW);
    }

    // Hot reload (recompilePasses, reloadTexture, reloadModel).
    GpuPass* findPass(const std::string& name) const {
        for (auto& p : passes)
            if (p->pass->name == name) return p.get();
        return nullptr;
    }

    void deleteSamplerObjects(const std::vector<SamplerSlot>& slots) {
        for (const SamplerSlot& slot : slots) {
            glDeleteSamplers(1, &slot.samplerObject);
            std::erase(samplerObjects, slot.samplerObject);
        }
    }

    // createReusing: the previous build, and the textures it may give, while create() runs.
    static thread_local const Impl* textureDonor;
    static thread_local const std::vector<std::string>* donatedTextures;

    // A texture the donor holds with the same declaration (files, layout, colour space, mipmaps)
    // is copied on the GPU instead of being read, decoded and converted again.
    bool takeOverTexture(const Texture& t) {
        if (!textureDonor || !donatedTextures ||
            std::find(donatedTextures->begin(), donatedTextures->end(), t.name) == donatedTextures->end())
            return false;
        const Texture* old = textureDonor->ws.findTexture(t.name);
        auto it = textureDonor->textures.find(t.name);
        if (!old || it == textureDonor->textures.end() || old->kind != t.kind || old->layout != t.layout ||
            old->colorSpace != t.colorSpace || old->mipmaps != t.mipmaps || old->faceSize != t.faceSize ||
            old->files.size() != t.files.size())
            return false;
        for (size_t i = 0; i < t.files.size(); ++i)
            if ((textureDonor->ws.folder / old->files[i]).lexically_normal() != (ws.folder / t.files[i]).lexically_normal())
                return false;
        GLuint copy = copyTexture(it->second);
        if (!copy) return false;
        textures[t.name] = copy;
        return true;
    }

    static GLuint copyTexture(GLuint source) {
        while (glGetError() != GL_NO_ERROR) {
        }
        GLint target = 0, levels = 0, width = 0, height = 0, internal = 0;
        GLint swizzle[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
        glGetTextureParameteriv(source, GL_TEXTURE_TARGET, &target);
        glGetTextureParameteriv(source, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        glGetTextureParameteriv(source, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
        glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_WIDTH, &width);
        glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_HEIGHT, &height);
        glGetTextureLevelParameteriv(source, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
        if ((target != GL_TEXTURE_2D && target != GL_TEXTURE_CUBE_MAP) || levels < 1 || width < 1 || height < 1)
            return 0;
        GLuint copy = 0;
        glCreateTextures(static_cast<GLenum>(target), 1, &copy);
        glTextureStorage2D(copy, levels, static_cast<GLenum>(internal), width, height);
        glTextureParameteriv(copy, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
        for (GLint level = 0; level < levels; ++level)
            glCopyImageSubData(source, static_cast<GLenum>(target), level, 0, 0, 0, copy, static_cast<GLenum>(target), level,
                               0, 0, 0, std::max(1, width >> level), std::max(1, height >> level),
                               target == GL_TEXTURE_CUBE_MAP ? 6 : 1);
        if (glGetError() != GL_NO_ERROR) {
            glDeleteTextures(1, &copy);
            return 0;
        }
        return copy;
    }
};

GlExecutor::GlExecutor(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GlExecutor::~GlExecutor() = default;

std::unique_ptr<GlExecutor> GlExecutor::create(const Workspace& ws, glm::ivec2 viewport, Diagnostics& d,
                                               const ExecutorOptions& options) {
    if (viewport.x < 1 || viewport.y < 1) {
        d.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "",
                     "viewport size " + std::to_string(viewport.x) + "x" + std::to_string(viewport.y) + " is empty"});
        return nullptr;
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    auto impl = std::make_unique<Impl>(ws);
    impl->options = options;
    impl->limits = {queryMaxTargetSize(), options.memoryBudget};
    if (Diagnostics over = checkViewportLimits(viewport, impl->limits, {ws.path.string(), 0}); !over.empty()) {
        d.insert(d.end(), over.begin(), over.end());
        return nullptr;
    }
    impl->viewport = viewport;
    impl->compatibility = ws.profile == GlProfile::Compatibility;
    if (impl->compatibility) {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        if (!(mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT)) {
            d.push_back({Diagnostic::Severity::Error, {ws.path.string(), 0}, "<workspace>",
                         "the workspace asks for a compatibility-profile context (legacy GLSL, fixed-function "
                         "matrices), but the current context is a core profile one"});
            return nullptr;
        }
    }
    for (const Variable& v : ws.variables) impl->values[v.name] = v.value;
    if (!impl->buildGraphs(d)) return nullptr;
    const bool allocated = impl->allocateTargets(d);
    bool ok = impl->loadTextures(d) && allocated;
    std::set<int> runnable;  // every pass some combination of switches runs
    for (auto& [off, g] : impl->graphs) runnable.insert(g.schedule.begin(), g.schedule.end());
    for (int index : runnable) {
        const Pass& pass = ws.passes[static_cast<size_t>(index)];
        auto gp = std::make_unique<GpuPass>();
        gp->pass = &pass;
        gp->index = index;
        gp->target = impl->findTarget(ws.passTargetName(pass));
        gp->mesh = impl->meshFor(pass.draw, d);
        gp->model = modelMatrix(pass.draw);
        gp->program = impl->compileProgram(pass, d, gp->initializedUniforms);
        // Without memory (the targets failed to allocate: already reported) or not declared at all.
        if (allocated && (!gp->target || !gp->target->resource)) {
            impl->error(d, pass.where, passLabel(pass), "target '" + ws.passTargetName(pass) + "' is not declared");
            ok = false;
        }
        if (!gp->program || !gp->mesh || !gp->target || !gp->target->resource) {
            ok = false;
            glDeleteProgram(gp->program);
            continue;
        }
        impl->bindStreams(*gp, d);
        ok = impl->bindUniforms(*gp, d) && ok;
        impl->passes.push_back(std::move(gp));
    }
    if (!ok) return nullptr;
    impl->selectGraph();
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    std::unique_ptr<GlExecutor> executor(new GlExecutor(std::move(impl)));
    executor->camera_ = OrbitCamera(ws.camera);
    executor->viewport_ = viewport;
    return executor;
}

Diagnostics GlExecutor::renderFrame(const FrameClock& clock) {
    Diagnostics d;
    Impl& s = *impl_;
    while (glGetError() != GL_NO_ERROR) {
    }
    s.selectGraph();
    for (auto& t : s.targets) t->writtenThisFrame = false;
    TimerFrame* timer = s.beginTimedFrame(s.schedule.size());
    s.lastFramePasses.clear();
    const FrameCamera camera(camera_, viewport_);
    for (const GpuPass* scheduled : s.schedule) {
        const GpuPass& gp = *scheduled;
        const Pass& pass = *gp.pass;
        GpuTarget& target = *gp.target;
        GpuResource& memory = *target.resource;
        GLuint framebuffer = memory.framebuffers[memory.writeBuffer()];
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, memory.spec.size.x, memory.spec.size.y);
        s.applyState(pass);
        if (pass.clear.color) glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, glm::value_ptr(*pass.clear.color));
        if (pass.clear.depth) {
            glDepthMask(GL_TRUE);
            glClearNamedFramebufferfv(framebuffer, GL_DEPTH, 0, &*pass.clear.depth);
            glDepthMask(pass.depth.write ? GL_TRUE : GL_FALSE);
        }
        glUseProgram(gp.program);
        s.upload(gp, clock, frame_, camera, camera_.settings(), viewport_);
        if (s.compatibility) loadFixedFunctionState(camera.projection, camera.view * gp.model);
        for (const SamplerSlot& slot : gp.samplers) {
            GLuint texture = slot.texture;
            if (slot.target) {
                // frame="previous": what the last frame left. The current frame: the buffer a pass
                // wrote this frame, or, before any pass has, still what the last frame left (the
                // write buffer of a double-buffered target then holds the frame before that).
                const GpuTarget& t = *slot.target;
                const GpuResource& r = *t.resource;
                bool current = !slot.sampler->previousFrame && t.writtenThisFrame;
                texture = r.textures[current ? r.writeBuffer() : r.front];
            }
            glBindTextureUnit(static_cast<GLuint>(slot.unit), texture);
            glBindSampler(static_cast<GLuint>(slot.unit), slot.samplerObject);
        }
        gp.mesh->draw(gp.streams);
        target.writtenThisFrame = true;
        s.lastFramePasses.push_back(pass.name);
        if (memory.spec.mipmaps) glGenerateTextureMipmap(memory.textures[memory.writeBuffer()]);
        if (timer) {
            timer->passes.push_back(pass.name);
            glQueryCounter(timer->queries[timer->passes.size()], GL_TIMESTAMP);
        }
        for (GLenum e; (e = glGetError()) != GL_NO_ERROR;)
            d.push_back({Diagnostic::Severity::Error, pass.where, passLabel(pass),
                         describeGlError(e) + " while drawing into '" + target.name + "'"});
    }
    // Double-buffered targets written this frame: next frame writes the other buffer, and
    // frame="previous" reads this one.
    for (auto& t : s.targets)
        if (t->resource && t->resource->spec.history && t->writtenThisFrame) t->resource->front = 1 - t->resource->front;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++frame_;
    return d;
}

const Value* GlExecutor::variable(const std::string& name) const {
    auto it = impl_->values.find(name);
    return it == impl_->values.end() ? nullptr : &it->second;
}

std::string GlExecutor::setVariable(const std::string& name, const Value& value) {
    Impl& s = *impl_;
    auto it = s.values.find(name);
    if (it == s.values.end()) return "no variable named '" + name + "'";
    if (it->second.type != value.type)
        return "variable '" + name + "' is a " + valueTypeName(it->second.type) + " (" +
               std::to_string(componentCount(it->second.type)) + " values), not a " + valueTypeName(value.type);
    bool reallocate = false;
    for (const RenderTarget& t : s.ws.targets) {
        if (t.formatVariable == name) {
            if (!selectTargetFormat(t, &value)) return formatChoiceError(t, &value);
            reallocate = reallocate || *selectTargetFormat(t, &value) != *selectTargetFormat(t, &it->second);
        }
        if (t.scaleVariable == name) {
            if (!selectTargetSize(t, &value)) return scaleChoiceError(t, &value);
            reallocate = reallocate || value.asInt() != it->second.asInt();
        }
    }
    it->second = value;
    s.variablesChanged = true;
    // A new format or size changes which targets can share memory: the plan and its memory start
    // over (every target back to its initial value). Effect switches take effect at the next frame.
    if (reallocate) {
        Diagnostics d;
        if (!s.allocateTargets(d)) return d.empty() ? "cannot allocate the targets" : d.front().message;
    }
    return {};
}

void GlExecutor::setTimingEnabled(bool enabled) {
    impl_->timing = enabled;
    if (!enabled) {
        for (TimerFrame& f : impl_->timerFrames) f.pending = false;
        impl_->timings.clear();
        impl_->frameMilliseconds = 0.0;
    }
}

const std::vector<PassTiming>& GlExecutor::passTimings() const {
    impl_->collectTimings(false);
    return impl_->timings;
}

double GlExecutor::frameGpuMilliseconds() const { return impl_->frameMilliseconds; }

Result<Image> GlExecutor::readTarget(const std::string& name) const {
    const Impl& s = *impl_;
    const GpuTarget* t = s.findTarget(name);
    if (!t) return Error{"no render target named '" + name + "'"};
    const PlannedTarget& planned = s.plan.targets[static_cast<size_t>(s.plan.find(name))];
    if (!t->resource) {
        std::string why = "target '" + name + "' is not computed: no pass the outputs need writes or reads it";
        if (int writer = s.lastWriter(name); writer >= 0)
            why += " (its writer '" + s.ws.passes[static_cast<size_t>(writer)].name + "' is " +
                   passFateName(s.graph->nodes[static_cast<size_t>(writer)].fate) + ": " +
                   s.graph->nodes[static_cast<size_t>(writer)].why + ")";
        return Error{why + "; ask for it as an output (rmfx render --target " + name + ")"};
    }
    const GpuResource& r = *t->resource;
    if (static_cast<size_t>(r.spec.targets.back()) != static_cast<size_t>(s.plan.find(name)))
        return Error{"target '" + name + "' shares memory with '" +
                     s.plan.targets[static_cast<size_t>(r.spec.targets.back())].name +
                     "', which overwrites it later in the frame; ask for it as an output (rmfx render --target " +
                     name + ") to keep it"};
    int buffer = r.front;  // the newest finished contents
    Image image;
    image.width = planned.size.x;
    image.height = planned.size.y;
    image.channels = gl::channelCount(planned.format) == 1 ? 1 : 4;
    image.highDynamicRange = true;
    std::vector<float> rgba(static_cast<size_t>(image.width) * image.height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(r.textures[buffer], 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(rgba.size() * sizeof(float)), rgba.data());
    if (GLenum e = glGetError(); e != GL_NO_ERROR) return Error{describeGlError(e) + " reading target '" + name + "'"};
    image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
    for (int y = 0; y < image.height; ++y) {
        const float* src = &rgba[static_cast<size_t>(image.height - 1 - y) * image.width * 4];
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < image.channels; ++c) image.at(x, y, c) = src[x * 4 + c];
    }
    return image;
}

std::vector<std::string> GlExecutor::targetNames() const {
    std::vector<std::string> names;
    for (auto& t : impl_->targets) names.push_back(t->name);
    return names;
}

glm::ivec2 GlExecutor::targetSize(const std::string& name) const {
    int i = impl_->plan.find(name);
    return i < 0 ? glm::ivec2(0) : impl_->plan.targets[static_cast<size_t>(i)].size;
}

TargetFormat GlExecutor::targetFormat(const std::string& name) const {
    int i = impl_->plan.find(name);
    return i < 0 ? TargetFormat::RGBA8 : impl_->plan.targets[static_cast<size_t>(i)].format;
}

unsigned GlExecutor::targetTexture(const std::string& name) const {
    const GpuTarget* t = impl_->findTarget(name);
    return t && t->resource ? t->resource->textures[t->resource->front] : 0;
}

const PassGraph& GlExecutor::graph() const {
    impl_->selectGraph();
    return *impl_->graph;
}
const TargetPlan& GlExecutor::targetPlan() const { return impl_->plan; }
const std::set<std::string>& GlExecutor::askedEffects() const { return impl_->askedEffects; }
const std::set<std::string>& GlExecutor::switchedOffEffects() const {
    impl_->selectGraph();
    return impl_->switchedOff;
}
const std::vector<std::string>& GlExecutor::passesRun() const { return impl_->lastFramePasses; }

int GlExecutor::allocatedTextureCount() const {
    int count = 0;
    for (auto& r : impl_->resources)
        for (GLuint texture : r->textures) count += texture != 0 ? 1 : 0;
    return count;
}

// Hot reload: each change is built completely before anything of the running build is touched.

Diagnostics GlExecutor::recompilePasses(const std::vector<std::string>& passNames) {
    Diagnostics d;
    Impl& s = *impl_;
    while (glGetError() != GL_NO_ERROR) {
    }
    std::vector<std::string> names;
    for (const std::string& name : passNames)
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    size_t samplerObjectsBefore = s.samplerObjects.size();
    std::vector<std::pair<GpuPass*, GpuPass>> rebuilt;
    bool ok = true;
    for (const std::string& name : names) {
        GpuPass* old = s.findPass(name);
        if (!old && s.ws.findPass(name)) continue;  // culled: nothing compiled to replace
        if (!old) {
            s.error(d, {s.ws.path.string(), 0}, "<pass name=\"" + name + "\">", "no enabled pass named '" + name + "' to recompile");
            ok = false;
            continue;
        }
        GpuPass fresh;
        fresh.pass = old->pass;
        fresh.index = old->index;
        fresh.target = old->target;
        fresh.mesh = old->mesh;
        fresh.model = old->model;
        fresh.program = s.compileProgram(*fresh.pass, d, fresh.initializedUniforms);
        if (!fresh.program) {
            ok = false;
            continue;
        }
        s.bindStreams(fresh, d);
        ok = s.bindUniforms(fresh, d) && ok;
        rebuilt.emplace_back(old, std::move(fresh));
    }
    if (!ok) {
        for (auto& [old, fresh] : rebuilt) glDeleteProgram(fresh.program);
        // bindUniforms appended the new passes' sampler objects.
        glDeleteSamplers(static_cast<GLsizei>(s.samplerObjects.size() - samplerObjectsBefore),
                         s.samplerObjects.data() + samplerObjectsBefore);
        s.samplerObjects.resize(samplerObjectsBefore);
        return d;
    }
    for (auto& [old, fresh] : rebuilt) {
        glDeleteProgram(old->program);
        s.deleteSamplerObjects(old->samplers);
        *old = std::move(fresh);
    }
    return d;
}

Diagnostics GlExecutor::reloadTexture(const std::string& name) {
    Diagnostics d;
    Impl& s = *impl_;
    const Texture* spec = s.ws.findTexture(name);
    auto it = s.textures.find(name);
    if (spec && it == s.textures.end()) return d;  // no pass that can run samples it: nothing loaded
    if (!spec) {
        s.error(d, {s.ws.path.string(), 0}, "", "no texture named '" + name + "' to reload");
        return d;
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    auto loaded = loadGlTexture(s.ws, *spec);
    if (!loaded) {
        s.error(d, spec->where, "", loaded.error());
        return d;
    }
    if (GLenum e = glGetError(); e != GL_NO_ERROR) {
        glDeleteTextures(1, &loaded->name);
        s.error(d, spec->where, "", describeGlError(e) + " while uploading texture '" + name + "'");
        return d;
    }
    GLuint old = it->second;
    it->second = loaded->name;
    for (auto& p : s.passes)
        for (SamplerSlot& slot : p->samplers)
            if (!slot.target && slot.sampler->texture == name) slot.texture = loaded->name;
    glDeleteTextures(1, &old);
    return d;
}

Diagnostics GlExecutor::reloadModel(const std::string& file) {
    Diagnostics d;
    Impl& s = *impl_;
    auto it = s.meshes.find("file:" + file);
    const Pass* user = nullptr;
    for (const auto& p : s.passes)
        if (!p->pass->draw.mesh && p->pass->draw.file == file) user = p->pass;
    if (it == s.meshes.end() || !user) {
        s.error(d, {s.ws.path.string(), 0}, "<draw>", "no pass draws model file '" + file + "'");
        return d;
    }
    auto loaded = loadModel(s.ws.folder / file);
    if (!loaded) {
        s.error(d, user->draw.where, "<draw>", loaded.error());
        return d;
    }
    auto fresh = std::make_unique<GlMesh>(*loaded);
    for (auto& p : s.passes)
        if (p->mesh == it->second.get()) p->mesh = fresh.get();
    it->second = std::move(fresh);
    return d;
}

thread_local const GlExecutor::Impl* GlExecutor::Impl::textureDonor = nullptr;
thread_local const std::vector<std::string>* GlExecutor::Impl::donatedTextures = nullptr;

std::unique_ptr<GlExecutor> GlExecutor::createReusing(const Workspace& ws, glm::ivec2 viewport, Diagnostics& diagnostics,
                                                      const GlExecutor& previous,
                                                      const std::vector<std::string>& reusableTextures) {
    struct Donation {
        Donation(const Impl* impl, const std::vector<std::string>* names) {
            Impl::textureDonor = impl;
            Impl::donatedTextures = names;
        }
        ~Donation() {
            Impl::textureDonor = nullptr;
            Impl::donatedTextures = nullptr;
        }
    } donation(previous.impl_.get(), &reusableTextures);
    return create(ws, viewport, diagnostics, previous.impl_->options);
}

void GlExecutor::setMouse(glm::vec2 pixels, glm::ivec3 buttons) {
    impl_->mouse = glm::dvec2(pixels);
    impl_->mouseButtons = buttons;
}

unsigned GlExecutor::passProgram(const std::string& pass) const {
    const GpuPass* p = impl_->findPass(pass);
    return p ? p->program : 0;
}

unsigned GlExecutor::textureObject(const std::string& name) const {
    auto it = impl_->textures.find(name);
    return it == impl_->textures.end() ? 0 : it->second;
}

}  // namespace rmfx
