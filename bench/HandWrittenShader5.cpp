#include "bench/HandWrittenShader5.h"

#include <fstream>
#include <set>
#include <sstream>

#include <epoxy/gl.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "frontend/shader/PassProgram.h"
#include "frontend/shader/ShaderPreprocessor.h"
#include "gl/GlMesh.h"
#include "gl/GlTexture.h"
#include "io/mesh/BuiltinMeshes.h"
#include "model/OrbitCamera.h"

namespace rmfx::bench {
namespace {

enum class UniformKind { Float, Int, Vec2, Vec3, Mat3, Mat4 };

struct HandUniform {
    GLint location = -1;
    UniformKind kind = UniformKind::Float;
    const void* data = nullptr;  // float, int or glm type, owned by the State
};

// One pass, everything resolved to GL names at setup.
struct HandPass {
    GLuint framebuffer = 0;
    GLsizei width = 0, height = 0;
    bool clear = false;  // colour (0, 0, 0, 1) and depth 1
    bool depthTest = false, depthWrite = false, cullBack = false, blendAdd = false;
    GLuint program = 0;
    const GlMesh* mesh = nullptr;
    int uniformCount = 0;
    HandUniform uniforms[8];
    int textureCount = 0;
    GLuint textures[8] = {};
    GLuint samplers[8] = {};
};

// What the per-frame code reads: camera matrices computed once per frame, variable values and
// pass constants.
struct FrameValues {
    glm::mat4 viewProjection{1.0f};
    glm::mat4 inverseViewProjection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    glm::mat4 model{1.0f};
    glm::mat3 normalMatrix{1.0f};
    float exposure = 0.0f;
    int environmentFormat = 0;
    float glow[3] = {0.0f, 0.0f, 0.0f};
    float streakFactor = 0.0f;
    float ghostFactor = 0.0f;
    int effectOn = 1;                // rmfx_effect_glare, _streak, _ghost: every effect runs
    glm::vec2 inverseQuarterSize{0.0f};
    glm::vec2 directions[4] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};  // dl, dr, ul, ur
    float offsetFactors[2] = {1.0f, 4.0f};
};

struct Uniform {
    const char* name;
    UniformKind kind;
    const void* data;
};

struct Texture {
    const char* name;  // the sampler uniform
    GLuint texture;
    GLuint sampler;
};

std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

struct HandWrittenShader5::State {
    glm::ivec2 viewport{1};
    OrbitCamera camera;
    FrameValues values;
    std::vector<HandPass> passes;

    std::vector<GLuint> targetTextures, framebuffers, programs, samplerObjects, imageTextures;
    GLuint sceneDepth = 0;
    GLuint outputTexture = 0;
    std::unique_ptr<GlMesh> fullscreen, teapot;

    ~State() {
        glDeleteFramebuffers(static_cast<GLsizei>(framebuffers.size()), framebuffers.data());
        glDeleteTextures(static_cast<GLsizei>(targetTextures.size()), targetTextures.data());
        glDeleteTextures(static_cast<GLsizei>(imageTextures.size()), imageTextures.data());
        glDeleteRenderbuffers(1, &sceneDepth);
        glDeleteSamplers(static_cast<GLsizei>(samplerObjects.size()), samplerObjects.data());
        for (GLuint p : programs) glDeleteProgram(p);
    }

    // A colour texture and its framebuffer, cleared to 0.
    GLuint target(glm::ivec2 size, GLuint* texture, GLuint depth = 0, GLenum format = GL_RGBA16F) {
        GLuint t = 0, f = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &t);
        glTextureStorage2D(t, 1, format, size.x, size.y);
        glCreateFramebuffers(1, &f);
        glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT0, t, 0);
        if (depth) glNamedFramebufferRenderbuffer(f, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(f, GL_COLOR, 0, zero);
        targetTextures.push_back(t);
        framebuffers.push_back(f);
        if (texture) *texture = t;
        return f;
    }

