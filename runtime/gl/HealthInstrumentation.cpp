#include "gl/HealthInstrumentation.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include <epoxy/gl.h>

#include "frontend/shader/ShaderPreprocessor.h"
#include "gl/HealthBuffer.h"

namespace rmfx {
namespace {

constexpr const char* kRenamedMain = "rmfx_health_pass_main";
constexpr std::uint32_t kInfinityBits = 0x7F800000u;

// The fragment output at location 0: its name and how many float components it has.
struct ColourOutput {
    std::string name;
    int components = 0;
};

Result<ColourOutput> colourOutput(GLuint program) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_PROGRAM_OUTPUT, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLenum props[3] = {GL_LOCATION, GL_TYPE, GL_ARRAY_SIZE};
        GLint values[3] = {};
        glGetProgramResourceiv(program, GL_PROGRAM_OUTPUT, static_cast<GLuint>(i), 3, props, 3, nullptr, values);
        if (values[0] != 0) continue;
        char name[256] = {};
        glGetProgramResourceName(program, GL_PROGRAM_OUTPUT, static_cast<GLuint>(i), sizeof name, nullptr, name);
        const std::string output = name;
        if (output.rfind("gl_", 0) == 0 || output.find('[') != std::string::npos || values[2] != 1)
            return Error{"its colour output '" + output + "' is a built-in or an array"};
        switch (values[1]) {
            case GL_FLOAT: return ColourOutput{output, 1};
            case GL_FLOAT_VEC2: return ColourOutput{output, 2};
            case GL_FLOAT_VEC3: return ColourOutput{output, 3};
            case GL_FLOAT_VEC4: return ColourOutput{output, 4};
            default: return Error{"its colour output '" + output + "' is not a float vector"};
        }
    }
    return Error{"it has no colour output at location 0"};
}

// Whether `sampler` is a plain sampler2D the fragment shader reads.
bool fragmentSampler2D(GLuint program, const std::string& sampler) {
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, sampler.c_str());
    if (index == GL_INVALID_INDEX) return false;
    const GLenum props[3] = {GL_TYPE, GL_ARRAY_SIZE, GL_REFERENCED_BY_FRAGMENT_SHADER};
    GLint values[3] = {};
    glGetProgramResourceiv(program, GL_UNIFORM, index, 3, props, 3, nullptr, values);
    return values[0] == GL_SAMPLER_2D && values[1] == 1 && values[2] != 0;
}

bool mentions(const std::string& code, const char* word) { return code.find(word) != std::string::npos; }

std::string widened(const ColourOutput& output) {
    switch (output.components) {
        case 1: return "vec4(" + output.name + ", 0.0, 0.0, 0.0)";
        case 2: return "vec4(" + output.name + ", 0.0, 0.0)";
        case 3: return "vec4(" + output.name + ", 0.0)";
        default: return output.name;
    }
}

