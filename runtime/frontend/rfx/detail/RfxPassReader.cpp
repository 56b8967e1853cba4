#include "frontend/rfx/detail/RfxPassReader.h"

#include <algorithm>
#include <map>
#include <set>
#include <string_view>

#include "core/IdentifierSearch.h"
#include "frontend/rfx/detail/RfxAssemblyShader.h"
#include "frontend/rfx/detail/RfxPackedColor.h"
#include "frontend/rfx/detail/RfxRenderStates.h"
#include "frontend/rfx/detail/RfxSamplerStates.h"
#include "frontend/rfx/detail/RfxTextureStageStates.h"
#include "frontend/rfx/detail/RfxShaderCode.h"
#include "frontend/shader/HlslGlobalInitializers.h"
#include "frontend/shader/HlslSemantics.h"

namespace rmfx::rfx {
namespace {

using tinyxml2::XMLElement;

template <class T, class Member>
const T* findIn(const std::vector<const Declarations*>& levels, Member member, const std::string& name) {
    for (const Declarations* d : levels)
        for (const T& item : d->*member)
            if (item.name == name) return &item;
    return nullptr;
}

class PassReader {
public:
    PassReader(const RfxElement& e, RfxApi api, const VisibleScopes& scopes, HlslMatrixOrder hlslMatrices,
               const std::map<const XMLElement*, HlslMatrixOrder>& shaderOrders)
        : e_(e), api_(api), hlslMatrices_(hlslMatrices), shaderOrders_(shaderOrders) {
        // What the pass declares itself comes first: RenderMonkey let a pass hold its own
        // texture variables, renderable textures, models and stream maps.
        scopes_.levels.push_back(&out_.declared);
        scopes_.levels.insert(scopes_.levels.end(), scopes.levels.begin(), scopes.levels.end());
    }

    std::optional<ReadPass> read() {
        auto index = e_.integer("PASS_INDEX", -1000000, 1000000);
        auto enabled = e_.flag("ENABLED", false);
        out_.pass.name = e_.text("NAME").value_or("");
        out_.pass.where = e_.where();
        out_.pass.enabled = enabled.value_or(true);
        out_.index = index.value_or(0);
        // Declarations first, wherever they stand: shaders and texture objects before them use them.
        std::set<const XMLElement*> declarations;
        for (const XMLElement* c = e_.xml()->FirstChildElement(); c; c = c->NextSiblingElement())
            if (readDeclaration(at(c), passLevel_)) {
                takePassDeclarations();
                declarations.insert(c);
            }
        for (const XMLElement* c = e_.xml()->FirstChildElement(); c; c = c->NextSiblingElement())
            if (!declarations.count(c)) child(c);
        // After the children: an assembly shader reads variables, texture objects and the stream
        // map that RenderMonkey writes after it.
        for (const RfxElement& c : assemblyShaders_) assemblyShader(c);
        bindStreams();
        checkConstants();
        for (ReadPass::SamplerWithoutObject& sampler : samplersWithoutObject_) {
            sampler.used = std::any_of(out_.pass.shaders.begin(), out_.pass.shaders.end(),
                                       [&](const ShaderSource& s) { return mentionsIdentifier(s.code, sampler.name); });
            out_.samplersWithoutObject.push_back(std::move(sampler));
        }
        if (!index) return std::nullopt;
        return out_;
    }

private:
    RfxElement at(const XMLElement* x) const { return RfxElement(x, e_.file(), e_.diagnostics()); }