    GLuint sampler(GLenum filter) {
        GLuint s = 0;
        glCreateSamplers(1, &s);
        glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
        glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
        glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(s, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        samplerObjects.push_back(s);
        return s;
    }

    // Compiles a vertex and a fragment shader; a null vertex file takes the built-in shader
    // `builtinVertex`. Files get the executor's effect prelude: every effect asked for, each
    // following a uniform bool because shader_5's effects have switch variables.
    Result<GLuint> program(const Workspace& ws, const char* vertexFile, const char* builtinVertex, const char* fragmentFile) {
        static const std::vector<std::string> defines = {"RMFX_EFFECT_glare rmfx_effect_glare",
                                                         "RMFX_EFFECT_streak rmfx_effect_streak",
                                                         "RMFX_EFFECT_ghost rmfx_effect_ghost"};
        static const std::vector<std::string> declarations = {
            "uniform bool rmfx_effect_glare;", "uniform bool rmfx_effect_streak;", "uniform bool rmfx_effect_ghost;"};
        auto expand = [&](const char* file, const char* builtin, Diagnostics& d) {
            ShaderInput input;
            input.root = input.folder = ws.folder;
            input.snippets = &ws.snippets;
            if (file) {
                std::filesystem::path path = ws.folder / file;
                input.code = readFile(path);
                input.start = {path.string(), 1};
                input.folder = path.parent_path();
                input.defines = defines;
                input.declarations = declarations;
            } else {
                input.code = builtin;
                input.start = {"<built-in vertex shader>", 1};
            }
            return preprocessShader(input, d).code;
        };
        Diagnostics d;
        std::string stages[2] = {expand(vertexFile, builtinVertex, d), expand(fragmentFile, nullptr, d)};
        if (hasErrors(d)) return Error{formatAll(d)};
        GLuint p = glCreateProgram();
        programs.push_back(p);
        for (int i = 0; i < 2; ++i) {
            GLuint shader = glCreateShader(i == 0 ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER);
            const char* text = stages[i].c_str();
            glShaderSource(shader, 1, &text, nullptr);
            glCompileShader(shader);
            GLint ok = 0;
            glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
            if (!ok) {
                char log[4096] = {};
                glGetShaderInfoLog(shader, sizeof log, nullptr, log);
                glDeleteShader(shader);
                return Error{std::string(i == 0 ? (vertexFile ? vertexFile : "built-in vertex shader") : fragmentFile) +
                             ": " + log};
            }
            glAttachShader(p, shader);
            glDeleteShader(shader);
        }
        glLinkProgram(p);
        GLint linked = 0;
        glGetProgramiv(p, GL_LINK_STATUS, &linked);
        if (!linked) return Error{std::string(fragmentFile) + ": link failed"};
        return p;
    }

    // A pass: uniforms the program does not use are dropped (GL removed them), sampler uniforms
    // get units 0, 1, … in the order given. Every active uniform must be given: a uniform left
    // out would make the frame differ from the executor's.
    Result<void> add(const std::string& name, GLuint framebuffer, glm::ivec2 size, GLuint program, const GlMesh& mesh,
                     HandPass states, std::vector<Uniform> uniforms, std::vector<Texture> textures) {
        HandPass p = states;
        p.framebuffer = framebuffer;
        p.width = size.x;
        p.height = size.y;
        p.program = program;
        p.mesh = &mesh;
        std::set<std::string> given;
        for (const Uniform& u : uniforms) {
            given.insert(u.name);
            GLint location = glGetUniformLocation(program, u.name);
            if (location < 0) continue;
            p.uniforms[p.uniformCount++] = {location, u.kind, u.data};
        }
        for (const Texture& t : textures) {
            given.insert(t.name);
            GLint location = glGetUniformLocation(program, t.name);
            if (location < 0) continue;
            glProgramUniform1i(program, location, p.textureCount);
            p.textures[p.textureCount] = t.texture;
            p.samplers[p.textureCount] = t.sampler;
            ++p.textureCount;
        }
        GLint active = 0;
        glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &active);
        for (GLint i = 0; i < active; ++i) {
            char uniform[256] = {};
            glGetActiveUniformName(program, static_cast<GLuint>(i), sizeof uniform, nullptr, uniform);
            if (!given.count(uniform)) return Error{"pass '" + name + "' leaves uniform '" + uniform + "' unset"};
        }
        passes.push_back(p);
        return {};
    }
};

