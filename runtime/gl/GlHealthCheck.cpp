#include "gl/GlHealthCheck.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <epoxy/gl.h>

#include "gl/GlFullScreenTriangle.h"
#include "gl/HealthBuffer.h"
#include "gl/SoftwareRasteriser.h"

namespace rmfx {
namespace {

// The unit the inspected target is bound to: above those a pass's samplers use.
constexpr GLuint kTargetUnit = 31;

// The buffer's words (gl/HealthBuffer.h), at the binding point BINDING.
#define RMFX_HEALTH_BLOCK "layout(std430, binding = BINDING) buffer RmfxHealth { int words[]; };\n"

// Fragment shaders drawn over an attachment-less framebuffer: a compute dispatch costs about a
// millisecond on llvmpipe whatever it does, a draw a fraction of that.

// One fragment per pixel of the target: which kinds its channels hold. The first pixel is the
// smallest index in GL's order (row 0 at the bottom: HealthBuffer.h says why).
const char* const reduceSource = "#version 450 core\n" RMFX_HEALTH_BLOCK R"(
uniform sampler2D Target;
uniform int Position;
uniform int Channels;
uniform bool Negatives;
uniform vec4 Largest;
void record(int kind, int pixel) {
    int entry = (Position * KINDS + kind) * ENTRY_WORDS;
    atomicAdd(words[entry], 1);
    atomicMin(words[entry + 1], pixel);
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
    int pixel = p.y * size.x + p.x;
    if (nan) record(0, pixel);
    if (positiveInf) record(1, pixel);
    if (negativeInf) record(2, pixel);
    if (negative) record(3, pixel);
    if (atLargest) record(4, pixel);
}
)";

// First, a screen: one fragment per 2x2 pixels (the last row and column read again where the size
// is odd), discarded when the channels of all four lie within what the format holds without a
// finding; the others pass an occlusion query, and only where one passed are the count and its
// record drawn (under the query's condition). NaN fails every comparison. Cheap where nothing
// is found, as is usual: a software rasteriser runs every line of a shader for every fragment,
// taken or not, so the atomics above cost it even where no pixel records (and four pixels a
// fragment measured faster on llvmpipe than one or sixteen: docs/performance.md).
constexpr int kScreenBlock = 2;
const char* const screenSource = R"(#version 450 core
uniform sampler2D Target;
uniform vec4 Lowest;   // per channel: the smallest value that is no finding
uniform vec4 Highest;  // the largest
bool clean(ivec2 p, ivec2 last) {
    vec4 v = texelFetch(Target, min(p, last), 0);
    return all(greaterThanEqual(v, Lowest)) && all(lessThanEqual(v, Highest));
}
void main() {
    ivec2 last = textureSize(Target, 0) - 1;
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    if (clean(p, last) && clean(p + ivec2(1, 0), last) && clean(p + ivec2(0, 1), last) && clean(p + ivec2(1, 1), last)) discard;
}
)";

// One fragment per kind (a 5x1 viewport): where a pass holds the kind, the first pixel's value and
// its inputs' texels there, in the first record slot of the pass's own (the frame's first pass is
// chosen on reading).
const char* const fetchSource = "#version 450 core\n" RMFX_HEALTH_BLOCK R"(
uniform sampler2D Target;
uniform sampler2D Inputs[8];
uniform int InputCount;
uniform int Position;
uniform int Records;  // the first word of the records
void storeVec4(int at, vec4 v) { for (int c = 0; c < 4; ++c) words[at + c] = floatBitsToInt(v[c]); }
void main() {
    int kind = int(gl_FragCoord.x);
    int entry = (Position * KINDS + kind) * ENTRY_WORDS;
    int first = words[entry + 1];
    if (words[entry] == 0) return;
    ivec2 size = textureSize(Target, 0);
    ivec2 p = ivec2(first % size.x, first / size.x);
    int record = Records + (Position * KINDS + kind) * SLOTS * RECORD_WORDS;
    words[record] = first;
    storeVec4(record + 4, texelFetch(Target, p, 0));
    vec2 centre = (vec2(p) + 0.5) / vec2(size);
    for (int i = 0; i < InputCount; ++i) {
        ivec2 s = textureSize(Inputs[i], 0);
        storeVec4(record + 8 + 4 * i, texelFetch(Inputs[i], clamp(ivec2(centre * vec2(s)), ivec2(0), s - 1), 0));
    }
    words[entry + 2] = 1;
}
)";