// What the added main() does after the pass's own: the health buffer's words as HealthBuffer.h
// lays them out, and the format's limits as uniforms (setHealthUniforms).
std::string appendix(const ColourOutput& output, const std::vector<std::string>& inputs, int binding, bool earlyTests) {
    std::string s = "\n#undef main\n";
    s += "layout(std430, binding = " + std::to_string(binding) + ") buffer rmfx_health_Buffer { int rmfx_health_words[]; };\n";
    // The same words four at a time: a record's value and inputs each in one store (a software
    // rasteriser runs every store of every fragment, taken or not; one of four words costs it a
    // quarter of four of one).
    s += "layout(std430, binding = " + std::to_string(binding) + ") buffer rmfx_health_Quads { ivec4 rmfx_health_quads[]; };\n";
    if (earlyTests) s += "layout(early_fragment_tests) in;\n";
    s += R"(uniform int rmfx_health_Slot;       // the pass's first entry: position times the kinds
uniform int rmfx_health_Records;    // the first word of the records
uniform ivec2 rmfx_health_Size;     // of the target
uniform int rmfx_health_Channels;   // the target's; 0: it is not inspected
uniform uint rmfx_health_NegativeAbove; // the magnitude's bits above which a negative value is one
// A channel whose bits are below is none of the kinds (screenBelow); in a channel inspected, the
// bits of the smallest magnitude stored at the format's largest or beyond (+Inf's where it has none).
uniform uvec4 rmfx_health_Below;
// An input's texel at the fragment's centre, the texel its sampler would fetch there.
vec4 rmfx_health_input(int rmfx_health_which) {
    vec2 rmfx_health_centre = (floor(gl_FragCoord.xy) + 0.5) / vec2(rmfx_health_Size);
    ivec2 rmfx_health_size;
)";
    for (size_t i = 0; i < inputs.size(); ++i)
        s += "    if (rmfx_health_which == " + std::to_string(i) + ") {\n        rmfx_health_size = textureSize(" + inputs[i] +
             ", 0);\n        return texelFetch(" + inputs[i] +
             ", clamp(ivec2(rmfx_health_centre * vec2(rmfx_health_size)), ivec2(0), rmfx_health_size - 1), 0);\n    }\n";
    std::string lowestKind = std::to_string(healthKindCount - 1);
    for (int k = healthKindCount - 2; k >= 0; --k)
        lowestKind = "rmfx_health_lowest == " + std::to_string(1 << k) + " ? " + std::to_string(k) + " : " + lowestKind;
    s += R"(    return vec4(0.0);
}
// Works out, one channel a step, the kinds `bits` (the pixel's value as written) holds, on the bits:
// NaN (1), +Inf (2), -Inf (4), and of finite values negative (8) and at the format's largest (16);
// then counts each kind at `pixel`. A fragment that lowers a kind's first pixel takes a record slot
// for it, and writes its pixel, value and inputs there, a quad a step. Each memory operation and
// the kinds' code are written once, and each step goes through them: a software rasteriser runs
// everything written in the function once for every group of fragments, found or not
// (docs/performance.md), so the kinds of one channel cost it a quarter of the four's.
void rmfx_health_count(uvec4 rmfx_health_bits, int rmfx_health_channels, int rmfx_health_pixel) {
    int rmfx_health_channel = 0;  // the next channel to work out
    int rmfx_health_left = 0;     // kinds found and not counted yet
    int rmfx_health_kind = 0;
    int rmfx_health_step = 0;  // 0: count the next kind; 1: take a record slot; 2 + q: store the record's quad q
    int rmfx_health_record = 0;
    while (rmfx_health_channel < rmfx_health_channels || rmfx_health_left != 0 || rmfx_health_step != 0) {
        if (rmfx_health_channel < rmfx_health_channels) {
            uint rmfx_health_of = rmfx_health_bits[rmfx_health_channel];
            uint rmfx_health_magnitude = rmfx_health_of & 0x7FFFFFFFu;
            uint rmfx_health_sign = rmfx_health_of >> 31u;
            rmfx_health_left |= rmfx_health_magnitude > 0x7F800000u ? 1
                : rmfx_health_magnitude == 0x7F800000u ? 2 << rmfx_health_sign
                : (rmfx_health_sign != 0u && rmfx_health_magnitude > rmfx_health_NegativeAbove ? 8 : 0)
                  | (rmfx_health_magnitude >= rmfx_health_Below[rmfx_health_channel] ? 16 : 0);
            ++rmfx_health_channel;
            continue;
        }
        if (rmfx_health_step == 0) {  // the lowest kind left (findLSB is GLSL 4.00)
            int rmfx_health_lowest = rmfx_health_left & -rmfx_health_left;
            rmfx_health_kind = )" + lowestKind + R"(;
            rmfx_health_left ^= rmfx_health_lowest;
        }
        int rmfx_health_entry = (rmfx_health_Slot + rmfx_health_kind) * )" + std::to_string(kHealthEntryWords) + R"(;
        int rmfx_health_added = 0;
        if (rmfx_health_step < 2) rmfx_health_added = atomicAdd(rmfx_health_words[rmfx_health_entry + 2 * rmfx_health_step], 1);
        if (rmfx_health_step == 0) {
            rmfx_health_step = atomicMin(rmfx_health_words[rmfx_health_entry + 1], rmfx_health_pixel) > rmfx_health_pixel ? 1 : 0;
        } else if (rmfx_health_step == 1) {
            rmfx_health_record = rmfx_health_Records + ((rmfx_health_Slot + rmfx_health_kind) * )" +
         std::to_string(kHealthRecordSlots) + " + rmfx_health_added) * " + std::to_string(kHealthRecordWords) + R"(;
            rmfx_health_step = rmfx_health_added < )" + std::to_string(kHealthRecordSlots) + R"( ? 2 : 0;
        } else {
            int rmfx_health_quad = rmfx_health_step - 2;
            ivec4 rmfx_health_stored = rmfx_health_quad == 0 ? ivec4(rmfx_health_pixel, 0, 0, 0)
                : rmfx_health_quad == 1 ? ivec4(rmfx_health_bits) : floatBitsToInt(rmfx_health_input(rmfx_health_quad - 2));
            rmfx_health_quads[(rmfx_health_record >> 2) + rmfx_health_quad] = rmfx_health_stored;
            rmfx_health_step = rmfx_health_quad < )" + std::to_string(1 + inputs.size()) + R"( ? rmfx_health_step + 1 : 0;
        }
    }
}
)";
    s += "void main() {\n    " + std::string(kRenamedMain) + "();\n";
    // One comparison per channel screens a value (screenBelow): on a GPU only a value it lets
    // through goes on to the kinds. Working out the kinds of every value cost an NVIDIA H100 16 % of
    // hdr_lighting's frame, against 5 % for a cheaper test in its place (docs/performance.md).
    s += "    uvec4 rmfx_health_bits = floatBitsToUint(" + widened(output) + ");\n";
    s += R"(    if (!any(greaterThanEqual(rmfx_health_bits, rmfx_health_Below))) return;
    rmfx_health_count(rmfx_health_bits, min(rmfx_health_Channels, )" + std::to_string(output.components) +
         R"(), int(gl_FragCoord.y) * rmfx_health_Size.x + int(gl_FragCoord.x));
}
)";
    return s;
}