HandWrittenShader5::HandWrittenShader5(std::unique_ptr<State> state) : state_(std::move(state)) {}
HandWrittenShader5::~HandWrittenShader5() = default;

Result<std::unique_ptr<HandWrittenShader5>> HandWrittenShader5::create(const Workspace& ws, glm::ivec2 viewport) {
    auto s = std::make_unique<State>();
    s->viewport = viewport;
    s->camera = OrbitCamera(ws.camera);
    FrameValues& v = s->values;
    auto value = [&](const char* name) -> Result<float> {
        const Variable* variable = ws.findVariable(name);
        if (!variable) return Error{ws.path.string() + " has no variable '" + name + "': is it shader_5?"};
        return variable->value.data[0];
    };
    for (auto [name, out] : {std::pair<const char*, float*>{"Exposure_Level", &v.exposure}, {"Glow_Factor", &v.glow[0]},
                             {"Glow_Factor2", &v.glow[1]}, {"Glow_Factor3", &v.glow[2]},
                             {"Streak_Factor", &v.streakFactor}, {"Ghost_Factor", &v.ghostFactor}}) {
        auto x = value(name);
        if (!x) return Error{x.error()};
        *out = *x;
    }
    auto format = value("Environment_Format");
    if (!format) return Error{format.error()};
    v.environmentFormat = static_cast<int>(*format);
    // Derived from <draw mesh="teapot"/> (no transform) as the executor does.
    v.model = glm::mat4(1.0f);
    v.normalMatrix = glm::inverseTranspose(glm::mat3(v.model));

    // Images.
    GLuint images[3] = {};
    const char* imageNames[3] = {"Sky_Alpha64", "Sky_Float", "Ghost_Mask"};
    for (int i = 0; i < 3; ++i) {
        const rmfx::Texture* spec = ws.findTexture(imageNames[i]);
        if (!spec) return Error{ws.path.string() + " has no texture '" + imageNames[i] + "'"};
        auto loaded = loadGlTexture(ws, *spec);
        if (!loaded) return Error{loaded.error()};
        images[i] = loaded->name;
        s->imageTextures.push_back(loaded->name);
    }
    const GLuint skyAlpha64 = images[0], skyFloat = images[1], ghostMask = images[2];

    // Targets: scene (with depth) and the screen at the viewport size, the rest at a quarter; all
    // rgba16f but the screen.
    glm::ivec2 quarter = (viewport + 3) / 4;
    v.inverseQuarterSize = 1.0f / glm::vec2(quarter);
    glCreateRenderbuffers(1, &s->sceneDepth);
    glNamedRenderbufferStorage(s->sceneDepth, GL_DEPTH_COMPONENT32F, viewport.x, viewport.y);
    GLuint scene = 0, glare[6] = {}, streak4[4] = {}, streak16[4] = {}, ghost[2] = {};
    GLuint sceneFb = s->target(viewport, &scene, s->sceneDepth);
    GLuint glareFb[6], streak4Fb[4], streak16Fb[4], ghostFb[2];
    for (int i = 0; i < 6; ++i) glareFb[i] = s->target(quarter, &glare[i]);
    for (int i = 0; i < 4; ++i) {
        streak4Fb[i] = s->target(quarter, &streak4[i]);
        streak16Fb[i] = s->target(quarter, &streak16[i]);
    }
    for (int i = 0; i < 2; ++i) ghostFb[i] = s->target(quarter, &ghost[i]);
    // The screen in the format of shader_5's <output>: the combine's additive blend into a half-float
    // screen rounds twice where the executor's rounds nowhere.
    GLuint outputFb = s->target(viewport, &s->outputTexture, 0, GL_RGBA32F);

    const GLuint linear = s->sampler(GL_LINEAR), nearest = s->sampler(GL_NEAREST);
    s->fullscreen = std::make_unique<GlMesh>(makeFullscreenTriangle());
    s->teapot = std::make_unique<GlMesh>(makeMesh(BuiltinMesh::Teapot));
    const GlMesh& triangle = *s->fullscreen;

    using K = UniformKind;
    const Uniform inverseViewProjection{"rm_InvViewProjection", K::Mat4, &v.inverseViewProjection};
    const Uniform exposure{"Exposure_Level", K::Float, &v.exposure};
    const Uniform cameraPosition{"rm_CameraPosition", K::Vec3, &v.cameraPosition};
    const Uniform environmentFormat{"Environment_Format", K::Int, &v.environmentFormat};
    const Uniform inverseTargetSize{"rm_InvTargetSize", K::Vec2, &v.inverseQuarterSize};
    HandPass plain;
    HandPass clearing;
    clearing.clear = true;
    HandPass depthTested;
    depthTested.depthTest = depthTested.depthWrite = depthTested.cullBack = true;
    HandPass additive;
    additive.blendAdd = true;

    auto program = [&](const char* vertexFile, const char* builtinVertex, const char* fragmentFile) -> Result<GLuint> {
        return s->program(ws, vertexFile, builtinVertex, fragmentFile);
    };
    const std::string fullscreenVertexText = builtinFullscreenVertexShader();
    const std::string modelVertexText = builtinModelVertexShader();
    const char* fullscreenVertex = fullscreenVertexText.c_str();
    std::vector<Result<void>> added;
    // One program per pass, as the executor compiles them: the driver sees the same objects.
    auto check = [&](Result<GLuint> p) -> GLuint {
        if (!p) {
            added.push_back(Error{p.error()});
            return 0;
        }
        return *p;
    };

    added.push_back(s->add("environment", sceneFb, viewport, check(program(nullptr, fullscreenVertex, "glsl/sky.frag")),
                           triangle, clearing,
                           {inverseViewProjection, exposure, cameraPosition, environmentFormat},
                           {{"Environment", skyAlpha64, linear}, {"Environment_Float", skyFloat, linear}}));
    added.push_back(s->add("teapot", sceneFb, viewport,
                           check(program(nullptr, modelVertexText.c_str(), "glsl/teapot.frag")), *s->teapot,
                           depthTested,
                           {{"rm_Model", K::Mat4, &v.model}, {"rm_ViewProjection", K::Mat4, &v.viewProjection},
                            {"rm_NormalMatrix", K::Mat3, &v.normalMatrix}, exposure, cameraPosition, environmentFormat},
                           {{"Environment", skyAlpha64, linear}, {"Environment_Float", skyFloat, linear}}));
    for (int i = 0; i < 6; ++i)
        added.push_back(s->add("glare_" + std::to_string(i + 1), glareFb[i], quarter,
                               check(program(nullptr, fullscreenVertex, "glsl/gauss9.frag")), triangle, plain,
                               {inverseViewProjection, inverseTargetSize},
                               {{"Texture0", i == 0 ? scene : glare[i - 1], linear}}));
    const char* streakNames[4] = {"dl", "dr", "ul", "ur"};
    for (int i = 0; i < 4; ++i)
        for (int second = 0; second < 2; ++second)
            added.push_back(s->add(std::string("streak_") + streakNames[i] + (second ? "_16" : "_4"),
                                   second ? streak16Fb[i] : streak4Fb[i], quarter,
                                   check(program(nullptr, fullscreenVertex, "glsl/streak.frag")), triangle, plain,
                                   {inverseViewProjection, inverseTargetSize, {"direction", K::Vec2, &v.directions[i]},
                                    {"offsetFactor", K::Float, &v.offsetFactors[second]}},
                                   {{"Texture0", second ? streak4[i] : scene, linear}}));
    for (int i = 0; i < 2; ++i)
        added.push_back(s->add("ghost_" + std::to_string(i + 1), ghostFb[i], quarter,
                               check(program("glsl/ghost.vert", nullptr, "glsl/ghost_combined.frag")), triangle, plain,
                               {{"Ghost_Factor", K::Float, &v.ghostFactor}},
                               {{"Texture0", i == 0 ? scene : ghost[0], linear}, {"Texture1", ghostMask, linear}}));
    added.push_back(s->add("screen", outputFb, viewport, check(program(nullptr, fullscreenVertex, "glsl/copy.frag")),
                           triangle, plain, {inverseViewProjection}, {{"Texture0", scene, nearest}}));
    added.push_back(s->add("combine", outputFb, viewport,
                           check(program(nullptr, fullscreenVertex, "glsl/all_combine.frag")), triangle, additive,
                           {inverseViewProjection, {"Glow_Factor", K::Float, &v.glow[0]},
                            {"Glow_Factor2", K::Float, &v.glow[1]}, {"Glow_Factor3", K::Float, &v.glow[2]},
                            {"Streak_Factor", K::Float, &v.streakFactor}, {"rmfx_effect_glare", K::Int, &v.effectOn},
                            {"rmfx_effect_streak", K::Int, &v.effectOn}, {"rmfx_effect_ghost", K::Int, &v.effectOn}},
                           {{"Texture0", ghost[1], linear}, {"Texture1", glare[3], linear}, {"Texture2", glare[4], linear},
                            {"Texture3", glare[5], linear}, {"Texture4", streak16[0], linear},
                            {"Texture5", streak16[1], linear}, {"Texture6", streak16[2], linear},
                            {"Texture7", streak16[3], linear}}));
    std::string errors;
    for (const Result<void>& r : added)
        if (!r) errors += (errors.empty() ? "" : "\n") + r.error();
    if (!errors.empty()) return Error{errors};
    if (GLenum e = glGetError(); e != GL_NO_ERROR) return Error{"GL error " + std::to_string(e) + " while setting up"};
    return std::unique_ptr<HandWrittenShader5>(new HandWrittenShader5(std::move(s)));
}