    void child(const XMLElement* x) {
        RfxElement c = at(x);
        std::string_view tag = x->Name();
        if (tag == "RmGLShader" || tag == "RmGLESShader" || tag == "RmHLSLShader") {
            shader(c, tag);
        } else if (tag == "RmShader" && api_ == RfxApi::Direct3D) {
            assemblyShaders_.push_back(c);
            constantsOf(c, pixelShader(c));
        } else if (tag == "RmShader") {
            c.warning("an assembly shader: rmfx compiles only HLSL and GLSL, so this pass cannot run");
            out_.runnable = false;
            out_.whyNotRunnable = "its " + std::string(pixelShader(c) ? "pixel" : "vertex") + " shader " + c.label() +
                                  " (line " + std::to_string(c.line()) + ") is assembly";
            constantsOf(c, pixelShader(c));
        } else if (tag == "RmRenderStateBlock") {
            out_.stateBlocks.push_back(x);
        } else if (tag == "RmRenderTarget") {
            renderTarget(c);
        } else if (tag == "RmModelReference") {
            if (const ModelDeclaration* m = scopes_.model(c.name())) {
                out_.pass.draw.file = m->file;
                out_.pass.draw.where = c.where();
            } else {
                c.error("no <RmModelData NAME=\"" + c.name() + "\"> is visible from the pass");
            }
        } else if (tag == "RmStreamMapReference") {
            streamMap_ = scopes_.streamMap(c.name());
            if (!streamMap_) c.error("no <RmStreamMap NAME=\"" + c.name() + "\"> is visible from the pass");
        } else if (tag == "RmTextureObject") {
            textureObject(c);
        } else if (tag == "RmSampler") {
            sampler(c, true);
        } else if (tag == "RmShaderConstant") {
            constant(c);
        } else if (tag == "RmCameraReference") {
            // Checked by the importer, which knows the effect's cameras and which one is active.
            out_.pass.camera = c.name();
            out_.pass.cameraWhere = c.where();
        } else if (tag == "RmPlugInData") {
            // the effect's camera is the only one rmfx has; plug-in data is editor state
        } else {
            c.warning("rmfx does not support <" + std::string(tag) + "> in a pass; ignored");
        }
    }

    // Variables become pass constants; the rest is the pass's own, looked up before the effect's.
    void takePassDeclarations() {
        for (Variable& v : passLevel_.variables) out_.pass.constants.push_back(std::move(v));
        auto take = [](auto& from, auto& into) {
            for (auto& item : from) into.push_back(std::move(item));
        };
        take(passLevel_.textures, out_.declared.textures);
        take(passLevel_.targets, out_.declared.targets);
        take(passLevel_.models, out_.declared.models);
        take(passLevel_.streamMaps, out_.declared.streamMaps);
        take(passLevel_.unsupported, out_.declared.unsupported);
        passLevel_ = {};
    }

    static bool pixelShader(const RfxElement& c) { return c.flag("PIXEL_SHADER", false).value_or(false); }

    void shader(const RfxElement& c, std::string_view tag) {
        ShaderSource s;
        auto pixel = c.flag("PIXEL_SHADER");
        s.stage = pixel.value_or(false) ? ShaderStage::Fragment : ShaderStage::Vertex;
        s.where = c.where();
        if (tag == "RmGLShader") {
            // Desktop GLSL of any version runs in the compatibility profile, which accepts
            // #version 110 through 4.x and the fixed-function built-ins: one dialect for all.
            s.dialect = ShaderDialect::GlslLegacy;
        } else if (tag == "RmGLESShader") {
            s.dialect = ShaderDialect::GlslEs100;
        } else {
            s.dialect = ShaderDialect::Hlsl;
            s.entryPoint = c.text("ENTRY_POINT").value_or("main");
            s.profile = c.text("TARGET").value_or("");
            const auto own = shaderOrders_.find(c.xml());
            s.matrixOrder = own != shaderOrders_.end() ? own->second : hlslMatrices_;
            constantsOf(c, pixelShader(c));
            for (const XMLElement* x = c.xml()->FirstChildElement("RmShaderConstant"); x; x = x->NextSiblingElement("RmShaderConstant"))
                if (const char* name = x->Attribute("NAME")) s.constantTable.emplace_back(name);
        }
        std::optional<RfxShaderCode> code = shaderCodeOf(c);
        if (!code) return;
        s.code = std::move(code->code);
        s.codeLine = code->line;
        if (!pixel) return;
        for (const ShaderSource& other : out_.pass.shaders)
            if (other.stage == s.stage) {
                c.error(std::string("the pass already has a ") + (pixel.value() ? "pixel" : "vertex") + " shader (line " +
                        std::to_string(other.where.line) + ")");
                return;
            }
        out_.pass.shaders.push_back(std::move(s));
    }