// The smallest written magnitude a format stores at its largest finite value or beyond, rounding
// to nearest (ties to even, which goes down from each midpoint here): half 65488, unsigned
// 11-bit 64768, 10-bit 64000, each just above.
glm::vec4 largestWritten(TargetFormat format) {
    const FormatHealthLimits limits = formatHealthLimits(format);
    glm::vec4 at(0.0f);
    for (int c = 0; c < 4; ++c) {
        const float largest = limits.largest[c];
        if (largest <= 0.0f) continue;
        // The step below the largest finite value: 32 for half, 512 for unsigned 11-bit and 1024 for
        // 10-bit floats (6 and 5 mantissa bits at 2^15).
        const float step = largest == 64512.0f ? 1024.0f : largest == 65024.0f ? 512.0f : 32.0f;
        at[c] = std::nextafter(largest - step / 2.0f, largest);
    }
    return at;
}

// Per channel, the smallest bit pattern that may be one of the kinds: as unsigned integers the bits
// of non-negative floats are in their order, and every negative value, -0 included, and every NaN
// and infinity lie at or above 0x7F800000. So a channel's bits below this are none of the kinds;
// at or above, the kinds are worked out exactly, and the same bits mark the format's largest. A
// channel not inspected gets the largest pattern: only that one (a NaN) goes on to the exact
// test, which leaves such a channel out.
glm::uvec4 screenBelow(const FormatHealthLimits& limits, glm::vec4 largest) {
    glm::uvec4 below(0xFFFFFFFFu);
    if (!limits.inspected) return below;
    for (int c = 0; c < limits.channels && c < 4; ++c)
        below[c] = largest[c] > 0.0f ? std::bit_cast<std::uint32_t>(largest[c]) : kInfinityBits;
    return below;
}

}  // namespace