void HandWrittenShader5::renderFrame() {
    State& s = *state_;
    FrameValues& v = s.values;
    glm::mat4 view = s.camera.view();
    glm::mat4 projection = s.camera.projection(static_cast<float>(s.viewport.x) / static_cast<float>(s.viewport.y));
    v.viewProjection = projection * view;
    v.inverseViewProjection = glm::inverse(v.viewProjection);
    v.cameraPosition = s.camera.position();

    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    // As shader_5.xml's combine: colour added, the screen's alpha kept.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ZERO, GL_ONE);
    glBlendEquation(GL_FUNC_ADD);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    for (const HandPass& p : s.passes) {
        glBindFramebuffer(GL_FRAMEBUFFER, p.framebuffer);
        glViewport(0, 0, p.width, p.height);
        if (p.blendAdd) glEnable(GL_BLEND);
        else glDisable(GL_BLEND);
        if (p.depthTest) glEnable(GL_DEPTH_TEST);
        else glDisable(GL_DEPTH_TEST);
        if (p.cullBack) glEnable(GL_CULL_FACE);
        else glDisable(GL_CULL_FACE);
        if (p.clear) {
            const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f}, far = 1.0f;
            glClearNamedFramebufferfv(p.framebuffer, GL_COLOR, 0, black);
            glDepthMask(GL_TRUE);
            glClearNamedFramebufferfv(p.framebuffer, GL_DEPTH, 0, &far);
        }
        glDepthMask(p.depthWrite ? GL_TRUE : GL_FALSE);
        glUseProgram(p.program);
        for (int i = 0; i < p.uniformCount; ++i) {
            const HandUniform& u = p.uniforms[i];
            const float* f = static_cast<const float*>(u.data);
            switch (u.kind) {
                case UniformKind::Float: glProgramUniform1f(p.program, u.location, *f); break;
                case UniformKind::Int: glProgramUniform1i(p.program, u.location, *static_cast<const int*>(u.data)); break;
                case UniformKind::Vec2: glProgramUniform2fv(p.program, u.location, 1, f); break;
                case UniformKind::Vec3: glProgramUniform3fv(p.program, u.location, 1, f); break;
                case UniformKind::Mat3: glProgramUniformMatrix3fv(p.program, u.location, 1, GL_FALSE, f); break;
                case UniformKind::Mat4: glProgramUniformMatrix4fv(p.program, u.location, 1, GL_FALSE, f); break;
            }
        }
        for (int i = 0; i < p.textureCount; ++i) {
            glBindTextureUnit(static_cast<GLuint>(i), p.textures[i]);
            glBindSampler(static_cast<GLuint>(i), p.samplers[i]);
        }
        p.mesh->draw();  // glBindVertexArray, glDrawElements
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

unsigned HandWrittenShader5::outputTexture() const { return state_->outputTexture; }
int HandWrittenShader5::passCount() const { return static_cast<int>(state_->passes.size()); }

}  // namespace rmfx::bench