    void assemblyShader(const RfxElement& c) {
        AssemblyContext context;
        context.variable = [this](const std::string& name) -> const Variable* {
            for (const Variable& v : out_.pass.constants)
                if (v.name == name) return &v;
            return scopes_.variable(name);
        };
        for (const auto& [name, stage] : objectStages_) {
            d3dasm::SamplerKind kind = d3dasm::SamplerKind::Texture2D;
            if (const Texture* t = scopes_.texture(textureOf_[name]); t && t->kind == TextureKind::Cube)
                kind = d3dasm::SamplerKind::Cube;
            d3dasm::SamplerBinding binding{name, stage, kind};
            if (auto st = stageStates_.find(name); st != stageStates_.end()) {
                binding.bumpMatrix = st->second.bumpMatrix;
                binding.bumpScale = st->second.bumpScale;
                binding.bumpOffset = st->second.bumpOffset;
            }
            context.samplers.push_back(binding);
        }
        if (streamMap_)
            for (size_t i = 0; i < streamMap_->streams.size() && i < streamMap_->registers.size(); ++i)
                if (streamMap_->registers[i] >= 0)
                    context.streams.push_back({streamMap_->registers[i], streamSemantic(streamMap_->streams[i])});
        context.passEnabled = out_.pass.enabled;
        std::string why;
        std::optional<ShaderSource> s = readAssemblyShader(c, context, why);
        if (!s) {
            if (out_.runnable) out_.whyNotRunnable = why;
            out_.runnable = false;
            return;
        }
        for (const ShaderSource& other : out_.pass.shaders)
            if (other.stage == s->stage) {
                c.error(std::string("the pass already has a ") + (s->stage == ShaderStage::Fragment ? "pixel" : "vertex") +
                        " shader (line " + std::to_string(other.where.line) + ")");
                return;
            }
        out_.pass.shaders.push_back(std::move(*s));
    }

    // "TEXCOORD1" for the texture coordinates of index 1.
    static std::string streamSemantic(const VertexStream& stream) {
        std::string name = hlslVertexInputName(stream.usage, stream.usageIndex);
        const std::string prefix = "rm_hlsl_in_";
        return name.rfind(prefix, 0) == 0 ? name.substr(prefix.size()) : name;
    }

    // RmShaderConstant and RmSampler children of a D3D shader.
    void constantsOf(const RfxElement& c, bool pixel) {
        for (const XMLElement* x = c.xml()->FirstChildElement(); x; x = x->NextSiblingElement()) {
            std::string_view tag = x->Name();
            if (tag == "RmShaderConstant") constant(at(x));
            else if (tag == "RmSampler") sampler(at(x), pixel);
        }
    }

    // Checked once the pass's shaders are known: RenderMonkey keeps constants that name nothing
    // (left over from edits); they matter only when a shader uses the name.
    void constant(const RfxElement& c) { constants_.push_back(c); }

    void checkConstants() {
        for (const RfxElement& c : constants_) {
            std::string name = c.name();
            bool passLevel = std::any_of(out_.pass.constants.begin(), out_.pass.constants.end(),
                                         [&](const Variable& v) { return v.name == name; });
            if (passLevel || scopes_.variable(name) || scopes_.texture(name)) continue;
            bool used = std::any_of(out_.pass.shaders.begin(), out_.pass.shaders.end(),
                                    [&](const ShaderSource& s) { return mentionsIdentifier(s.code, name); });
            std::string message = "no variable '" + name + "' is visible from the pass (pass, effect, group or workspace)";
            if (!used) c.warning(message + "; its shaders do not use it, so it is ignored");
            else if (api_ != RfxApi::Direct3D) c.error(message);
            // Direct3D ran a shader whatever its constant table held: a shader constant keeps the
            // value its declaration gives, a constant register nothing set held zero.
            else if (declaresConstant(name))
                c.warning(message + "; the shader declares it const, with its own value, which it keeps");
            else if (declaresInitialValue(name))
                c.warning(message + "; the shader declares it with an initial value, which Direct3D kept and so does rmfx");
            else
                c.warning(message + "; Direct3D ran with its constant register unset, so it is fed zero");
        }
    }

