#include "gl/GlHealthCheck.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>

#include <epoxy/gl.h>

#include "gl/GlFullScreenTriangle.h"

namespace rmfx {
namespace {

constexpr int kMaxInputs = 8;
// The unit the inspected target is bound to: above those a pass's samplers use.
constexpr GLuint kTargetUnit = 31;

// Two storage buffers: per pass and kind, its count and first pixel (binding 0), and what the pixel
// draw found there (binding 1). Mirror the std430 blocks of the shaders below.
struct PassEntry {
    std::int32_t count;
    std::int32_t first;
};
struct PixelRecord {
    std::int32_t pixel;
    std::int32_t padding[3];
    float value[4];
    float inputs[kMaxInputs][4];
};
static_assert(sizeof(PixelRecord) == 160);

#define RMFX_HEALTH_BLOCK                                                         \
    "struct Entry { int count; int first; };\n"                                  \
    "struct Record { int pixel; int pad0; int pad1; int pad2; vec4 value; vec4 inputs[8]; };\n" \
    "layout(std430, binding = 0) buffer Entries { Entry entries[]; };\n"         \
    "layout(std430, binding = 1) buffer Records { Record records[]; };\n"

// Fragment shaders drawn over an attachment-less framebuffer: a compute dispatch costs about a
// millisecond on llvmpipe whatever it does, a draw a fraction of that.

// One fragment per pixel of the target: which kinds its channels hold. The first pixel is the
// smallest index in reading order (row 0 at the top: GL's rows counted from the bottom are flipped).
const char* const reduceSource = "#version 450 core\n" RMFX_HEALTH_BLOCK R"(
uniform sampler2D Target;
uniform int Position;
uniform int Channels;
uniform bool Negatives;
uniform vec4 Largest;
void record(int kind, int pixel) {
    atomicAdd(entries[Position * 5 + kind].count, 1);
    atomicMin(entries[Position * 5 + kind].first, pixel);
}
void main() {
    ivec2 size = textureSize(Target, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 v = texelFetch(Target, p, 0);
    bool nan = false, positiveInf = false, negativeInf = false, negative = false, atLargest = false;
    for (int c = 0; c < Channels; ++c) {
        float x = v[c];
        if (isnan(x)) nan = true;
        else if (isinf(x)) { if (x > 0.0) positiveInf = true; else negativeInf = true; }
        else {
            if (Negatives && x < 0.0) negative = true;
            if (Largest[c] > 0.0 && abs(x) >= Largest[c]) atLargest = true;
        }
    }
    int pixel = (size.y - 1 - p.y) * size.x + p.x;
    if (nan) record(0, pixel);
    if (positiveInf) record(1, pixel);
    if (negativeInf) record(2, pixel);
    if (negative) record(3, pixel);
    if (atLargest) record(4, pixel);
}
)";

// One fragment per kind (a 5x1 viewport): where a pass holds the kind, the first pixel's value and
// its inputs' texels there, in the pass's own record (the frame's first pass is chosen on reading).
const char* const fetchSource = "#version 450 core\n" RMFX_HEALTH_BLOCK R"(
uniform sampler2D Target;
uniform sampler2D Inputs[8];
uniform int InputCount;
uniform int Position;
void main() {
    int kind = int(gl_FragCoord.x);
    int slot = Position * 5 + kind;
    Entry e = entries[slot];
    if (e.count == 0) return;
    ivec2 size = textureSize(Target, 0);
    ivec2 p = ivec2(e.first % size.x, size.y - 1 - e.first / size.x);
    records[slot].pixel = e.first;
    records[slot].value = texelFetch(Target, p, 0);
    vec2 centre = (vec2(p) + 0.5) / vec2(size);
    for (int i = 0; i < InputCount; ++i) {
        ivec2 s = textureSize(Inputs[i], 0);
        records[slot].inputs[i] = texelFetch(Inputs[i], clamp(ivec2(centre * vec2(s)), ivec2(0), s - 1), 0);
    }
}
)";

Result<ProgramHandle> fullScreenProgram(const char* fragment, const char* what) {
    ProgramHandle program = createProgram();
    for (const auto& [type, source] : {std::pair{GL_VERTEX_SHADER, fullScreenTriangleVertexSource()}, {GL_FRAGMENT_SHADER, fragment}}) {
        ShaderHandle shader = createShader(type);
        glShaderSource(shader.get(), 1, &source, nullptr);
        glCompileShader(shader.get());
        GLint compiled = 0;
        glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &compiled);
        if (!compiled) {
            char log[2048] = {};
            glGetShaderInfoLog(shader.get(), sizeof log, nullptr, log);
            return Error{std::string("--check: the ") + what + " shader does not compile: " + log};
        }
        glAttachShader(program.get(), shader.get());
    }
    glLinkProgram(program.get());
    GLint ok = 0;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) return Error{std::string("--check: the ") + what + " shader does not link"};
    return program;
}

}  // namespace