Result<std::string> instrumentForHealth(const Pass& pass, const std::string& fragmentCode, unsigned program,
                                        const std::vector<std::string>& inputSamplers, int bufferBinding) {
    if (pass.blend.enabled) return Error{"it blends onto its target"};
    if (pass.alphaTest.enabled) return Error{"it has an alpha test"};
    const std::optional<OpeningVersion> version = openingVersion(fragmentCode);
    if (!version || version->number < 330 || version->es) return Error{"its fragment shader is older than GLSL 3.30 or GLSL ES"};
    const bool earlyTests = pass.depth.test;
    if (earlyTests && (mentions(fragmentCode, "discard") || mentions(fragmentCode, "gl_FragDepth")))
        return Error{"it tests depth and its fragment shader discards or writes gl_FragDepth"};
    Result<ColourOutput> output = colourOutput(program);
    if (!output) return Error{output.error()};
    std::vector<std::string> inputs;
    for (const std::string& sampler : inputSamplers) {
        if (!fragmentSampler2D(program, sampler))
            return Error{"its input '" + sampler + "' is not a sampler2D of its fragment shader"};
        if (inputs.size() < static_cast<size_t>(kHealthMaxInputs)) inputs.push_back(sampler);
    }
    std::string head;
    if (version->number < 430) head += "#extension GL_ARB_shader_storage_buffer_object : require\n";
    if (earlyTests && version->number < 420) head += "#extension GL_ARB_shader_image_load_store : require\n";
    head += "#define main " + std::string(kRenamedMain) + "\n";
    std::string code = fragmentCode;
    code.insert(version->end, head);
    if (!code.empty() && code.back() != '\n') code += '\n';
    return code + appendix(*output, inputs, bufferBinding, earlyTests);
}

HealthUniforms findHealthUniforms(unsigned program) {
    HealthUniforms u;
    u.slot = glGetUniformLocation(program, "rmfx_health_Slot");
    u.records = glGetUniformLocation(program, "rmfx_health_Records");
    u.size = glGetUniformLocation(program, "rmfx_health_Size");
    u.channels = glGetUniformLocation(program, "rmfx_health_Channels");
    u.negativeAbove = glGetUniformLocation(program, "rmfx_health_NegativeAbove");
    u.below = glGetUniformLocation(program, "rmfx_health_Below");
    // The compiler drops what the added main() does not use: a target's channels always are.
    u.found = u.slot >= 0 && u.size >= 0 && u.channels >= 0 && u.below >= 0;
    return u;
}

void setHealthUniforms(const HealthUniforms& u, size_t position, size_t capacity, glm::ivec2 size, TargetFormat format) {
    const HealthUniforms::Values values{position, capacity, size, format};
    if (u.set == values) return;
    u.set = values;
    const FormatHealthLimits limits = formatHealthLimits(format);
    const bool half = format == TargetFormat::RGBA16F || format == TargetFormat::RG16F || format == TargetFormat::R16F;
    glUniform1i(u.slot, static_cast<GLint>(position * healthKindCount));
    glUniform1i(u.records, static_cast<GLint>(healthRecordsBase(capacity)));
    glUniform2i(u.size, size.x, size.y);
    glUniform1i(u.channels, limits.inspected ? limits.channels : 0);
    // A negative magnitude above this is stored as a negative value: half floats round one up to
    // 2^-25 (half their smallest subnormal) to zero. Where the format holds none, no finite one is.
    const float smallest = half ? std::ldexp(1.0f, -25) : 0.0f;
    glUniform1ui(u.negativeAbove, limits.holdsNegatives ? std::bit_cast<std::uint32_t>(smallest) : kInfinityBits);
    const glm::uvec4 below = screenBelow(limits, largestWritten(format));
    glUniform4ui(u.below, below.x, below.y, below.z, below.w);
}

}  // namespace rmfx