    // Whether an HLSL shader of the pass gives global `name` a constant initial value (`float k = 1.0 / 64.0;`).
    bool declaresInitialValue(const std::string& name) const {
        for (const ShaderSource& s : out_.pass.shaders) {
            if (s.dialect != ShaderDialect::Hlsl || !mentionsIdentifier(s.code, name)) continue;
            for (const HlslGlobalInitializer& init : findHlslGlobalInitializers(s.code))
                if (init.name == name && init.constant) return true;
        }
        return false;
    }

    // Whether a shader of the pass declares `name` const (`static const float2 o[12] = …`).
    bool declaresConstant(const std::string& name) const {
        for (const ShaderSource& s : out_.pass.shaders) {
            for (size_t at = s.code.find(name); at != std::string::npos; at = s.code.find(name, at + 1)) {
                const size_t statement = s.code.find_last_of(";{}", at);
                const std::string before = s.code.substr(statement == std::string::npos ? 0 : statement + 1,
                                                         at - (statement == std::string::npos ? 0 : statement + 1));
                if (mentionsIdentifier(before, "const") && mentionsIdentifier(s.code.substr(at, name.size() + 1), name))
                    return true;
            }
        }
        return false;
    }

    void sampler(const RfxElement& c, bool pixel) {
        std::string name = c.name();
        if (textureObjects_.count(name)) return;
        for (const ReadPass::SamplerWithoutObject& known : samplersWithoutObject_)
            if (known.name == name) return;
        ReadPass::SamplerWithoutObject s{name, std::nullopt, c.xml(), false};
        if (auto reg = c.integer("REGISTER", 0, 15, false)) s.stage = d3dSamplerStage(static_cast<int>(*reg), !pixel);
        samplersWithoutObject_.push_back(std::move(s));
    }

    void textureObject(const RfxElement& c) {
        Sampler s;
        s.uniform = c.name();
        s.where = c.where();
        // The sampler has its object, even one whose texture is reported missing below.
        textureObjects_.insert(s.uniform);
        if (auto stage = c.integer("STATE_INDEX", 0, 15, false)) objectStages_[s.uniform] = static_cast<int>(*stage);
        std::erase_if(samplersWithoutObject_, [&](const auto& p) { return p.name == s.uniform; });
        const XMLElement* ref = c.xml()->FirstChildElement("RmTextureReference");
        if (!ref) {
            c.error("it has no <RmTextureReference> naming the texture it binds");
            return;
        }
        std::string texture = at(ref).name();
        textureOf_[s.uniform] = texture;
        bool mipmaps = true;
        if (scopes_.texture(texture)) {
            s.texture = texture;
        } else if (const RenderTarget* t = scopes_.target(texture)) {
            s.target = texture;
            mipmaps = t->mipmaps;
        } else if (const UnsupportedDeclaration* u = scopes_.unsupported(texture)) {
            at(ref).error("'" + texture + "' is " + u->what + " (line " + std::to_string(u->where.line) +
                          "), which rmfx does not have: this pass cannot be imported");
            return;
        } else {
            at(ref).error("no texture variable or renderable texture '" + texture + "' is visible from the pass");
            return;
        }
        SamplerStates states(api_ == RfxApi::Direct3D, mipmaps);
        for (const XMLElement* x = c.xml()->FirstChildElement("RmState"); x; x = x->NextSiblingElement("RmState")) {
            if (api_ != RfxApi::Direct3D) states.applyGl(at(x));
            else if (at(x).text("USAGE", false).value_or("") == "TEXTURE_STATE")
                applyTextureStageState(at(x), objectStages_.count(s.uniform) ? objectStages_[s.uniform] : 0,
                                       stageStates_[s.uniform]);
            else states.applyD3d(at(x));
        }
        states.finish(c, s);
        if (auto stage = objectStages_.find(s.uniform); stage != objectStages_.end())
            out_.stageObjects[d3dSamplerStage(stage->second, c.flag("VERTEX_TEXTURE", false).value_or(false))] = s;
        out_.pass.samplers.push_back(std::move(s));
    }