// The shader's text with BINDING and the buffer's layout (KINDS, ENTRY_WORDS, SLOTS,
// RECORD_WORDS) given their values.
std::string withLayout(std::string source, int binding) {
    for (const auto& [name, value] : {std::pair<std::string, int>{"BINDING", binding},
                                      {"KINDS", healthKindCount},
                                      {"ENTRY_WORDS", kHealthEntryWords},
                                      {"SLOTS", kHealthRecordSlots},
                                      {"RECORD_WORDS", kHealthRecordWords}})
        for (size_t at = source.find(name); at != std::string::npos; at = source.find(name, at))
            source.replace(at, name.size(), std::to_string(value));
    return source;
}

Result<ProgramHandle> fullScreenProgram(const std::string& fragmentSource, const char* what) {
    ProgramHandle program = createProgram();
    const char* fragment = fragmentSource.c_str();
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

Result<std::unique_ptr<GlHealthCheck>> GlHealthCheck::create(HealthCheckMethod method) {
    std::unique_ptr<GlHealthCheck> check(new GlHealthCheck);
    check->software_ = currentContextIsSoftwareRasteriser();
    check->method_ = method;
    check->binding_ = healthBufferBinding();
    auto screen = fullScreenProgram(screenSource, "health-screen");
    if (!screen) return Error{screen.error()};
    check->screen_ = std::move(*screen);
    glProgramUniform1i(check->screen_.get(), glGetUniformLocation(check->screen_.get(), "Target"), static_cast<GLint>(kTargetUnit));
    check->screenLowest_ = glGetUniformLocation(check->screen_.get(), "Lowest");
    check->screenHighest_ = glGetUniformLocation(check->screen_.get(), "Highest");
    auto reduce = fullScreenProgram(withLayout(reduceSource, check->binding_), "health-count");
    if (!reduce) return Error{reduce.error()};
    auto fetch = fullScreenProgram(withLayout(fetchSource, check->binding_), "health-pixel");
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
    check->fetchRecords_ = glGetUniformLocation(f, "Records");
    check->empty_ = createFramebuffer();
    glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &check->maxSize_.x);
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &check->maxSize_.y);
    check->vertexArray_ = createVertexArray();
    return check;
}