Result<std::unique_ptr<GlHealthCheck>> GlHealthCheck::create() {
    std::unique_ptr<GlHealthCheck> check(new GlHealthCheck);
    auto reduce = fullScreenProgram(reduceSource, "health-count");
    if (!reduce) return Error{reduce.error()};
    auto fetch = fullScreenProgram(fetchSource, "health-pixel");
    if (!fetch) return Error{fetch.error()};
    check->reduce_ = std::move(*reduce);
    check->fetch_ = std::move(*fetch);
    const GLuint r = check->reduce_.get(), f = check->fetch_.get();
    glProgramUniform1i(r, glGetUniformLocation(r, "Target"), static_cast<GLint>(kTargetUnit));
    glProgramUniform1i(f, glGetUniformLocation(f, "Target"), static_cast<GLint>(kTargetUnit));
    check->reducePosition_ = glGetUniformLocation(r, "Position");
    check->reduceChannels_ = glGetUniformLocation(r, "Channels");
    check->reduceNegatives_ = glGetUniformLocation(r, "Negatives");
    check->reduceLargest_ = glGetUniformLocation(r, "Largest");
    check->fetchPosition_ = glGetUniformLocation(f, "Position");
    check->fetchInputCount_ = glGetUniformLocation(f, "InputCount");
    check->fetchInputs_ = glGetUniformLocation(f, "Inputs");
    check->empty_ = createFramebuffer();
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &check->maxSize_.x);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &check->maxSize_.y);
    check->vertexArray_ = createVertexArray();
    return check;
}