    void renderTarget(const RfxElement& c) {
        if (targetSeen_) {
            c.warning("a second render target (multiple render targets): rmfx passes write one; ignored");
            return;
        }
        targetSeen_ = true;
        if (auto index = c.integer("INDEX", 0, 15, false); index && *index != 0)
            c.warning("INDEX " + std::to_string(*index) + ": written as the pass's only target");
        bool screen = c.flag("RENDER_TO_SCREEN", false).value_or(false);
        if (!screen) {
            if (!scopes_.target(c.name())) {
                c.error("no <RmRenderableTexture NAME=\"" + c.name() + "\"> is visible from the pass");
                return;
            }
            out_.pass.target = c.name();
        }
        if (c.flag("COLOR_CLEAR", false).value_or(false)) {
            if (auto packed = c.integer("CLEAR_COLOR_VALUE", -2147483648LL, 4294967295LL))
                out_.pass.clear.color = unpackArgb(*packed);
        }
        if (c.flag("DEPTH_CLEAR", false).value_or(false)) {
            if (auto depth = c.number("DEPTH_CLEAR_VALUE")) {
                if (*depth < 0 || *depth > 1) c.error("DEPTH_CLEAR_VALUE must be within 0…1");
                else out_.pass.clear.depth = *depth;
            }
        }
    }

    // Streams feed named attributes in OpenGL ES, and in OpenGL only when the vertex shader
    // declares an attribute of that name (RenderMonkey feeds gl_Vertex, gl_Normal… otherwise).
    // In Direct3D they feed the vertex shader's input of that usage (TEXCOORD1, TANGENT0…), which
    // the HLSL translator names by hlslVertexInputName.
    void bindStreams() {
        if (!streamMap_) return;
        const ShaderSource* vertex = nullptr;
        for (const ShaderSource& s : out_.pass.shaders)
            if (s.stage == ShaderStage::Vertex) vertex = &s;
        for (VertexStream stream : streamMap_->streams) {
            if (api_ == RfxApi::Direct3D) stream.attribute = hlslVertexInputName(stream.usage, stream.usageIndex);
            if (api_ == RfxApi::OpenGL && !(vertex && declaresVertexInput(vertex->code, stream.attribute)))
                stream.attribute.clear();
            out_.pass.streams.push_back(std::move(stream));
        }
    }

    const RfxElement& e_;
    RfxApi api_;
    HlslMatrixOrder hlslMatrices_;
    const std::map<const XMLElement*, HlslMatrixOrder>& shaderOrders_;
    ReadPass out_;
    VisibleScopes scopes_;  // the pass's own declarations (out_.declared), then the levels above
    Declarations passLevel_;
    const StreamMapDeclaration* streamMap_ = nullptr;
    bool targetSeen_ = false;
    std::vector<ReadPass::SamplerWithoutObject> samplersWithoutObject_;
    std::set<std::string> textureObjects_;
    std::vector<RfxElement> constants_;
    std::vector<RfxElement> assemblyShaders_;
    std::map<std::string, int> objectStages_;         // texture object → STATE_INDEX (its sampler stage)
    std::map<std::string, std::string> textureOf_;    // texture object → the texture it binds
    std::map<std::string, TextureStageStates> stageStates_;  // texture object → its texture stage states
};

}  // namespace

const Variable* VisibleScopes::variable(const std::string& name) const {
    return findIn<Variable>(levels, &Declarations::variables, name);
}
const Texture* VisibleScopes::texture(const std::string& name) const {
    return findIn<Texture>(levels, &Declarations::textures, name);
}
const RenderTarget* VisibleScopes::target(const std::string& name) const {
    return findIn<RenderTarget>(levels, &Declarations::targets, name);
}
const UnsupportedDeclaration* VisibleScopes::unsupported(const std::string& name) const {
    return findIn<UnsupportedDeclaration>(levels, &Declarations::unsupported, name);
}
const StreamMapDeclaration* VisibleScopes::streamMap(const std::string& name) const {
    return findIn<StreamMapDeclaration>(levels, &Declarations::streamMaps, name);
}
const ModelDeclaration* VisibleScopes::model(const std::string& name) const {
    return findIn<ModelDeclaration>(levels, &Declarations::models, name);
}

std::optional<ReadPass> readPass(const RfxElement& e, RfxApi api, const VisibleScopes& scopes, HlslMatrixOrder hlslMatrices,
                                 const std::map<const XMLElement*, HlslMatrixOrder>& shaderOrders) {
    return PassReader(e, api, scopes, hlslMatrices, shaderOrders).read();
}

}  // namespace rmfx::rfx
