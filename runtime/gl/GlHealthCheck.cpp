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

// The storage buffer: the first finding of each kind, then (count, first pixel) per pass and kind.
// Mirrors the std430 block of the shaders below.
struct FirstRecord {
    std::int32_t pass;
    std::int32_t pixel;
    std::int32_t padding[2];
    float value[4];
    float inputs[kMaxInputs][4];
};
static_assert(sizeof(FirstRecord) == 160);
struct PassEntry {
    std::int32_t count;
    std::int32_t first;
};
constexpr size_t kFirstsBytes = sizeof(FirstRecord) * healthKindCount;

#define RMFX_HEALTH_BLOCK                                                               \
    "struct First { int pass; int pixel; int pad0; int pad1; vec4 value; vec4 inputs[8]; };\n" \
    "struct Entry { int count; int first; };\n"                                         \
    "layout(std430, binding = 0) buffer Health { First firsts[5]; Entry entries[]; };\n"

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
    // Counted by the occlusion query that lets the pixel draw below run only where a kind was found.
    if (!(nan || positiveInf || negativeInf || negative || atLargest)) discard;
}
)";

// One fragment per kind (a 5x1 viewport): the first pass of the frame to hold it records where and what.
// Drawn under conditional rendering on the count draw's occlusion query, without waiting for it:
// drawn or not when nothing was found, it changes nothing.
const char* const fetchSource = "#version 450 core\n" RMFX_HEALTH_BLOCK R"(
uniform sampler2D Target;
uniform sampler2D Inputs[8];
uniform int InputCount;
uniform int Position;
void main() {
    int kind = int(gl_FragCoord.x);
    Entry e = entries[Position * 5 + kind];
    if (e.count == 0) return;
    if (atomicCompSwap(firsts[kind].pass, -1, Position) != -1) return;
    ivec2 size = textureSize(Target, 0);
    ivec2 p = ivec2(e.first % size.x, size.y - 1 - e.first / size.x);
    firsts[kind].pixel = e.first;
    firsts[kind].value = texelFetch(Target, p, 0);
    vec2 centre = (vec2(p) + 0.5) / vec2(size);
    for (int i = 0; i < InputCount; ++i) {
        ivec2 s = textureSize(Inputs[i], 0);
        firsts[kind].inputs[i] = texelFetch(Inputs[i], clamp(ivec2(centre * vec2(s)), ivec2(0), s - 1), 0);
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
    check->found_ = createQuery(GL_ANY_SAMPLES_PASSED);
    check->vertexArray_ = createVertexArray();
    return check;
}

void GlHealthCheck::growBuffer(size_t passes) {
    if (buffer_.get() && passes <= capacity_) return;
    capacity_ = std::max<size_t>(passes, 16);
    buffer_ = createBuffer();
    glNamedBufferStorage(buffer_.get(), static_cast<GLsizeiptr>(kFirstsBytes + capacity_ * healthKindCount * sizeof(PassEntry)),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void GlHealthCheck::beginFrame(int frame, size_t passes) {
    frame_ = frame;
    growBuffer(passes);
    passes_.assign(passes, PassHealth{});
    inputLabels_.assign(passes, {});
    widths_.assign(passes, 0);
    std::vector<unsigned char> initial(kFirstsBytes + passes * healthKindCount * sizeof(PassEntry), 0);
    for (int k = 0; k < healthKindCount; ++k) {
        FirstRecord record{};
        record.pass = -1;
        std::memcpy(initial.data() + k * sizeof(FirstRecord), &record, sizeof record);
    }
    for (size_t i = 0; i < passes * healthKindCount; ++i) {
        PassEntry entry{0, INT_MAX};
        std::memcpy(initial.data() + kFirstsBytes + i * sizeof(PassEntry), &entry, sizeof entry);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glNamedBufferSubData(buffer_.get(), 0, static_cast<GLsizeiptr>(initial.size()), initial.data());
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

    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_.get());
    glBindTextureUnit(kTargetUnit, texture);
    glBindSampler(kTargetUnit, 0);
    // Changed only when the size does: each change makes the driver validate the framebuffer again
    // (and a framebuffer larger than the draw costs llvmpipe its whole area).
    const glm::ivec2 defaultSize{std::max(size.x, healthKindCount), size.y};
    if (defaultSize != emptySize_) {
        glNamedFramebufferParameteri(empty_.get(), GL_FRAMEBUFFER_DEFAULT_WIDTH, defaultSize.x);
        glNamedFramebufferParameteri(empty_.get(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, defaultSize.y);
        emptySize_ = defaultSize;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, empty_.get());
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(vertexArray_.get());
    glViewport(0, 0, size.x, size.y);
    const GLuint r = reduce_.get();
    glUseProgram(r);
    glUniform1i(reducePosition_, static_cast<GLint>(position));
    glUniform1i(reduceChannels_, limits.channels);
    glUniform1i(reduceNegatives_, limits.holdsNegatives ? 1 : 0);
    glUniform4f(reduceLargest_, limits.largest.x, limits.largest.y, limits.largest.z, limits.largest.w);
    glBeginQuery(GL_ANY_SAMPLES_PASSED, found_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    // Orders this count before the pixel draw's reads, and every earlier pixel draw's writes
    // before the next pass's: no second barrier is needed after the pixel draw.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const GLuint f = fetch_.get();
    glUseProgram(f);
    GLint units[kMaxInputs] = {};
    int count = std::min(static_cast<int>(inputs.size()), kMaxInputs);
    for (int i = 0; i < kMaxInputs; ++i) units[i] = i < count ? inputs[static_cast<size_t>(i)].unit : static_cast<GLint>(kTargetUnit);
    for (int i = 0; i < count; ++i) inputLabels_[position].push_back(inputs[static_cast<size_t>(i)].label);
    glUniform1iv(fetchInputs_, kMaxInputs, units);
    glUniform1i(fetchInputCount_, count);
    glUniform1i(fetchPosition_, static_cast<GLint>(position));
    glViewport(0, 0, healthKindCount, 1);
    glBeginConditionalRender(found_.get(), GL_QUERY_NO_WAIT);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndConditionalRender();
    glBindVertexArray(0);
    glBindTextureUnit(kTargetUnit, 0);
}

FrameHealth GlHealthCheck::endFrame() {
    FrameHealth frame;
    const size_t passes = passes_.size();
    std::vector<unsigned char> data(kFirstsBytes + passes * healthKindCount * sizeof(PassEntry));
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffer_.get(), 0, static_cast<GLsizeiptr>(data.size()), data.data());
    std::vector<std::array<PassEntry, healthKindCount>> entries(passes);
    for (size_t p = 0; p < passes; ++p) {
        for (int k = 0; k < healthKindCount; ++k) {
            std::memcpy(&entries[p][static_cast<size_t>(k)],
                        data.data() + kFirstsBytes + (p * healthKindCount + static_cast<size_t>(k)) * sizeof(PassEntry),
                        sizeof(PassEntry));
            passes_[p].counts[static_cast<size_t>(k)] = entries[p][static_cast<size_t>(k)].count;
        }
    }
    for (int k = 0; k < healthKindCount; ++k) {
        FirstRecord record;
        std::memcpy(&record, data.data() + k * sizeof(FirstRecord), sizeof record);
        if (record.pass < 0 || static_cast<size_t>(record.pass) >= passes) continue;
        const PassHealth& p = passes_[static_cast<size_t>(record.pass)];
        HealthFinding finding;
        finding.kind = allHealthKinds[static_cast<size_t>(k)];
        finding.frame = frame_;
        finding.pass = p.pass;
        finding.target = p.target;
        finding.count = p.counts[static_cast<size_t>(k)];
        const int width = std::max(1, widths_[static_cast<size_t>(record.pass)]);
        finding.pixel = glm::ivec2(record.pixel % width, record.pixel / width);
        finding.value = glm::vec4(record.value[0], record.value[1], record.value[2], record.value[3]);
        const auto& labels = inputLabels_[static_cast<size_t>(record.pass)];
        for (size_t i = 0; i < labels.size(); ++i)
            finding.inputs.push_back({labels[i], glm::vec4(record.inputs[i][0], record.inputs[i][1], record.inputs[i][2],
                                                           record.inputs[i][3])});
        frame.findings.push_back(std::move(finding));
    }
    frame.passes = passes_;
    return frame;
}

}  // namespace rmfx