void GlHealthCheck::growBuffer(FrameInFlight& f, size_t passes) {
    if (f.buffer.get() && passes <= f.capacity) return;
    f.capacity = std::max<size_t>(passes, 16);
    const size_t words = healthRecordsBase(f.capacity) +
                         f.capacity * healthKindCount * kHealthRecordSlots * static_cast<size_t>(kHealthRecordWords);
    f.buffer = createBuffer();
    glNamedBufferStorage(f.buffer.get(), static_cast<GLsizeiptr>(words * sizeof(std::int32_t)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    const GLsizeiptr countBytes = static_cast<GLsizeiptr>(healthRecordsBase(f.capacity) * sizeof(std::int32_t));
    const GLbitfield access = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    f.counts = createBuffer();
    glNamedBufferStorage(f.counts.get(), countBytes, nullptr, access | GL_CLIENT_STORAGE_BIT);
    f.mapped = static_cast<const std::int32_t*>(glMapNamedBufferRange(f.counts.get(), 0, countBytes, access));
}

void GlHealthCheck::beginFrame(int frame, size_t passes) {
    auto free = std::find_if(frames_.begin(), frames_.end(), [](const auto& f) { return !f->inFlight; });
    if (free == frames_.end()) free = frames_.insert(frames_.end(), std::make_unique<FrameInFlight>());
    now_ = free->get();
    FrameInFlight& f = now();
    f.frame = frame;
    growBuffer(f, passes);
    f.passes.assign(passes, PassHealth{});
    f.inputLabels.assign(passes, {});
    f.sizes.assign(passes, glm::ivec2(1));
    pending_.clear();
    std::vector<std::int32_t> entries(healthRecordsBase(passes), 0);  // count, first, records taken, 0
    for (size_t e = 1; e < entries.size(); e += kHealthEntryWords) entries[e] = INT_MAX;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    if (!entries.empty())
        glNamedBufferSubData(f.buffer.get(), 0, static_cast<GLsizeiptr>(entries.size() * sizeof(std::int32_t)), entries.data());
    // For the frame: nothing else in rmfx binds a storage buffer there.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(binding_), f.buffer.get());
}

void GlHealthCheck::bindCommonState() {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(binding_), now().buffer.get());
    glBindFramebuffer(GL_FRAMEBUFFER, empty_.get());
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(vertexArray_.get());
}

void GlHealthCheck::overTarget(const Inspection& i) {
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
}

void GlHealthCheck::drawScreen(const Inspection& i) {
    overTarget(i);
    glViewport(0, 0, (i.size.x + kScreenBlock - 1) / kScreenBlock, (i.size.y + kScreenBlock - 1) / kScreenBlock);
    glUseProgram(screen_.get());
    constexpr float infinity = std::numeric_limits<float>::infinity();
    glm::vec4 lowest(-infinity), highest(infinity);
    for (int c = 0; c < i.limits.channels && c < 4; ++c) {
        // Below the format's largest where it has one (a finding at and beyond it), else finite.
        const float largest = i.limits.largest[c];
        highest[c] = largest > 0.0f ? std::nextafter(largest, 0.0f) : std::numeric_limits<float>::max();
        lowest[c] = i.limits.holdsNegatives ? 0.0f : -highest[c];
    }
    glUniform4fv(screenLowest_, 1, &lowest[0]);
    glUniform4fv(screenHighest_, 1, &highest[0]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GlHealthCheck::drawCount(const Inspection& i) {
    overTarget(i);
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
    GLint units[kHealthMaxInputs] = {};
    const int count = std::min(static_cast<int>(i.inputs.size()), kHealthMaxInputs);
    for (int k = 0; k < kHealthMaxInputs; ++k) {
        units[k] = static_cast<GLint>(kTargetUnit);
        if (k >= count) continue;
        const Input& input = i.inputs[static_cast<size_t>(k)];
        units[k] = k;
        glBindTextureUnit(static_cast<GLuint>(k), input.texture);
        glBindSampler(static_cast<GLuint>(k), 0);
    }
    glUniform1iv(fetchInputs_, kHealthMaxInputs, units);
    glUniform1i(fetchRecords_, static_cast<GLint>(healthRecordsBase(now().capacity)));
    glUniform1i(fetchInputCount_, count);
    glUniform1i(fetchPosition_, static_cast<GLint>(i.position));
    glViewport(0, 0, healthKindCount, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

bool GlHealthCheck::notePass(size_t position, const std::string& pass, const std::string& target, glm::ivec2 size,
                             TargetFormat format, const std::vector<Input>& inputs) {
    if (position >= now().passes.size()) return false;
    PassHealth& health = now().passes[position];
    health.pass = pass;
    health.target = target;
    health.inspected = formatHealthLimits(format).inspected;
    if (!health.inspected || size.x <= 0 || size.y <= 0) return false;
    now().sizes[position] = size;
    now().inputLabels[position].clear();
    for (size_t k = 0; k < inputs.size() && k < static_cast<size_t>(kHealthMaxInputs); ++k)
        now().inputLabels[position].push_back(inputs[k].label);
    return true;
}

bool GlHealthCheck::countsWhileDrawing(bool sharesItsTarget, int inputs) const {
    switch (method_) {
        case HealthCheckMethod::WhileDrawing: return true;
        case HealthCheckMethod::AfterPass: return false;
        case HealthCheckMethod::Automatic: break;
    }
    // A software rasteriser runs the counting code of every fragment, found or not: with many
    // inputs to record that costs it more than a screen of the target after the pass, with few of
    // them less than the screen and the wait before its batch, and always less than a screen of
    // the whole target after each model drawn into it (docs/performance.md).
    return !software_ || sharesItsTarget || inputs <= kSoftwareCountingInputs;
}

void GlHealthCheck::afterPass(size_t position, const std::string& pass, const std::string& target, unsigned texture,
                              glm::ivec2 size, TargetFormat format, const std::vector<Input>& inputs,
                              const std::string& whyNotWhileDrawing, unsigned condition) {
    if (position < now().passes.size()) now().passes[position].whyNotWhileDrawing = whyNotWhileDrawing;
    if (!notePass(position, pass, target, size, format, inputs)) return;
    if (texture == 0 || size.x > maxSize_.x || size.y > maxSize_.y) return;
    Inspection inspection{position, texture, size, formatHealthLimits(format), {}, condition};
    for (size_t k = 0; k < inputs.size() && k < static_cast<size_t>(kHealthMaxInputs); ++k) inspection.inputs.push_back(inputs[k]);
    pending_.push_back(std::move(inspection));
}

void GlHealthCheck::beforeCountingPass(size_t position, const std::string& pass, const std::string& target, glm::ivec2 size,
                                       TargetFormat format, const std::vector<Input>& inputs, const HealthUniforms& uniforms,
                                       bool keepsEarlierPixels) {
    notePass(position, pass, target, size, format, inputs);
    if (position < now().passes.size()) {
        now().passes[position].countedWhileDrawing = true;
        now().passes[position].ownPixelsOnly = keepsEarlierPixels;
    }
    setHealthUniforms(uniforms, position, now().capacity, size, format);
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
    while (screens_.size() < pending_.size()) screens_.push_back(createQuery(GL_ANY_SAMPLES_PASSED));
    // A pass content skip left out (Inspection::condition) draws no screen, so its query fails.
    for (size_t k = 0; k < pending_.size(); ++k) {
        const Inspection& i = pending_[k];
        glBeginQuery(GL_ANY_SAMPLES_PASSED, screens_[k].get());
        if (i.condition) glBeginConditionalRender(i.condition, GL_QUERY_WAIT);
        drawScreen(i);
        if (i.condition) glEndConditionalRender();
        glEndQuery(GL_ANY_SAMPLES_PASSED);
    }
    auto whereScreened = [&](size_t k, auto draw) {
        glBeginConditionalRender(screens_[k].get(), GL_QUERY_WAIT);
        draw(pending_[k]);
        glEndConditionalRender();
    };
    for (size_t k = 0; k < pending_.size(); ++k) whereScreened(k, [&](const Inspection& i) { drawCount(i); });
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    for (size_t k = 0; k < pending_.size(); ++k) whereScreened(k, [&](const Inspection& i) { drawPixel(i); });
    glBindVertexArray(0);
    glBindTextureUnit(kTargetUnit, 0);
    pending_.clear();
}

void GlHealthCheck::endFrame() {
    inspectPending();
    FrameInFlight& f = now();
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the shaders' writes, for the copy and the reads after the fence
    const size_t countWords = healthRecordsBase(f.passes.size());
    if (f.mapped && countWords > 0)
        glCopyNamedBufferSubData(f.buffer.get(), f.counts.get(), 0, 0, static_cast<GLsizeiptr>(countWords * sizeof(std::int32_t)));
    f.fence.insert();
    f.inFlight = true;
    inFlight_.push_back(now_);
    glFlush();  // so that the fence signals without anything else sending it
}

std::vector<FrameHealth> GlHealthCheck::finishedFrames(bool wait) {
    std::vector<FrameHealth> out;
    size_t done = 0;
    while (done < inFlight_.size() && (wait || inFlight_[done]->fence.signalled())) {
        inFlight_[done]->fence.wait();  // the mapped counts are the GPU's only once it has passed
        out.push_back(read(*inFlight_[done]));
        ++done;
    }
    inFlight_.erase(inFlight_.begin(), inFlight_.begin() + static_cast<std::ptrdiff_t>(done));
    return out;
}

FrameHealth GlHealthCheck::read(FrameInFlight& f) {
    f.inFlight = false;
    f.fence.reset();
    FrameHealth frame;
    const size_t passes = f.passes.size();
    std::vector<std::int32_t> entries(healthRecordsBase(passes));
    if (!entries.empty() && f.mapped)
        std::memcpy(entries.data(), f.mapped, entries.size() * sizeof(std::int32_t));
    else if (!entries.empty())
        glGetNamedBufferSubData(f.buffer.get(), 0, static_cast<GLsizeiptr>(entries.size() * sizeof(std::int32_t)), entries.data());
    auto entry = [&](size_t pass, int kind) { return &entries[(pass * healthKindCount + static_cast<size_t>(kind)) * kHealthEntryWords]; };
    for (size_t p = 0; p < passes; ++p)
        for (int k = 0; k < healthKindCount; ++k) f.passes[p].counts[static_cast<size_t>(k)] = entry(p, k)[0];
    for (int k = 0; k < healthKindCount; ++k) {
        size_t first = passes;
        for (size_t p = 0; p < passes && first == passes; ++p)
            if (f.passes[p].counts[static_cast<size_t>(k)] > 0) first = p;
        if (first == passes) continue;
        const std::int32_t firstPixel = entry(first, k)[1];
        const int taken = std::clamp(entry(first, k)[2], 0, kHealthRecordSlots);
        std::vector<std::int32_t> records(static_cast<size_t>(taken * kHealthRecordWords));
        const size_t at = healthRecordsBase(f.capacity) +
                          (first * healthKindCount + static_cast<size_t>(k)) * kHealthRecordSlots * static_cast<size_t>(kHealthRecordWords);
        if (taken > 0)
            glGetNamedBufferSubData(f.buffer.get(), static_cast<GLintptr>(at * sizeof(std::int32_t)),
                                    static_cast<GLsizeiptr>(records.size() * sizeof(std::int32_t)), records.data());
        const PassHealth& p = f.passes[first];
        HealthFinding finding;
        finding.kind = allHealthKinds[static_cast<size_t>(k)];
        finding.frame = f.frame;
        finding.pass = p.pass;
        finding.target = p.target;
        finding.count = p.counts[static_cast<size_t>(k)];
        // Counted from GL's bottom row; reported from the top, as images are shown.
        const glm::ivec2 size(std::max(1, f.sizes[first].x), std::max(1, f.sizes[first].y));
        finding.pixel = glm::ivec2(firstPixel % size.x, size.y - 1 - firstPixel / size.x);
        finding.recorded = false;
        auto vec4At = [&](const std::int32_t* words) {
            glm::vec4 v;
            std::memcpy(&v[0], words, sizeof v);
            return v;
        };
        for (int slot = 0; slot < taken && !finding.recorded; ++slot) {
            const std::int32_t* record = &records[static_cast<size_t>(slot * kHealthRecordWords)];
            if (record[0] != firstPixel) continue;
            finding.recorded = true;
            finding.value = vec4At(record + 4);
            const auto& labels = f.inputLabels[first];
            for (size_t i = 0; i < labels.size(); ++i) finding.inputs.push_back({labels[i], vec4At(record + 8 + 4 * i)});
        }
        frame.findings.push_back(std::move(finding));
    }
    frame.passes = f.passes;
    return frame;
}

}  // namespace rmfx
