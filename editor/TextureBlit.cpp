#include "editor/TextureBlit.h"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>

namespace rmfx::editor {
namespace {

// A full-screen triangle from gl_VertexID; uv covers [0, 1] over the viewport.
const char* vertexSource = R"(#version 450 core
out vec2 uv;
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// The display transform of runtime/ImageWrite: NaN to 0, clamp to [0, 1], then the piecewise
// sRGB curve (IEC 61966-2-1), so that the window's 8-bit pixels round to what a PNG holds.
const char* fragmentSource = R"(#version 450 core
in vec2 uv;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1) uniform sampler3D volume;
uniform bool exact;
uniform bool sliced;   // a slice of `volume` at depth `slice` in [0, 1]
uniform float slice;
uniform ivec2 origin;
uniform float scale;
uniform bool srgb;
uniform bool topRowFirst;  // the texture's row 0 is the picture's top row (a Direct3D texture space)
out vec4 color;

float display(float v) {
    v = isnan(v) ? 0.0 : clamp(v, 0.0, 1.0);
    if (srgb) v = v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055;
    return clamp(v, 0.0, 1.0);
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy) - origin;
    vec2 at = uv;
    if (topRowFirst) {
        texel.y = textureSize(source, 0).y - 1 - texel.y;
        at.y = 1.0 - at.y;
    }
    vec4 t = sliced ? texture(volume, vec3(at, slice))
           : exact  ? texelFetch(source, texel, 0)
                    : texture(source, at);
    vec3 c = t.rgb * scale;
    color = vec4(display(c.r), display(c.g), display(c.b), 1.0);
}
)";

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log;
}

GLuint compile(GLenum stage, const char* source, std::string* error) {
    GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        *error = shaderLog(shader);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

GLuint makeSampler(GLenum minify, GLenum magnify) {
    GLuint sampler = 0;
    glCreateSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minify));
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magnify));
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    return sampler;
}

}  // namespace

Result<std::unique_ptr<TextureBlit>> TextureBlit::create() {
    std::string error;
    GLuint vs = compile(GL_VERTEX_SHADER, vertexSource, &error);
    if (!vs) return Error{"editor display shader (vertex): " + error};
    GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentSource, &error);
    if (!fs) {
        glDeleteShader(vs);
        return Error{"editor display shader (fragment): " + error};
    }
    std::unique_ptr<TextureBlit> blit(new TextureBlit);
    blit->program_ = glCreateProgram();
    glAttachShader(blit->program_, vs);
    glAttachShader(blit->program_, fs);
    glLinkProgram(blit->program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = 0;
    glGetProgramiv(blit->program_, GL_LINK_STATUS, &linked);
    if (!linked) return Error{"editor display shader does not link"};
    blit->exactLocation_ = glGetUniformLocation(blit->program_, "exact");
    blit->originLocation_ = glGetUniformLocation(blit->program_, "origin");
    blit->scaleLocation_ = glGetUniformLocation(blit->program_, "scale");
    blit->srgbLocation_ = glGetUniformLocation(blit->program_, "srgb");
    blit->slicedLocation_ = glGetUniformLocation(blit->program_, "sliced");
    blit->sliceLocation_ = glGetUniformLocation(blit->program_, "slice");
    blit->topRowFirstLocation_ = glGetUniformLocation(blit->program_, "topRowFirst");
    glCreateVertexArrays(1, &blit->vertexArray_);
    blit->nearest_ = makeSampler(GL_NEAREST, GL_NEAREST);
    blit->linear_ = makeSampler(GL_LINEAR, GL_NEAREST);  // magnified texels stay sharp
    return blit;
}

TextureBlit::~TextureBlit() {
    glDeleteProgram(program_);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteSamplers(1, &nearest_);
    glDeleteSamplers(1, &linear_);
}

void TextureBlit::setRowsTopFirst(bool topFirst) { glProgramUniform1i(program_, topRowFirstLocation_, topFirst ? 1 : 0); }

void TextureBlit::drawExact(unsigned texture, glm::ivec2 origin, DisplayTransform transform) {
    draw(texture, nearest_, true, origin, 1.0f, transform);
}

void TextureBlit::drawFiltered(unsigned texture, float exposureStops, DisplayTransform transform) {
    draw(texture, linear_, false, glm::ivec2(0), std::exp2(exposureStops), transform);
}

void TextureBlit::drawSlice(unsigned volume, float depth, DisplayTransform transform) {
    glProgramUniform1i(program_, slicedLocation_, 1);
    glProgramUniform1f(program_, sliceLocation_, std::clamp(depth, 0.0f, 1.0f));
    glBindTextureUnit(1, volume);
    glBindSampler(1, linear_);
    draw(0, linear_, false, glm::ivec2(0), 1.0f, transform);
    glBindSampler(1, 0);
    glBindTextureUnit(1, 0);
    glProgramUniform1i(program_, slicedLocation_, 0);
}

void TextureBlit::draw(unsigned texture, unsigned sampler, bool exact, glm::ivec2 origin, float scale,
                       DisplayTransform transform) {
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(program_);
    glProgramUniform1i(program_, exactLocation_, exact ? 1 : 0);
    glProgramUniform2i(program_, originLocation_, origin.x, origin.y);
    glProgramUniform1f(program_, scaleLocation_, scale);
    glProgramUniform1i(program_, srgbLocation_, transform == DisplayTransform::Srgb ? 1 : 0);
    glBindTextureUnit(0, texture);
    glBindSampler(0, sampler);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(0, 0);
    glBindTextureUnit(0, 0);
    glUseProgram(0);
}

}  // namespace rmfx::editor