void GlHealthCheck::growBuffer(size_t passes) {
    if (entries_.get() && passes <= capacity_) return;
    capacity_ = std::max<size_t>(passes, 16);
    entries_ = createBuffer();
    glNamedBufferStorage(entries_.get(), static_cast<GLsizeiptr>(capacity_ * healthKindCount * sizeof(PassEntry)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    records_ = createBuffer();
    glNamedBufferStorage(records_.get(), static_cast<GLsizeiptr>(capacity_ * healthKindCount * sizeof(PixelRecord)), nullptr, 0);
}

void GlHealthCheck::beginFrame(int frame, size_t passes) {
    frame_ = frame;
    growBuffer(passes);
    passes_.assign(passes, PassHealth{});
    inputLabels_.assign(passes, {});
    widths_.assign(passes, 0);
    pending_.clear();
    std::vector<PassEntry> initial(passes * healthKindCount, PassEntry{0, INT_MAX});
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (!initial.empty())
        glNamedBufferSubData(entries_.get(), 0, static_cast<GLsizeiptr>(initial.size() * sizeof(PassEntry)), initial.data());
}

void GlHealthCheck::bindCommonState() {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, entries_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, records_.get());
    glBindFramebuffer(GL_FRAMEBUFFER, empty_.get());
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(vertexArray_.get());
}

void GlHealthCheck::drawCount(const Inspection& i) {
    // Changed only when the size does: each change makes the driver validate the framebuffer again
    // (and a framebuffer larger than the draw costs llvmpipe its whole area).
    const glm::ivec2 defaultSize{std::max(i.size.x, healthKindCount), i.size.y};
    if (defaultSize != emptySize_) {
        glNamedFramebufferParameteri(empty_.get(), GL_FRAMEBUFFER_DEFAULT_WIDTH, defaultSize.x);
        glNamedFramebufferParameteri(empty_.get(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, defaultSize.y);
        emptySize_ = defaultSize;
    }
    glBindTextureUnit(kTargetUnit, i.texture);
    glBindSampler(kTargetUnit, 0);
    glViewport(0, 0, i.size.x, i.size.y);
    glUseProgram(reduce_.get());
    glUniform1i(reducePosition_, static_cast<GLint>(i.position));
    glUniform1i(reduceChannels_, i.limits.channels);
    glUniform1i(reduceNegatives_, i.limits.holdsNegatives ? 1 : 0);
    glUniform4f(reduceLargest_, i.limits.largest.x, i.limits.largest.y, i.limits.largest.z, i.limits.largest.w);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GlHealthCheck::drawPixel(const Inspection& i) {
    glBindTextureUnit(kTargetUnit, i.texture);
    glUseProgram(fetch_.get());
    GLint units[kMaxInputs] = {};
    const int count = std::min(static_cast<int>(i.inputs.size()), kMaxInputs);
    for (int k = 0; k < kMaxInputs; ++k) {
        units[k] = static_cast<GLint>(kTargetUnit);
        if (k >= count) continue;
        const Input& input = i.inputs[static_cast<size_t>(k)];
        units[k] = k;
        glBindTextureUnit(static_cast<GLuint>(k), input.texture);
        glBindSampler(static_cast<GLuint>(k), 0);
    }
    glUniform1iv(fetchInputs_, kMaxInputs, units);
    glUniform1i(fetchInputCount_, count);
    glUniform1i(fetchPosition_, static_cast<GLint>(i.position));
    glViewport(0, 0, healthKindCount, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GlHealthCheck::afterPass(size_t position, const std::string& pass, const std::string& target, unsigned texture,
                              glm::ivec2 size, TargetFormat format, const std::vector<Input>& inputs) {
    if (position >= passes_.size()) return;
    PassHealth& health = passes_[position];
    health.pass = pass;
    health.target = target;
    const FormatHealthLimits limits = formatHealthLimits(format);
    health.inspected = limits.inspected;
    if (!limits.inspected || texture == 0 || size.x <= 0 || size.y <= 0 || size.x > maxSize_.x || size.y > maxSize_.y)
        return;
    widths_[position] = size.x;
    Inspection inspection{position, texture, size, limits, {}};
    for (size_t k = 0; k < inputs.size() && k < static_cast<size_t>(kMaxInputs); ++k) {
        inputLabels_[position].push_back(inputs[k].label);
        inspection.inputs.push_back(inputs[k]);
    }
    pending_.push_back(std::move(inspection));
}

void GlHealthCheck::beforeWriting(unsigned texture) {
    for (const Inspection& i : pending_) {
        bool read = i.texture == texture;
        for (const Input& input : i.inputs) read = read || input.texture == texture;
        if (read) {
            inspectPending();
            return;
        }
    }
}

void GlHealthCheck::inspectPending() {
    if (pending_.empty()) return;
    // None of the count draws waits for another; one barrier orders them all before the pixel draws.
    bindCommonState();
    for (const Inspection& i : pending_) drawCount(i);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (const Inspection& i : pending_) drawPixel(i);
    glBindVertexArray(0);
    glBindTextureUnit(kTargetUnit, 0);
    pending_.clear();
}

FrameHealth GlHealthCheck::endFrame() {
    inspectPending();
    FrameHealth frame;
    const size_t passes = passes_.size();
    std::vector<PassEntry> entries(passes * healthKindCount);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (!entries.empty())
        glGetNamedBufferSubData(entries_.get(), 0, static_cast<GLsizeiptr>(entries.size() * sizeof(PassEntry)), entries.data());
    for (size_t p = 0; p < passes; ++p)
        for (int k = 0; k < healthKindCount; ++k)
            passes_[p].counts[static_cast<size_t>(k)] = entries[p * healthKindCount + static_cast<size_t>(k)].count;
    for (int k = 0; k < healthKindCount; ++k) {
        size_t first = passes;
        for (size_t p = 0; p < passes && first == passes; ++p)
            if (passes_[p].counts[static_cast<size_t>(k)] > 0) first = p;
        if (first == passes) continue;
        PixelRecord record{};
        glGetNamedBufferSubData(records_.get(), static_cast<GLintptr>((first * healthKindCount + static_cast<size_t>(k)) * sizeof record),
                                sizeof record, &record);
        const PassHealth& p = passes_[first];
        HealthFinding finding;
        finding.kind = allHealthKinds[static_cast<size_t>(k)];
        finding.frame = frame_;
        finding.pass = p.pass;
        finding.target = p.target;
        finding.count = p.counts[static_cast<size_t>(k)];
        const int width = std::max(1, widths_[first]);
        finding.pixel = glm::ivec2(record.pixel % width, record.pixel / width);
        finding.value = glm::vec4(record.value[0], record.value[1], record.value[2], record.value[3]);
        const auto& labels = inputLabels_[first];
        for (size_t i = 0; i < labels.size(); ++i)
            finding.inputs.push_back({labels[i], glm::vec4(record.inputs[i][0], record.inputs[i][1], record.inputs[i][2],
                                                           record.inputs[i][3])});
        frame.findings.push_back(std::move(finding));
    }
    frame.passes = passes_;
    return frame;
}

}  // namespace rmfx
